// SPDX-License-Identifier: BSD-3-Clause
// The local repair of cut surfaces (CutRepair) and the least-area minimisation (CutMinimize):
// a least-area meridian cocycle of a swept torus is spoilt by coboundaries of random tet blobs
// (inside and touching the boundary), which makes sheets touch each other and the boundary at
// isolated vertices; the repair must make the surface proper at every vertex without changing
// the cohomology class, and every component must then be a manifold, two-sided surface.
// Minimisation must bring the spoilt cocycle back to the meridian's area.
#include "CutMinimize.h"
#include "CutRepair.h"
#include "CutSurface.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"
#include "TopologyAdjacency.h"
#include "TopologyHomology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <vector>

using polycubehex::TetMesh;
using polycubehex_test::SweptTorus;

namespace
{
/// True when `difference` (one value per interior face) is a coboundary: integrating it along
/// the dual graph gives a consistent function on tets.
bool IsCoboundary(const polycubehex::TetAdjacency& adjacency, const std::vector<int>& difference)
{
  std::vector<long long> potential(adjacency.TetCount, 0);
  std::vector<char> seen(adjacency.TetCount, 0);
  std::vector<int> queue;
  for (int seed = 0; seed < adjacency.TetCount; ++seed)
  {
    if (seen[seed])
    {
      continue;
    }
    seen[seed] = 1;
    queue.assign(1, seed);
    for (size_t head = 0; head < queue.size(); ++head)
    {
      const int t = queue[head];
      for (int k = 0; k < 4; ++k)
      {
        const int n = adjacency.Neighbor(t, k);
        if (n < 0)
        {
          continue;
        }
        const long long value = potential[t] +
          polycubehex::InteriorFaceSign(adjacency, t, k) *
            difference[adjacency.InteriorFaceId(t, k)];
        if (!seen[n])
        {
          seen[n] = 1;
          potential[n] = value;
          queue.push_back(n);
        }
        else if (potential[n] != value)
        {
          return false;
        }
      }
    }
  }
  return true;
}

int CountImproperVertices(const TetMesh& mesh,
  const polycubehex::TetAdjacency& adjacency,
  const std::vector<int>& cocycle)
{
  int count = 0;
  for (int v = 0; v < mesh.Vertices.rows(); ++v)
  {
    count += polycubehex::IsCocycleProperAtVertex(mesh.Cells, adjacency, cocycle, v) ? 0 : 1;
  }
  return count;
}
} // namespace

