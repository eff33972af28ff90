// SPDX-License-Identifier: BSD-3-Clause
// TriangleGrid answers "which triangle is nearest to p" by searching the cells about p and
// stopping once no unsearched cell can hold a nearer one. Every answer here is compared with a
// scan of all triangles, over cell sizes from far finer than the triangles to coarser than the
// whole surface, for points on, near, inside and far outside a sphere, with and without a
// filter on the triangles, so that a search that stops too early or skips a cell fails.
#include "TriangleGrid.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace polycubehex;
using polycubehex_test::Icosphere;

namespace
{
/// The nearest accepted triangle by a scan of all of them (-1 if none) and its distance.
template<class Accept>
int ScanNearest(const SurfaceMesh& mesh,
  const Eigen::Vector3d& p,
  const Accept& accept,
  double& distance)
{
  int nearest = -1;
  distance = std::numeric_limits<double>::max();
  for (int f = 0; f < static_cast<int>(mesh.Faces.rows()); ++f)
  {
    if (!accept(f))
    {
      continue;
    }
    const double d = (ClosestPointOnTriangle(p,
                        mesh.Vertices.row(mesh.Faces(f, 0)).transpose(),
                        mesh.Vertices.row(mesh.Faces(f, 1)).transpose(),
                        mesh.Vertices.row(mesh.Faces(f, 2)).transpose()) -
      p)
                       .norm();
    if (d < distance)
    {
      distance = d;
      nearest = f;
    }
  }
  return nearest;
}
} // namespace

int main()
{
  // A unit sphere of 1280 triangles, edges about 0.1.
  const SurfaceMesh sphere = Icosphere(3, 1.0);
  const auto all = [](int) { return true; };
  // Only the triangles of the upper half, so that points below search far for theirs.
  const auto upper = [&sphere](int f) { return sphere.Vertices.row(sphere.Faces(f, 0))[2] > 0.0; };

  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  int checked = 0;
  for (double cellSize : { 0.01, 0.05, 0.2, 1.0, 5.0 })
  {
    const TriangleGrid grid(sphere.Vertices, sphere.Faces, cellSize);
    PCH_CHECK(grid.CellSize() >= cellSize);
    for (int trial = 0; trial < 600; ++trial)
    {
      Eigen::Vector3d p;
      switch (trial % 4)
      {
        case 0: // anywhere in and about the grid, partly outside it
          p = Eigen::Vector3d(uniform(random), uniform(random), uniform(random)) * 1.5;
          break;
        case 1: // far outside
          p =
            Eigen::Vector3d(uniform(random), uniform(random), uniform(random)).normalized() * 20.0;
          break;
        default: // on or near the sphere
        {
          const Eigen::Vector3d direction =
            Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized();
          p = direction * (1.0 + (trial % 4 == 2 ? 0.0 : 0.05 * uniform(random)));
        }
      }
      for (int filtered = 0; filtered < 2; ++filtered)
      {
        Eigen::Vector3d closest;
        const int found =
          filtered ? grid.Nearest(p, upper, closest) : grid.Nearest(p, all, closest);
        double expected = 0.0;
        const int scanned = filtered ? ScanNearest(sphere, p, upper, expected)
                                     : ScanNearest(sphere, p, all, expected);
        PCH_CHECK(found >= 0 && scanned >= 0);
        PCH_CHECK_NEAR((closest - p).norm(), expected, 1e-12);
        if (filtered && found >= 0)
        {
          PCH_CHECK(upper(found));
        }
        // The closest point lies on the triangle returned.
        if (found >= 0)
        {
          const Eigen::Vector3d onFound = ClosestPointOnTriangle(p,
            sphere.Vertices.row(sphere.Faces(found, 0)).transpose(),
            sphere.Vertices.row(sphere.Faces(found, 1)).transpose(),
            sphere.Vertices.row(sphere.Faces(found, 2)).transpose());
          PCH_CHECK_NEAR((onFound - closest).norm(), 0.0, 1e-15);
        }
        ++checked;
      }
    }
  }
  PCH_CHECK(checked == 5 * 600 * 2);

  // Visit with ring 1 reaches every triangle within one cell of p.
  {
    const TriangleGrid grid(sphere.Vertices, sphere.Faces, 0.2);
    const Eigen::Vector3d p(0.0, 0.0, 1.0);
    std::vector<char> seen(static_cast<size_t>(sphere.Faces.rows()), 0);
    grid.Visit(p, 1, -1, [&seen](int f) { seen[static_cast<size_t>(f)] = 1; });
    for (int f = 0; f < static_cast<int>(sphere.Faces.rows()); ++f)
    {
      const double d = (ClosestPointOnTriangle(p,
                          sphere.Vertices.row(sphere.Faces(f, 0)).transpose(),
                          sphere.Vertices.row(sphere.Faces(f, 1)).transpose(),
                          sphere.Vertices.row(sphere.Faces(f, 2)).transpose()) -
        p)
                         .norm();
      if (d <= grid.CellSize())
      {
        PCH_CHECK(seen[static_cast<size_t>(f)]);
      }
    }
  }

  // Nothing to find: no triangles at all, or none accepted.
  {
    const SurfaceMesh none;
    const TriangleGrid empty(none.Vertices, none.Faces, 0.1);
    Eigen::Vector3d closest;
    PCH_CHECK(empty.Nearest(Eigen::Vector3d(1, 2, 3), all, closest) == -1);
    PCH_CHECK((closest - Eigen::Vector3d(1, 2, 3)).norm() == 0.0);
    const TriangleGrid grid(sphere.Vertices, sphere.Faces, 0.2);
    PCH_CHECK(grid.Nearest(
                Eigen::Vector3d(0, 0, 0), [](int) { return false; }, closest) == -1);
  }
  return polycubehex_test::FailureCount();
}
