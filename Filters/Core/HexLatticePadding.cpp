// SPDX-License-Identifier: BSD-3-Clause
#include "HexLatticePadding.h"

#include "HexPadding.h"

#include <algorithm>
#include <array>

namespace polycubehex
{
namespace
{
/// VTK hexahedron corners as offsets from the cube's minimum corner.
constexpr int CubeCorners[8][3] = { { 0, 0, 0 },
  { 1, 0, 0 },
  { 1, 1, 0 },
  { 0, 1, 0 },
  { 0, 0, 1 },
  { 1, 0, 1 },
  { 1, 1, 1 },
  { 0, 1, 1 } };
} // namespace

Points LatticeInwardDirections(const LatticeHexMesh& lattice)
{
  const int vertexCount = static_cast<int>(lattice.LatticeVertices.rows());
  Points directions = Points::Zero(vertexCount, 3);
  for (int v = 0; v < vertexCount && v < static_cast<int>(lattice.VertexChartLabels.size()); ++v)
  {
    // Each normal direction counts once, however many charts carry it.
    bool seen[6] = { false, false, false, false, false, false };
    for (int label : lattice.VertexChartLabels[v])
    {
      if (!seen[label])
      {
        seen[label] = true;
        directions(v, label / 2) += label % 2 == 0 ? -1.0 : 1.0;
      }
    }
  }
  return directions;
}

Status addLatticePaddingLayer(const Points& original,
  const Points& positions,
  const Tets& cells,
  const ChartPlanes& charts,
  double thickness,
  LatticeHexMesh& lattice,
  LatticePaddingResult& result,
  const PolycubeSeams* seams)
{
  result = LatticePaddingResult();
  HexMesh& mesh = lattice.Mesh;
  const int oldCount = static_cast<int>(lattice.LatticeVertices.rows());
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  const Points directions = LatticeInwardDirections(lattice);
  // Each hex's corners in its own frame: its vertices' coordinates without seams (the same
  // numbers), the cube at its origin with them.
  Points hexCorners(8 * static_cast<Eigen::Index>(hexCount), 3);
  const bool framed = lattice.HexOrigins.rows() == hexCount;
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      const Eigen::Index row = 8 * static_cast<Eigen::Index>(h) + k;
      if (framed)
      {
        for (int a = 0; a < 3; ++a)
        {
          hexCorners(row, a) = lattice.HexOrigins(h, a) + CubeCorners[k][a];
        }
      }
      else
      {
        hexCorners.row(row) = lattice.LatticeVertices.row(mesh.Cells(h, k));
      }
    }
  }
  const Points offsets = ComputePaddingOffsets(
    mesh.Cells, hexCorners, lattice.HexCornerRotations, directions, thickness);
  std::vector<Eigen::RowVector3d> copyLattice(oldCount);
  int unmapped = 0;
  auto innerPosition = [&](int v) -> Eigen::RowVector3d
  {
    const Eigen::Vector3d from = lattice.LatticeVertices.row(v).transpose();
    const Eigen::Vector3d to = from + offsets.row(v).transpose();
    copyLattice[v] = to.transpose();
    Eigen::RowVector3d image;
    if (MapLatticePoint(
          original, positions, cells, charts, lattice.VertexTets[v], from, to, 1e-9, image, seams))
    {
      return image;
    }
    // Off the volume (a boundary vertex without charts): the mean of its hexes' centres.
    ++unmapped;
    Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
    int count = 0;
    for (int h = 0; h < lattice.HexCenters.rows(); ++h)
    {
      for (int k = 0; k < 8; ++k)
      {
        if (mesh.Cells(h, k) == v)
        {
          mean += lattice.HexCenters.row(h);
          ++count;
        }
      }
    }
    copyLattice[v] = from.transpose();
    return mesh.Vertices.row(v) +
      2.0 * thickness * (mean / std::max(1, count) - mesh.Vertices.row(v));
  };
  HexPaddingResult padding;
  Status status = addPaddingLayer(mesh, innerPosition, padding);
  if (!status)
  {
    return status;
  }
  result.PaddingHexCount = static_cast<int>(padding.BoundaryQuads.rows());
  result.UnmappedVertexCount = unmapped;
  const int newCount = static_cast<int>(mesh.Vertices.rows());
  Points latticeVertices(newCount, 3);
  latticeVertices.topRows(oldCount) = lattice.LatticeVertices;
  lattice.VertexTets.resize(newCount, -1);
  for (int v = 0; v < oldCount; ++v)
  {
    const int copy = padding.InnerCopy[v];
    if (copy >= 0)
    {
      latticeVertices.row(copy) = copyLattice[v];
      lattice.VertexTets[copy] = lattice.VertexTets[v];
    }
  }
  lattice.LatticeVertices = std::move(latticeVertices);
  lattice.VertexCharts.resize(newCount);
  lattice.VertexChartLabels.resize(newCount);
  return Status::Success();
}

} // namespace polycubehex
