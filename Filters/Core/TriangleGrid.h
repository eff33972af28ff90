// SPDX-License-Identifier: BSD-3-Clause
// Triangles binned in a uniform grid, for the nearest triangle to a point and for the triangles
// near it. The hex smoothing projects every boundary vertex through it (HexSurfaceProjection.h),
// and the filters' sampled surface distance measures with it: a query looks at the few cells
// about the point and computes closest points on plain coordinates, which is several times
// faster than a general cell locator that builds a cell object per candidate.
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace polycubehex
{

/// Closest point of triangle (a, b, c) to p, by the Voronoi region of p (vertex, edge or face).
Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c);

/// A uniform grid over the bounding box of `vertices` whose cells list the triangles whose
/// bounding boxes reach into them. The vertices and faces must outlive the grid; const methods
/// are safe to call from several threads.
class TriangleGrid
{
public:
  /// @param cellSize  the wanted edge of a cell; raised where needed so that the grid has at
  ///                  most about 2^21 cells
  TriangleGrid(const Points& vertices, const Triangles& faces, double cellSize);

  double CellSize() const { return this->Cell; }
  /// Rings beyond this one hold no more cells.
  int MaxRing() const;

  /// Distance from p to the walls of its own cell, slightly understated so that rounding cannot
  /// overstate it; 0 when p is outside the grid (its cell is then a clamped one).
  double WallDistance(const Eigen::Vector3d& p) const;

  /// Calls visit(f) for the triangles binned within `ring` cells of p's cell, skipping the
  /// cells within `inner` cells (already searched; -1 for none). A triangle spanning several
  /// cells may be visited more than once.
  template<class Visitor>
  void Visit(const Eigen::Vector3d& p, int ring, int inner, Visitor&& visit) const;

  /// The triangle nearest to p among those accept(f) approves (-1 if none), and the closest
  /// point on it. Ties go to the lowest triangle index, so the answer does not depend on the
  /// grid's cells.
  template<class Accept>
  int Nearest(const Eigen::Vector3d& p, const Accept& accept, Eigen::Vector3d& closest) const;

private:
  std::array<int, 3> CellOf(const Eigen::Vector3d& p) const;
  size_t Index(int i, int j, int k) const
  {
    return (static_cast<size_t>(k) * this->Dims[1] + j) * this->Dims[0] + i;
  }

  const Points& Vertices;
  const Triangles& Faces;
  Eigen::Vector3d Origin = Eigen::Vector3d::Zero();
  double Cell = 1.0;
  std::array<int, 3> Dims = { 1, 1, 1 };
  std::vector<int> Start; ///< per cell, where its triangles begin in Items (CSR)
  std::vector<int> Items;
  /// #F bounding boxes: a triangle whose box is farther than the nearest one found so far
  /// cannot be nearer, and is skipped without computing its closest point.
  std::vector<Eigen::AlignedBox3d> FaceBox;
};

template<class Visitor>
void TriangleGrid::Visit(const Eigen::Vector3d& p, int ring, int inner, Visitor&& visit) const
{
  const std::array<int, 3> centre = this->CellOf(p);
  for (int i = std::max(0, centre[0] - ring); i <= std::min(this->Dims[0] - 1, centre[0] + ring);
       ++i)
  {
    for (int j = std::max(0, centre[1] - ring); j <= std::min(this->Dims[1] - 1, centre[1] + ring);
         ++j)
    {
      for (int k = std::max(0, centre[2] - ring);
           k <= std::min(this->Dims[2] - 1, centre[2] + ring);
           ++k)
      {
        if (std::abs(i - centre[0]) <= inner && std::abs(j - centre[1]) <= inner &&
          std::abs(k - centre[2]) <= inner)
        {
          continue;
        }
        const size_t b = this->Index(i, j, k);
        for (int item = this->Start[b]; item < this->Start[b + 1]; ++item)
        {
          visit(this->Items[static_cast<size_t>(item)]);
        }
      }
    }
  }
}

template<class Accept>
int TriangleGrid::Nearest(const Eigen::Vector3d& p,
  const Accept& accept,
  Eigen::Vector3d& closest) const
{
  double best = std::numeric_limits<double>::max();
  int nearest = -1;
  closest = p;
  if (this->Faces.rows() == 0)
  {
    return nearest;
  }
  auto consider = [&](int f)
  {
    // Strictly farther only: a tie must still be compared by face index.
    if (this->FaceBox[static_cast<size_t>(f)].squaredExteriorDistance(p) > best || !accept(f))
    {
      return;
    }
    const Eigen::Vector3d x = ClosestPointOnTriangle(p,
      this->Vertices.row(this->Faces(f, 0)).transpose(),
      this->Vertices.row(this->Faces(f, 1)).transpose(),
      this->Vertices.row(this->Faces(f, 2)).transpose());
    const double d = (x - p).squaredNorm();
    if (d < best || (d == best && f < nearest))
    {
      best = d;
      closest = x;
      nearest = f;
    }
  };
  // The nearest triangle found within `ring` cells is the nearest overall once it is closer
  // than `ring` cells: any closer triangle would have been binned in the searched cells.
  // p's own cell first: a point on or near the surface usually finds its triangle there, closer
  // than the cell's walls, and then nothing outside the cell can be as close (a triangle that
  // reaches into the ball about p up to that distance crosses the cell and is binned in it).
  int inner = -1;
  const double wall = this->WallDistance(p);
  if (wall > 0.0)
  {
    this->Visit(p, 0, -1, consider);
    if (std::sqrt(best) < wall)
    {
      return nearest;
    }
    inner = 0;
  }
  for (int ring = 1;; inner = ring, ring *= 2)
  {
    this->Visit(p, ring, inner, consider);
    if (std::sqrt(best) <= ring * this->Cell)
    {
      break;
    }
    if (ring > this->MaxRing())
    {
      // Far from every accepted triangle: try them all.
      for (int f = 0; f < static_cast<int>(this->Faces.rows()); ++f)
      {
        consider(f);
      }
      break;
    }
  }
  return nearest;
}

} // namespace polycubehex