int main(int, char*[])
{
  const double r = 0.5;
  const TetMesh mesh = SweptTorus(2.0, r, 0, 3, 24);
  polycubehex::TetAdjacency adjacency;
  PCH_CHECK(
    polycubehex::BuildTetAdjacency(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency)
      .Ok());
  polycubehex::CohomologyBasis basis;
  PCH_CHECK(polycubehex::ComputeCohomologyBasis(mesh.Cells, adjacency, true, basis).Ok());
  PCH_CHECK(basis.Beta1 == 1);
  if (basis.Beta1 != 1)
  {
    return PCH_TEST_RESULT();
  }
  const int faceCount = static_cast<int>(adjacency.InteriorFaces.size());
  std::vector<double> faceArea(faceCount);
  for (int f = 0; f < faceCount; ++f)
  {
    faceArea[f] = polycubehex::InteriorFaceArea(mesh.Cells, adjacency, mesh.Vertices, f);
  }
  std::vector<int> meridian = basis.Cocycles[0];
  const double initialArea = polycubehex::CochainArea(faceArea, meridian);
  const double meridianArea =
    polycubehex::MinimizeCocycleArea(adjacency, faceArea, meridian, 1, 10);
  std::cout << "meridian: basis cocycle area " << initialArea << ", minimised " << meridianArea
            << " (pi r^2 = " << 3.14159265358979 * r * r << ")" << std::endl;
  PCH_CHECK(meridianArea <= 3.14159265358979 * r * r);
  PCH_CHECK(IsCoboundary(adjacency,
    [&]
    {
      std::vector<int> d(faceCount);
      for (int f = 0; f < faceCount; ++f)
      {
        d[f] = meridian[f] - basis.Cocycles[0][f];
      }
      return d;
    }()));
  PCH_CHECK(CountImproperVertices(mesh, adjacency, meridian) == 0);

  std::mt19937 random(7);
  int totalImproper = 0;
  int repaired = 0;
  int trials = 40;
  for (int trial = 0; trial < trials; ++trial)
  {
    // Spoil: add the coboundary of a few random blobs of tets (some seeded at the boundary).
    std::vector<int> cocycle = meridian;
    const int blobs = 1 + trial % 4;
    for (int b = 0; b < blobs; ++b)
    {
      int seed = static_cast<int>(random() % adjacency.TetCount);
      if (trial % 2 == 0)
      {
        while ((adjacency.Neighbor(seed, 0) >= 0 && adjacency.Neighbor(seed, 1) >= 0 &&
          adjacency.Neighbor(seed, 2) >= 0 && adjacency.Neighbor(seed, 3) >= 0))
        {
          seed = static_cast<int>(random() % adjacency.TetCount);
        }
      }
      const int size = 1 + static_cast<int>(random() % 25);
      std::vector<int> blob{ seed };
      std::vector<char> inBlob(adjacency.TetCount, 0);
      inBlob[seed] = 1;
      for (size_t i = 0; i < blob.size() && static_cast<int>(blob.size()) < size; ++i)
      {
        for (int k = 0; k < 4 && static_cast<int>(blob.size()) < size; ++k)
        {
          const int n = adjacency.Neighbor(blob[i], k);
          if (n >= 0 && !inBlob[n] && random() % 3 != 0)
          {
            inBlob[n] = 1;
            blob.push_back(n);
          }
        }
      }
      const int shift = random() % 2 ? 1 : -1;
      for (int t : blob)
      {
        for (int k = 0; k < 4; ++k)
        {
          const int n = adjacency.Neighbor(t, k);
          if (n >= 0 && !inBlob[n])
          {
            cocycle[adjacency.InteriorFaceId(t, k)] -=
              polycubehex::InteriorFaceSign(adjacency, t, k) * shift;
          }
        }
      }
    }
    const std::vector<int> spoilt = cocycle;
    const int improper = CountImproperVertices(mesh, adjacency, cocycle);
    totalImproper += improper;
    int moves = 0;
    const bool ok =
      polycubehex::RepairCocycleSurface(mesh.Cells, adjacency, faceArea, cocycle, 10000, &moves);
    PCH_CHECK(ok);
    PCH_CHECK(polycubehex::IsCocycle(mesh.Cells, adjacency, cocycle));
    std::vector<int> difference(faceCount);
    for (int f = 0; f < faceCount; ++f)
    {
      difference[f] = cocycle[f] - spoilt[f];
    }
    PCH_CHECK(IsCoboundary(adjacency, difference));
    const int after = CountImproperVertices(mesh, adjacency, cocycle);
    PCH_CHECK(after == 0);
    repaired += improper > 0 && after == 0 ? 1 : 0;

    // Every face carries +-1 and every component is a valid (manifold, two-sided) surface.
    std::vector<polycubehex::CutFaceEntry> entries;
    bool simple = true;
    for (int f = 0; f < faceCount; ++f)
    {
      if (cocycle[f] != 0)
      {
        simple = simple && std::abs(cocycle[f]) == 1;
        entries.push_back({ f, cocycle[f] > 0 ? 1 : -1 });
      }
    }
    PCH_CHECK(simple);
    polycubehex::CutSurfaceReport report;
    polycubehex::AnalyzeCutSurface(mesh.Cells, adjacency, mesh.Vertices, entries, report);
    if (!report.Manifold || !report.TwoSided)
    {
      std::cerr << "trial " << trial << ": " << report.Problem << std::endl;
    }
    PCH_CHECK(report.Manifold && report.TwoSided);

    // Minimisation from the spoilt cocycle finds the meridian's area again.
    std::vector<int> again = spoilt;
    const double area = polycubehex::MinimizeCocycleArea(adjacency, faceArea, again, 1, 10);
    PCH_CHECK_NEAR(area, meridianArea, 1e-9);
  }
  std::cout << trials << " spoilt cocycles: " << totalImproper << " improper vertices in all, "
            << repaired << " cocycles repaired from improper" << std::endl;
  PCH_CHECK(repaired > trials / 4);
  return PCH_TEST_RESULT();
}
