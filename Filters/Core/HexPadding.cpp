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

/// The boundary quads and, optionally, the (hex, local face) each comes from.
Quads BoundaryQuadsOf(const HexMesh& mesh, std::vector<std::array<int, 2>>* faces)
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
      if (faces)
      {
        faces->push_back({ uses[i].Hex, uses[i].Face });
      }
      ++q;
    }
  }
  return quads;
}
} // namespace

Quads ComputeHexBoundaryQuads(const HexMesh& mesh)
{
  return BoundaryQuadsOf(mesh, nullptr);
}

Points ComputePaddingOffsets(const HexMesh& mesh,
  const Points& directions,
  double thickness,
  double minQuality)
{
  Points hexCorners(8 * mesh.Cells.rows(), 3);
  for (Eigen::Index h = 0; h < mesh.Cells.rows(); ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      hexCorners.row(8 * h + k) = mesh.Vertices.row(mesh.Cells(h, k));
    }
  }
  Points offsets =
    ComputePaddingOffsets(mesh.Cells, hexCorners, {}, directions, thickness, minQuality);
  if (offsets.rows() != mesh.Vertices.rows())
  {
    Points sized = Points::Zero(mesh.Vertices.rows(), 3);
    const Eigen::Index rows = std::min(offsets.rows(), sized.rows());
    sized.topRows(rows) = offsets.topRows(rows);
    offsets = std::move(sized);
  }
  return offsets;
}

Points ComputePaddingOffsets(const Hexes& cells,
  const Points& hexCorners,
  const std::vector<Eigen::Matrix3i>& cornerRotations,
  const Points& directions,
  double thickness,
  double minQuality)
{
  const int vertexCount = static_cast<int>(
    std::max<Eigen::Index>(directions.rows(), cells.rows() > 0 ? cells.maxCoeff() + 1 : 0));
  const int hexCount = static_cast<int>(cells.rows());
  HexMesh topology;
  topology.Cells = cells;
  std::vector<std::array<int, 2>> quadFaces; // (hex, local face) of each boundary quad
  const Quads quads = BoundaryQuadsOf(topology, &quadFaces);
  std::vector<bool> boundary(vertexCount, false);
  for (int q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      boundary[quads(q, k)] = true;
    }
  }
  Points offsets = Points::Zero(vertexCount, 3);
  for (int v = 0; v < vertexCount && v < directions.rows(); ++v)
  {
    if (boundary[v])
    {
      offsets.row(v) = thickness * directions.row(v);
    }
  }
  // Every hex after padding, as 8 (hex, corner of that hex, uses the copy) triples: the kept
  // hexes use the copies of their boundary vertices, a padding hex its quad's vertices and
  // their copies, seen from the hex the quad bounds.
  struct Corner
  {
    int Hex;
    int Local;
    bool Copy;
  };
  std::vector<std::array<Corner, 8>> hexes;
  hexes.reserve(hexCount + quads.rows());
  for (int h = 0; h < hexCount; ++h)
  {
    std::array<Corner, 8> hex;
    bool touches = false;
    for (int k = 0; k < 8; ++k)
    {
      hex[k] = { h, k, static_cast<bool>(boundary[cells(h, k)]) };
      touches = touches || hex[k].Copy;
    }
    if (touches)
    {
      hexes.push_back(hex);
    }
  }
  for (int q = 0; q < quads.rows(); ++q)
  {
    const int order[4] = { 0, 3, 2, 1 };
    const int h = quadFaces[q][0];
    std::array<Corner, 8> hex;
    for (int k = 0; k < 4; ++k)
    {
      const int local = Faces[quadFaces[q][1]][order[k]];
      hex[k] = { h, local, false };
      hex[4 + k] = { h, local, true };
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
        const Corner& corner = hex[k];
        const size_t row = 8 * static_cast<size_t>(corner.Hex) + corner.Local;
        corners.row(k) = hexCorners.row(static_cast<Eigen::Index>(row));
        if (corner.Copy)
        {
          const int v = cells(corner.Hex, corner.Local);
          if (cornerRotations.empty())
          {
            corners.row(k) += offsets.row(v);
          }
          else
          {
            corners.row(k) +=
              (cornerRotations[row].cast<double>() * offsets.row(v).transpose()).transpose();
          }
        }
      }
      if (HexScaledJacobian(corners) < minQuality)
      {
        for (int k = 0; k < 8; ++k)
        {
          if (hex[k].Copy)
          {
            shrink[cells(hex[k].Hex, hex[k].Local)] = true;
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
