// SPDX-License-Identifier: BSD-3-Clause
#include "MeditFormat.h"

#include "TextFile.h"
#include "TokenReader.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace polycubehex
{
namespace
{
std::string Describe(const TokenReader& reader)
{
  return " (line " + std::to_string(reader.Line()) + ")";
}

/// Reads the entity count that follows a keyword, refusing counts the text cannot hold.
Status ReadCount(TokenReader& reader, const std::string& keyword, int valuesPerEntity,
  long long& count)
{
  std::string token;
  if (!reader.Next(token))
  {
    return Status::Failure(keyword + ": the file ends before the number of entries");
  }
  if (!TokenReader::ParseInteger(token, count) || count < 0)
  {
    return Status::Failure(
      keyword + ": expected a number of entries, found '" + token + "'" + Describe(reader));
  }
  // Every value takes at least one character and one separator.
  const long long room = static_cast<long long>(reader.RemainingBytes() / 2 + 1);
  if (count > room / valuesPerEntity)
  {
    return Status::Failure(keyword + ": declares " + std::to_string(count) +
      " entries, more than the rest of the file can hold (truncated file or wrong count)" +
      Describe(reader));
  }
  return Status::Success();
}

Status ReadVertices(TokenReader& reader, MeditMesh& mesh)
{
  long long count = 0;
  Status status = ReadCount(reader, "Vertices", 4, count);
  if (!status)
  {
    return status;
  }
  const Eigen::Index first = mesh.Vertices.rows();
  mesh.Vertices.conservativeResize(first + count, 3);
  std::string token;
  for (long long v = 0; v < count; ++v)
  {
    for (int k = 0; k < 4; ++k) // x y z reference
    {
      const std::string entity = "vertex " + std::to_string(v + 1) + " of " + std::to_string(count);
      if (!reader.Next(token))
      {
        return Status::Failure("Vertices: the file ends inside " + entity);
      }
      if (k == 3)
      {
        long long reference = 0;
        if (!TokenReader::ParseInteger(token, reference))
        {
          return Status::Failure("Vertices: " + entity + " has a reference '" + token +
            "' that is not an integer (wrong count?)" + Describe(reader));
        }
        continue;
      }
      double value = 0;
      if (!TokenReader::ParseDouble(token, value))
      {
        return Status::Failure("Vertices: " + entity + " has a coordinate '" + token +
          "' that is not a number (wrong count?)" + Describe(reader));
      }
      if (!std::isfinite(value))
      {
        return Status::Failure(
          "Vertices: " + entity + " has a non-finite coordinate '" + token + "'" + Describe(reader));
      }
      mesh.Vertices(first + v, k) = value;
    }
  }
  return Status::Success();
}

/// Reads `count` elements of `nodes` vertex indices plus a reference, 1-based in the file.
template <typename Matrix>
Status ReadElements(TokenReader& reader, const std::string& keyword, const std::string& entityName,
  Matrix& cells)
{
  const int nodes = static_cast<int>(Matrix::ColsAtCompileTime);
  long long count = 0;
  Status status = ReadCount(reader, keyword, nodes + 1, count);
  if (!status)
  {
    return status;
  }
  const Eigen::Index first = cells.rows();
  cells.conservativeResize(first + count, nodes);
  std::string token;
  for (long long e = 0; e < count; ++e)
  {
    for (int k = 0; k <= nodes; ++k)
    {
      const std::string entity = entityName + " " + std::to_string(e + 1) + " of " + std::to_string(count);
      if (!reader.Next(token))
      {
        return Status::Failure(keyword + ": the file ends inside " + entity);
      }
      long long value = 0;
      if (!TokenReader::ParseInteger(token, value))
      {
        return Status::Failure(keyword + ": " + entity + " has '" + token +
          "' where an integer is expected (wrong count?)" + Describe(reader));
      }
      if (k == nodes)
      {
        continue; // the reference number, ignored
      }
      if (value < 1 || value > (1LL << 31) - 1)
      {
        return Status::Failure(keyword + ": " + entity + " has vertex index " + token +
          ", but indices are 1-based and positive" + Describe(reader));
      }
      cells(first + e, k) = static_cast<int>(value - 1);
    }
  }
  return Status::Success();
}

/// Skips the numbers that follow an unknown keyword, up to the next keyword.
void SkipUnknownBlock(TokenReader& reader)
{
  std::string token;
  while (reader.Peek(token) && !TokenReader::LooksLikeKeyword(token))
  {
    reader.Next(token);
  }
}

template <typename Matrix>
Status CheckIndices(const Matrix& cells, const std::string& keyword, const std::string& entityName,
  Eigen::Index vertexCount)
{
  for (Eigen::Index e = 0; e < cells.rows(); ++e)
  {
    for (Eigen::Index k = 0; k < cells.cols(); ++k)
    {
      if (cells(e, k) >= vertexCount)
      {
        return Status::Failure(keyword + ": " + entityName + " " + std::to_string(e + 1) +
          " references vertex " + std::to_string(cells(e, k) + 1) + ", but there are only " +
          std::to_string(vertexCount) + " vertices");
      }
    }
  }
  return Status::Success();
}

template <typename Matrix>
void WriteElements(std::ostream& out, const char* keyword, const Matrix& cells)
{
  if (cells.rows() == 0)
  {
    return;
  }
  out << "\n" << keyword << "\n" << cells.rows() << "\n";
  for (Eigen::Index e = 0; e < cells.rows(); ++e)
  {
    for (Eigen::Index k = 0; k < cells.cols(); ++k)
    {
      out << cells(e, k) + 1 << ' ';
    }
    out << "0\n";
  }
}
} // namespace

Status ReadMedit(const std::string& text, MeditMesh& mesh, std::vector<std::string>* warnings)
{
  mesh = MeditMesh();
  TokenReader reader(text);
  std::string keyword;
  if (!reader.Peek(keyword))
  {
    return Status::Failure("the file is empty");
  }
  bool sawVersion = false;
  while (reader.Next(keyword))
  {
    Status status = Status::Success();
    if (keyword == "MeshVersionFormatted")
    {
      std::string version;
      long long number = 0;
      if (!reader.Next(version) || !TokenReader::ParseInteger(version, number))
      {
        return Status::Failure("MeshVersionFormatted: expected a version number");
      }
      sawVersion = true;
    }
    else if (keyword == "Dimension")
    {
      std::string dimension;
      long long number = 0;
      if (!reader.Next(dimension) || !TokenReader::ParseInteger(dimension, number))
      {
        return Status::Failure("Dimension: expected a number");
      }
      if (number != 3)
      {
        return Status::Failure(
          "Dimension: " + dimension + " is not supported; only 3-dimensional meshes are");
      }
    }
    else if (keyword == "Vertices")
    {
      status = ReadVertices(reader, mesh);
    }
    else if (keyword == "Edges")
    {
      status = ReadElements(reader, "Edges", "edge", mesh.EdgeCells);
    }
    else if (keyword == "Triangles")
    {
      status = ReadElements(reader, "Triangles", "triangle", mesh.TriangleCells);
    }
    else if (keyword == "Quadrilaterals")
    {
      status = ReadElements(reader, "Quadrilaterals", "quadrilateral", mesh.QuadCells);
    }
    else if (keyword == "Tetrahedra")
    {
      status = ReadElements(reader, "Tetrahedra", "tetrahedron", mesh.TetCells);
    }
    else if (keyword == "Hexahedra")
    {
      status = ReadElements(reader, "Hexahedra", "hexahedron", mesh.HexCells);
    }
    else if (keyword == "End")
    {
      break;
    }
    else if (TokenReader::LooksLikeKeyword(keyword))
    {
      if (warnings)
      {
        warnings->push_back("skipped the unsupported keyword '" + keyword + "'" + Describe(reader));
      }
      SkipUnknownBlock(reader);
    }
    else
    {
      return Status::Failure("expected a keyword, found '" + keyword + "'" + Describe(reader) +
        (sawVersion ? " (a count is probably smaller than its entries)" : " (not a MEDIT file?)"));
    }
    if (!status)
    {
      return status;
    }
  }
  if (!sawVersion)
  {
    return Status::Failure("MeshVersionFormatted: missing; this is not a MEDIT .mesh file");
  }
  const Eigen::Index vertexCount = mesh.Vertices.rows();
  for (const Status& status : { CheckIndices(mesh.EdgeCells, "Edges", "edge", vertexCount),
         CheckIndices(mesh.TriangleCells, "Triangles", "triangle", vertexCount),
         CheckIndices(mesh.QuadCells, "Quadrilaterals", "quadrilateral", vertexCount),
         CheckIndices(mesh.TetCells, "Tetrahedra", "tetrahedron", vertexCount),
         CheckIndices(mesh.HexCells, "Hexahedra", "hexahedron", vertexCount) })
  {
    if (!status)
    {
      return status;
    }
  }
  return Status::Success();
}

Status ReadMeditFile(const std::string& path, MeditMesh& mesh, std::vector<std::string>* warnings)
{
  std::string text;
  Status status = ReadTextFile(path, text);
  if (!status)
  {
    return status;
  }
  return ReadMedit(text, mesh, warnings);
}

Status WriteMedit(std::ostream& out, const MeditMesh& mesh)
{
  out << "MeshVersionFormatted 2\nDimension 3\n\nVertices\n" << mesh.Vertices.rows() << "\n";
  out << std::setprecision(17);
  for (Eigen::Index v = 0; v < mesh.Vertices.rows(); ++v)
  {
    out << mesh.Vertices(v, 0) << ' ' << mesh.Vertices(v, 1) << ' ' << mesh.Vertices(v, 2)
        << " 0\n";
  }
  WriteElements(out, "Edges", mesh.EdgeCells);
  WriteElements(out, "Triangles", mesh.TriangleCells);
  WriteElements(out, "Quadrilaterals", mesh.QuadCells);
  WriteElements(out, "Tetrahedra", mesh.TetCells);
  WriteElements(out, "Hexahedra", mesh.HexCells);
  out << "\nEnd\n";
  return out ? Status::Success() : Status::Failure("writing the MEDIT text failed");
}

Status WriteMeditFile(const std::string& path, const MeditMesh& mesh)
{
  std::ofstream out(path);
  if (!out)
  {
    return Status::Failure("cannot open '" + path + "' for writing");
  }
  return WriteMedit(out, mesh);
}

} // namespace polycubehex
