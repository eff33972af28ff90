// SPDX-License-Identifier: BSD-3-Clause
// untangleHexMesh on a cube lattice whose charts are the cube's six faces: a few interior, face
// and edge vertices pushed through their neighbours are untangled, boundary vertices stay on
// the cube's surface, corners do not move; a perfect lattice stays perfect; one or two threads
// give the same bits; a fork where the inverted count stalls is the run that stops there.
#include "HexPadding.h"
#include "HexScaledJacobian.h"
#include "HexUntangling.h"

#include "TestAssert.h"
#include "TestHexLattice.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <thread>
#include <vector>

using namespace polycubehex;
using polycubehex::testing::Lattice;
using polycubehex::testing::MakeLattice;
using polycubehex::testing::SurfaceError;

namespace
{
void TestTangledLattice()
{
  Lattice lattice = MakeLattice(6);
  HexMesh& mesh = lattice.Mesh;
  const Points start = mesh.Vertices;
  const double h = 1.0 / 6.0;
  // Interior vertices pushed through a neighbour, a face vertex through its neighbour within
  // the face z = 0, an edge vertex along the edge (y = 0, z = 0), a vertex of the face x = 1.
  mesh.Vertices.row(lattice.Id(2, 2, 2)) += Eigen::RowVector3d(1.5 * h, 0.3 * h, 0.0);
  mesh.Vertices.row(lattice.Id(4, 3, 2)) += Eigen::RowVector3d(0.0, -1.2 * h, 0.8 * h);
  mesh.Vertices.row(lattice.Id(3, 3, 1)) += Eigen::RowVector3d(-0.4 * h, 0.0, -1.3 * h);
  mesh.Vertices.row(lattice.Id(3, 3, 0)) += Eigen::RowVector3d(1.4 * h, 0.2 * h, 0.0);
  mesh.Vertices.row(lattice.Id(2, 0, 0)) += Eigen::RowVector3d(1.6 * h, 0.0, 0.0);
  mesh.Vertices.row(lattice.Id(6, 2, 4)) += Eigen::RowVector3d(0.0, 1.3 * h, -0.6 * h);
  const Eigen::VectorXd tangled = ComputeHexScaledJacobians(mesh);
  const int invertedBefore = static_cast<int>((tangled.array() <= 0.0).count());
  std::cout << "tangled lattice: " << invertedBefore << " inverted hexes, SJ min "
            << tangled.minCoeff() << std::endl;
  PCH_CHECK(invertedBefore >= 10);

  HexUntanglingResult result;
  PCH_CHECK(untangleHexMesh(
    mesh, lattice.VertexCharts, lattice.Surface, HexUntanglingParameters(), result));
  const Eigen::VectorXd quality = ComputeHexScaledJacobians(mesh);
  std::cout << "untangled: " << result.InvertedAfter << " inverted, SJ min " << quality.minCoeff()
            << " mean " << quality.mean() << " in " << result.Rounds << " rounds, "
            << result.Iterations << " iterations, " << result.ReleasedVertices << " released"
            << std::endl;
  PCH_CHECK(result.Kept);
  PCH_CHECK(result.InvertedBefore == invertedBefore);
  PCH_CHECK(result.InvertedAfter == 0);
  PCH_CHECK(result.ReleasedVertices == 0); // the cube's edges and corners are creases
  PCH_CHECK((quality.array() > 0.0).all());
  PCH_CHECK(quality.minCoeff() > 0.9);
  PCH_CHECK_NEAR(result.MinAfter, quality.minCoeff(), 1e-12);
  PCH_CHECK(SurfaceError(lattice, mesh.Vertices) < 1e-9);
  for (int i : { 0, 6 })
  {
    for (int j : { 0, 6 })
    {
      for (int k : { 0, 6 })
      {
        const int v = lattice.Id(i, j, k);
        PCH_CHECK(mesh.Vertices.row(v) == start.row(v));
      }
    }
  }
}

void TestPerfectLatticeStays()
{
  Lattice lattice = MakeLattice(4);
  const Points start = lattice.Mesh.Vertices;
  HexUntanglingResult result;
  PCH_CHECK(untangleHexMesh(
    lattice.Mesh, lattice.VertexCharts, lattice.Surface, HexUntanglingParameters(), result));
  const Eigen::VectorXd quality = ComputeHexScaledJacobians(lattice.Mesh);
  PCH_CHECK_NEAR(quality.minCoeff(), 1.0, 1e-12);
  PCH_CHECK_NEAR(result.MinAfter, 1.0, 1e-12);
  PCH_CHECK((lattice.Mesh.Vertices - start).cwiseAbs().maxCoeff() < 1e-9);
}

/// A lattice large enough for two threads, every free vertex jiggled, a few pushed through.
void TestThreadsGiveSameBits()
{
  Lattice lattice = MakeLattice(17);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jiggle(-0.3 / 17.0, 0.3 / 17.0);
  HexMesh& mesh = lattice.Mesh;
  for (int v = 0; v < mesh.Vertices.rows(); ++v)
  {
    if (lattice.VertexCharts[static_cast<size_t>(v)].empty())
    {
      for (int a = 0; a < 3; ++a)
      {
        mesh.Vertices(v, a) += jiggle(random);
      }
    }
  }
  mesh.Vertices.row(lattice.Id(5, 5, 5)) += Eigen::RowVector3d(1.5 / 17.0, 0.0, 0.0);
  mesh.Vertices.row(lattice.Id(11, 9, 4)) += Eigen::RowVector3d(0.0, 0.0, -1.4 / 17.0);
  HexUntanglingParameters params;
  params.MaxRounds = 4;
  params.IterationsPerRound = 60;
  HexMesh meshes[2] = { mesh, mesh };
  HexUntanglingResult results[2];
  for (int run = 0; run < 2; ++run)
  {
    setenv("POLYCUBEHEX_THREADS", run == 0 ? "1" : "2", 1);
    PCH_CHECK(
      untangleHexMesh(meshes[run], lattice.VertexCharts, lattice.Surface, params, results[run]));
  }
  unsetenv("POLYCUBEHEX_THREADS");
  std::cout << "17^3 lattice: SJ min " << results[0].MinBefore << " -> " << results[0].MinAfter
            << ", inverted " << results[0].InvertedBefore << " -> " << results[0].InvertedAfter
            << std::endl;
  PCH_CHECK(results[0].InvertedBefore > 0);
  PCH_CHECK(results[0].InvertedAfter == 0);
  PCH_CHECK(meshes[0].Vertices == meshes[1].Vertices);
  PCH_CHECK(results[0].Iterations == results[1].Iterations);
}

/// A cube corner, which may not move, pushed inside past the interior vertex next to it: its
/// hex stays inverted whatever the others do. With StallRounds the main rounds end once the
/// inverted count stops falling, sooner than the full run, and the result is still no worse
/// than the input.
void TestStallEndsRounds()
{
  HexUntanglingResult results[2];
  for (int stall : { 0, 1 })
  {
    Lattice lattice = MakeLattice(4);
    lattice.Mesh.Vertices.row(lattice.Id(0, 0, 0)) = Eigen::RowVector3d(0.4, 0.4, 0.4);
    HexUntanglingParameters params;
    params.ReleaseBelow = -1.0; // the corner stays a corner
    params.ReleaseCurvesBelow = -1.0;
    params.StallRounds = stall == 1 ? 2 : 0;
    HexUntanglingResult& result = results[stall];
    PCH_CHECK(untangleHexMesh(lattice.Mesh, lattice.VertexCharts, lattice.Surface, params, result));
    const Eigen::VectorXd quality = ComputeHexScaledJacobians(lattice.Mesh);
    std::cout << "pushed corner, StallRounds " << params.StallRounds << ": " << result.Rounds
              << " rounds, inverted " << result.InvertedBefore << " -> " << result.InvertedAfter
              << ", SJ min " << result.MinBefore << " -> " << result.MinAfter << std::endl;
    PCH_CHECK(result.InvertedBefore > 0);
    PCH_CHECK(result.InvertedAfter > 0); // the setup must leave the count stalled
    PCH_CHECK(result.InvertedAfter <= result.InvertedBefore);
    PCH_CHECK(static_cast<int>((quality.array() <= 0.0).count()) == result.InvertedAfter);
    PCH_CHECK(lattice.Mesh.Vertices.row(lattice.Id(0, 0, 0)) == Eigen::RowVector3d(0.4, 0.4, 0.4));
  }
  PCH_CHECK(results[1].Rounds < results[0].Rounds);
  PCH_CHECK(results[0].Rounds ==
    HexUntanglingParameters().MaxRounds + HexUntanglingParameters().FinalRounds);
}

/// The same pushed corner with a fork where the inverted count stalls: the main run is the run
/// without a fork, bit for bit, and the resumed fork is the run with StallRounds 2, bit for bit,
/// also when it finishes on another thread after the main run has moved on.
void TestForkIsTheStalledRun()
{
  auto pushed = []()
  {
    Lattice lattice = MakeLattice(4);
    lattice.Mesh.Vertices.row(lattice.Id(0, 0, 0)) = Eigen::RowVector3d(0.4, 0.4, 0.4);
    return lattice;
  };
  HexUntanglingParameters params;
  params.ReleaseBelow = -1.0;
  params.ReleaseCurvesBelow = -1.0;
  HexUntanglingParameters stalled = params;
  stalled.StallRounds = 2;
  Lattice plain = pushed();
  Lattice early = pushed();
  HexUntanglingResult plainResult;
  HexUntanglingResult earlyResult;
  PCH_CHECK(untangleHexMesh(plain.Mesh, plain.VertexCharts, plain.Surface, params, plainResult));
  PCH_CHECK(untangleHexMesh(early.Mesh, early.VertexCharts, early.Surface, stalled, earlyResult));

  Lattice main = pushed();
  HexSurfaceProjection projection(
    main.Surface, main.VertexCharts, main.Mesh, params.SoftFeatureAngle);
  int forks = 0;
  UntanglingFork kept;
  HexUntanglingResult mainResult;
  PCH_CHECK(untangleHexMesh(main.Mesh,
    projection,
    params,
    mainResult,
    {},
    [&forks, &kept](UntanglingFork&& fork)
    {
      ++forks;
      kept = std::move(fork);
    }));
  PCH_CHECK(forks == 1);
  PCH_CHECK(kept.Projection() != nullptr && kept.Projection() != &projection);
  PCH_CHECK(main.Mesh.Vertices == plain.Mesh.Vertices);
  PCH_CHECK(mainResult.Rounds == plainResult.Rounds);
  HexMesh resumed;
  HexUntanglingResult resumedResult;
  std::thread other([&]() { PCH_CHECK(resumeUntangling(kept, resumed, resumedResult)); });
  other.join();
  std::cout << "fork: main " << mainResult.Rounds << " rounds, fork " << resumedResult.Rounds
            << " rounds (the run with StallRounds 2: " << earlyResult.Rounds << ")" << std::endl;
  PCH_CHECK(resumed.Cells == early.Mesh.Cells);
  PCH_CHECK(resumed.Vertices == early.Mesh.Vertices);
  PCH_CHECK(resumedResult.Rounds == earlyResult.Rounds);
  PCH_CHECK(resumedResult.Iterations == earlyResult.Iterations);
  PCH_CHECK(resumedResult.InvertedAfter == earlyResult.InvertedAfter);
  PCH_CHECK(resumedResult.MinAfter == earlyResult.MinAfter);
  PCH_CHECK(resumedResult.InvertedBefore == earlyResult.InvertedBefore);

  // A run that never stalls never forks.
  Lattice tangled = MakeLattice(4);
  tangled.Mesh.Vertices.row(tangled.Id(2, 2, 2)) += Eigen::RowVector3d(0.3, 0.05, 0.0);
  HexSurfaceProjection tangledProjection(
    tangled.Surface, tangled.VertexCharts, tangled.Mesh, params.SoftFeatureAngle);
  forks = 0;
  PCH_CHECK(untangleHexMesh(tangled.Mesh,
    tangledProjection,
    HexUntanglingParameters(),
    mainResult,
    {},
    [&forks](UntanglingFork&&) { ++forks; }));
  PCH_CHECK(mainResult.InvertedBefore > 0 && mainResult.InvertedAfter == 0);
  PCH_CHECK(forks == 0);
  UntanglingFork empty;
  PCH_CHECK(!resumeUntangling(empty, resumed, resumedResult));
}

void TestRefusals()
{
  Lattice lattice = MakeLattice(2);
  HexUntanglingResult result;
  std::vector<std::vector<int>> tooFew(3);
  PCH_CHECK(
    !untangleHexMesh(lattice.Mesh, tooFew, lattice.Surface, HexUntanglingParameters(), result));
  HexUntanglingParameters bad;
  bad.VolumeWeight = 1.0;
  PCH_CHECK(!untangleHexMesh(lattice.Mesh, lattice.VertexCharts, lattice.Surface, bad, result));
}
} // namespace

int main(int, char*[])
{
  TestTangledLattice();
  TestPerfectLatticeStays();
  TestThreadsGiveSameBits();
  TestStallEndsRounds();
  TestForkIsTheStalledRun();
  TestRefusals();
  return PCH_TEST_RESULT();
}
