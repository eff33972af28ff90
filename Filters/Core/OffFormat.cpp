// SPDX-License-Identifier: BSD-3-Clause
#include "OffFormat.h"

#include "TextFile.h"

#include <cmath>
#include <sstream>

namespace polycubehex
{
namespace
{
/// OFF's faces may carry colours after their indices, so faces are read line by line; the
/// rest of the file is free layout. Lines are split here with comments removed.
std::vector<std::vector<std::string>> TokenizeLines(const std::string& text)
{
  std::vector<std::vector<std::string>> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    const std::size_t comment = line.find('#');
    if (comment != std::string::npos)
    {
      line.erase(comment);
    }
    std::istringstream words(line);
    std::vector<std::string> tokens;
    std::string token;
    while (words >> token)
    {
      tokens.push_back(token);
    }
    if (!tokens.empty())
    {
      lines.push_back(std::move(tokens));
    }
  }
  return lines;
}

bool ToInteger(const std::string& token, long long& value)
{
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return !token.empty() && end == token.c_str() + token.size();
}

bool ToDouble(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}
} // namespace

Status ReadOff(const std::string& text, OffMesh& mesh)
{
  mesh = OffMesh();
  const std::vector<std::vector<std::string>> lines = TokenizeLines(text);
  if (lines.empty())
  {
    return Status::Failure("OFF: the file is empty");
  }
  // Flatten everything before the faces: header, counts and vertices may wrap freely.
  std::size_t line = 0;
  std::size_t word = 0;
  auto nextToken = [&](std::string& token) {
    while (line < lines.size() && word >= lines[line].size())
    {
      ++line;
      word = 0;
    }
    if (line >= lines.size())
    {
      return false;
    }
    token = lines[line][word++];
    return true;
  };

  std::string token;
  nextToken(token);
  int extraVertexValues = 0;
  if (token.size() >= 3 && token.compare(token.size() - 3, 3, "OFF") == 0)
  {
    const std::string prefix = token.substr(0, token.size() - 3);
    if (prefix.find('4') != std::string::npos || prefix.find('n') != std::string::npos)
    {
      return Status::Failure("OFF: the header '" + token + "' (not 3-dimensional) is not supported");
    }
    extraVertexValues = (prefix.find('N') != std::string::npos ? 3 : 0) +
      (prefix.find('C') != std::string::npos ? 4 : 0) +
      (prefix.find("ST") != std::string::npos ? 2 : 0);
    if (!nextToken(token))
    {
      return Status::Failure("OFF: the file ends before the vertex and face counts");
    }
  }
  long long counts[3] = { 0, 0, 0 };
  for (int k = 0; k < 3; ++k)
  {
    if (k > 0 && !nextToken(token))
    {
      return Status::Failure("OFF: the file ends inside the vertex, face and edge counts");
    }
    if (!ToInteger(token, counts[k]) || counts[k] < 0)
    {
      return Status::Failure("OFF: expected the vertex, face and edge counts, found '" + token + "'");
    }
  }
  const long long vertexCount = counts[0];
  const long long faceCount = counts[1];
  if (vertexCount > static_cast<long long>(text.size()) / 6 ||
    faceCount > static_cast<long long>(text.size()) / 4)
  {
    return Status::Failure("OFF: the counts (" + std::to_string(vertexCount) + " vertices, " +
      std::to_string(faceCount) + " faces) are more than the file can hold (truncated file?)");
  }
  mesh.Vertices.resize(vertexCount, 3);
  for (long long v = 0; v < vertexCount; ++v)
  {
    for (int k = 0; k < 3 + extraVertexValues; ++k)
    {
      const std::string entity = "vertex " + std::to_string(v) + " of " + std::to_string(vertexCount);
      if (!nextToken(token))
      {
        return Status::Failure("OFF: the file ends inside " + entity);
      }
      double value = 0;
      if (!ToDouble(token, value))
      {
        return Status::Failure("OFF: " + entity + " has '" + token + "' where a number is expected");
      }
      if (k < 3)
      {
        if (!std::isfinite(value))
        {
          return Status::Failure("OFF: " + entity + " has a non-finite coordinate '" + token + "'");
        }
        mesh.Vertices(v, k) = value;
      }
    }
  }
  // Faces: one per line from here on.
  if (word > 0)
  {
    if (word < lines[line].size())
    {
      return Status::Failure("OFF: unexpected '" + lines[line][word] + "' after the last vertex");
    }
    ++line;
  }
  for (long long f = 0; f < faceCount; ++f, ++line)
  {
    const std::string entity = "face " + std::to_string(f) + " of " + std::to_string(faceCount);
    if (line >= lines.size())
    {
      return Status::Failure("OFF: the file ends before " + entity);
    }
    const std::vector<std::string>& tokens = lines[line];
    long long size = 0;
    if (!ToInteger(tokens[0], size) || size < 3)
    {
      return Status::Failure("OFF: " + entity + " starts with '" + tokens[0] +
        "', expected its number of vertices (3 or more)");
    }
    // Compared as size > tokens - 1: size + 1 overflows for a count near 2^63.
    if (size > static_cast<long long>(tokens.size()) - 1)
    {
      return Status::Failure("OFF: " + entity + " declares " + std::to_string(size) +
        " vertices but its line has " + std::to_string(tokens.size() - 1) + " values");
    }
    for (long long k = 1; k <= size; ++k)
    {
      long long index = 0;
      if (!ToInteger(tokens[k], index))
      {
        return Status::Failure("OFF: " + entity + " has '" + tokens[k] + "' where a vertex index is expected");
      }
      if (index < 0 || index >= vertexCount)
      {
        return Status::Failure("OFF: " + entity + " references vertex " + tokens[k] +
          ", but the vertices are numbered 0 to " + std::to_string(vertexCount - 1));
      }
      mesh.FaceIndices.push_back(static_cast<int>(index));
    }
    mesh.FaceOffsets.push_back(static_cast<int>(mesh.FaceIndices.size()));
  }
  return Status::Success();
}

Status ReadOffFile(const std::string& path, OffMesh& mesh)
{
  std::string text;
  Status status = ReadTextFile(path, text);
  if (!status)
  {
    return status;
  }
  return ReadOff(text, mesh);
}

} // namespace polycubehex
