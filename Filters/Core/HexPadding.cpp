// SPDX-License-Identifier: BSD-3-Clause
#include "HexPadding.h"

#include "HexScaledJacobian.h"

#include <algorithm>
#include <array>

namespace polycubehex
{
namespace
{
/// vtkHexahedron's faces, each ordered so that its normal points out of a positive hex.
constexpr int Faces[6][4] = { { 0, 4, 7, 3 },
  { 1, 2, 6, 5 },
  { 0, 1, 5, 4 },
  { 3, 7, 6, 2 },
  { 0, 3, 2, 1 },
  { 4, 5, 6, 7 } };
} // namespace

Quads ComputeHexBoundaryQuads(const HexMesh& mesh)
{
  struct Use
  {
    std::array<int, 4> Key;
    int Hex;
    int Face;
  };
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  std::vector<Use> uses;
  uses.reserve(6 * static_cast<size_t>(hexCount));
  for (int h = 0; h < hexCount; ++h)
  {
    for (int f = 0; f < 6; ++f)
    {
      Use use{ {}, h, f };
      for (int k = 0; k < 4; ++k)
      {
        use.Key[k] = mesh.Cells(h, Faces[f][k]);
      }
      std::sort(use.Key.begin(), use.Key.end());
      uses.push_back(use);
    }
  }
  std::vector<Use> sorted = uses;
  std::sort(sorted.begin(),
    sorted.end(),
    [](const Use& a, const Use& b) {
      return a.Key != b.Key ? a.Key < b.Key : (a.Hex != b.Hex ? a.Hex < b.Hex : a.Face < b.Face);
    });
  std::vector<char> boundary(uses.size(), 0);
  for (size_t i = 0; i < sorted.size();)
  {
    size_t j = i + 1;
    while (j < sorted.size() && sorted[j].Key == sorted[i].Key)
    {
      ++j;
    }
    if (j - i == 1)
    {
      boundary[6 * static_cast<size_t>(sorted[i].Hex) + sorted[i].Face] = 1;
    }
    i = j;
  }
  Quads quads(std::count(boundary.begin(), boundary.end(), 1), 4);
  int q = 0;
  for (size_t i = 0; i < uses.size(); ++i)
  {
    if (boundary[i])
    {
      for (int k = 0; k < 4; ++k)
      {
        quads(q, k) = mesh.Cells(uses[i].Hex, Faces[uses[i].Face][k]);
      }
      ++q;
    }
  }
  return quads;
}

Points ComputePaddingOffsets(const HexMesh& mesh,
  const Points& directions,
  double thickness,
  double minQuality)
{
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  const Quads quads = ComputeHexBoundaryQuads(mesh);
  std::vector<bool> boundary(vertexCount, false);
  for (int q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      boundary[quads(q, k)] = true;
    }
  }
  Points offsets = Points::Zero(vertexCount, 3);
  for (int v = 0; v < vertexCount; ++v)
  {
    if (boundary[v])
    {
      offsets.row(v) = thickness * directions.row(v);
    }
  }
  // Every hex after padding, as 8 (vertex, uses the copy) pairs: the kept hexes use the copies
  // of their boundary vertices, a padding hex its quad's vertices and their copies.
  std::vector<std::array<std::pair<int, bool>, 8>> hexes;
  hexes.reserve(hexCount + quads.rows());
  for (int h = 0; h < hexCount; ++h)
  {
    std::array<std::pair<int, bool>, 8> hex;
    bool touches = false;
    for (int k = 0; k < 8; ++k)
    {
      hex[k] = { mesh.Cells(h, k), boundary[mesh.Cells(h, k)] };
      touches = touches || hex[k].second;
    }
    if (touches)
    {
      hexes.push_back(hex);
    }
  }
  for (int q = 0; q < quads.rows(); ++q)
  {
    const int order[4] = { 0, 3, 2, 1 };
    std::array<std::pair<int, bool>, 8> hex;
    for (int k = 0; k < 4; ++k)
    {
      hex[k] = { quads(q, order[k]), false };
      hex[4 + k] = { quads(q, order[k]), true };
    }
    hexes.push_back(hex);
  }
  for (int round = 0; round < 6; ++round)
  {
    std::vector<bool> shrink(vertexCount, false);
    bool any = false;
    for (const auto& hex : hexes)
    {
      Eigen::Matrix<double, 8, 3> corners;
      for (int k = 0; k < 8; ++k)
      {
        corners.row(k) = mesh.Vertices.row(hex[k].first);
        if (hex[k].second)
        {
          corners.row(k) += offsets.row(hex[k].first);
        }
      }
      if (HexScaledJacobian(corners) < minQuality)
      {
        for (int k = 0; k < 8; ++k)
        {
          if (hex[k].second)
          {
            shrink[hex[k].first] = true;
            any = true;
          }
        }
      }
    }
    if (!any)
    {
      break;
    }
    for (int v = 0; v < vertexCount; ++v)
    {
      if (shrink[v])
      {
        offsets.row(v) *= 0.5;
      }
    }
  }
  return offsets;
}

Status addPaddingLayer(HexMesh& mesh,
  const std::function<Eigen::RowVector3d(int vertex)>& innerPosition,
  HexPaddingResult& result)
{
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  if (hexCount == 0)
  {
    return Status::Failure("padding needs at least one hex");
  }
  result.BoundaryQuads = ComputeHexBoundaryQuads(mesh);
  const int quadCount = static_cast<int>(result.BoundaryQuads.rows());

  result.InnerCopy.assign(vertexCount, -1);
  int copies = 0;
  for (int q = 0; q < quadCount; ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      int& copy = result.InnerCopy[result.BoundaryQuads(q, k)];
      if (copy < 0)
      {
        copy = vertexCount + copies++;
      }
    }
  }
  Points vertices(vertexCount + copies, 3);
  vertices.topRows(vertexCount) = mesh.Vertices;
  for (int v = 0; v < vertexCount; ++v)
  {
    if (result.InnerCopy[v] >= 0)
    {
      vertices.row(result.InnerCopy[v]) = innerPosition(v);
    }
  }

  Hexes cells(hexCount + quadCount, 8);
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      const int v = mesh.Cells(h, k);
      cells(h, k) = result.InnerCopy[v] >= 0 ? result.InnerCopy[v] : v;
    }
  }
  // The boundary quad (a, b, c, d) turns counter-clockwise seen from outside, so (a, d, c, b)
  // turns counter-clockwise seen from the padding hex below it: that is the hex's bottom face
  // 0-1-2-3 in VTK's order, with the inner copies as the top face 4-5-6-7.
  for (int q = 0; q < quadCount; ++q)
  {
    const int order[4] = { 0, 3, 2, 1 };
    for (int k = 0; k < 4; ++k)
    {
      const int v = result.BoundaryQuads(q, order[k]);
      cells(hexCount + q, k) = v;
      cells(hexCount + q, 4 + k) = result.InnerCopy[v];
    }
  }
  mesh.Vertices = std::move(vertices);
  mesh.Cells = std::move(cells);
  return Status::Success();
}

} // namespace polycubehex
