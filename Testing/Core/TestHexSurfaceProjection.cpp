// SPDX-License-Identifier: BSD-3-Clause
// HexSurfaceProjection finds the nearest triangle of a vertex's chart through a grid of cells
// and stops searching as soon as no unvisited cell can hold a nearer one. Here every answer is
// compared with a scan of all the chart's triangles, for points on, near and far from a sphere
// split into six charts, inside and outside the grid, so that a search that stops too early
// (for instance in the point's own cell when the nearest triangle lies in the next) fails.
#include "HexSurfaceProjection.h"
#include "PolycubeCharts.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace polycubehex;
using polycubehex_test::HexCubeGrid;
using polycubehex_test::Icosphere;

namespace
{
/// The distance from p to the nearest triangle of `chart`, by scanning them all.
double BruteForceDistance(const HexSmoothingSurface& surface, int chart, const Eigen::Vector3d& p)
{
  double best = std::numeric_limits<double>::max();
  for (Eigen::Index f = 0; f < surface.Faces.rows(); ++f)
  {
    if (surface.FaceChart[static_cast<size_t>(f)] != chart)
    {
      continue;
    }
    const Eigen::Vector3d x = ClosestPointOnTriangle(p,
      surface.Vertices.row(surface.Faces(f, 0)).transpose(),
      surface.Vertices.row(surface.Faces(f, 1)).transpose(),
      surface.Vertices.row(surface.Faces(f, 2)).transpose());
    best = std::min(best, (x - p).norm());
  }
  return best;
}
} // namespace

int main()
{
  // A unit sphere of 1280 triangles (edges about 0.1), charted by the dominant axis of the
  // normals as a polycube labelling would.
  const SurfaceMesh sphere = Icosphere(3, 1.0);
  HexSmoothingSurface surface;
  surface.Vertices = sphere.Vertices;
  surface.Faces = sphere.Faces;
  surface.FaceChart = PolycubeFaceLabels(sphere.Vertices, sphere.Faces);

  // A 6 x 6 x 6 lattice of hexes of edge 0.2 inside it: the grid's cells are 0.2 wide, two
  // triangle edges. Each boundary vertex is put on one chart (all six are used).
  HexMesh hexes = HexCubeGrid(6);
  hexes.Vertices = hexes.Vertices * 0.2 - Points::Constant(hexes.Vertices.rows(), 3, 0.6);
  std::vector<std::vector<int>> vertexCharts(static_cast<size_t>(hexes.Vertices.rows()));
  std::vector<int> representative(6, -1);
  for (Eigen::Index v = 0; v < hexes.Vertices.rows(); ++v)
  {
    if (hexes.Vertices.row(v).cwiseAbs().maxCoeff() < 0.6 - 1e-9)
    {
      continue; // interior
    }
    const int chart = static_cast<int>(v % 6);
    vertexCharts[static_cast<size_t>(v)] = { chart };
    representative[static_cast<size_t>(chart)] = static_cast<int>(v);
  }
  const HexSurfaceProjection projection(surface, vertexCharts, hexes, 0.0);
  for (int chart = 0; chart < 6; ++chart)
  {
    PCH_CHECK(representative[static_cast<size_t>(chart)] >= 0);
    PCH_CHECK(projection.Kind(representative[static_cast<size_t>(chart)]) ==
      HexVertexKind::Surface);
  }

  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    Eigen::Vector3d p;
    if (trial % 3 == 0)
    {
      p = Eigen::Vector3d(uniform(random), uniform(random), uniform(random)) * 1.5; // anywhere
    }
    else
    {
      // On or near the sphere, where a vertex being smoothed usually is.
      Eigen::Vector3d direction(gaussian(random), gaussian(random), gaussian(random));
      direction.normalize();
      p = direction * (1.0 + (trial % 3 == 1 ? 0.0 : 0.05 * uniform(random)));
    }
    for (int chart = 0; chart < 6; ++chart)
    {
      const int v = representative[static_cast<size_t>(chart)];
      if (v < 0)
      {
        continue;
      }
      Eigen::Vector3d normal;
      const Eigen::Vector3d q = projection.Project(v, p, &normal);
      const double expected = BruteForceDistance(surface, chart, p);
      PCH_CHECK_NEAR((q - p).norm(), expected, 1e-12);
      // The answer lies on one of the chart's triangles.
      PCH_CHECK_NEAR(BruteForceDistance(surface, chart, q), 0.0, 1e-12);
      PCH_CHECK_NEAR(normal.norm(), 1.0, 1e-12);
      ++checked;
    }
  }
  PCH_CHECK(checked == 3000 * 6);
  return polycubehex_test::FailureCount();
}
