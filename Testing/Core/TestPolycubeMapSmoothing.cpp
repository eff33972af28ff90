// SPDX-License-Identifier: BSD-3-Clause
// smoothPolycubeMap on a tet grid of a cube whose polycube is the cube itself, with the free
// coordinates the rounding would leave (interior vertices free, face vertices sliding in their
// face, edge vertices along their edge, corners fixed): a distorted map goes back to the
// identity, held coordinates do not move, an inverted map is untangled (and one its planes keep
// inverted is discarded), coordinates sharing a
// free variable stay equal, one or two threads give the same bits, bad sizes are refused.
#include "PolycubeMapSmoothing.h"
#include "TetGeometry.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <Eigen/SparseCore>

#include <cmath>
#include <cstdlib>
#include <vector>

using namespace polycubehex;
using polycubehex_test::CubeGrid;

namespace
{
bool OnFace(double value)
{
  return std::fabs(std::fabs(value) - 1.0) < 1e-12;
}

/// One free variable per coordinate not on a face of [-1, 1]^3 (a face's coordinate is its
/// plane). `shared` lists pairs of coordinates (3v + a) that move with one variable.
Eigen::SparseMatrix<double> CubeFreeBasis(const Points& rest,
  const std::vector<std::pair<int, int>>& shared = {})
{
  std::vector<int> column(static_cast<size_t>(rest.size()), -1);
  int columns = 0;
  for (Eigen::Index v = 0; v < rest.rows(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (!OnFace(rest(v, a)))
      {
        column[static_cast<size_t>(3 * v + a)] = columns++;
      }
    }
  }
  for (const auto& [first, second] : shared)
  {
    column[static_cast<size_t>(second)] = column[static_cast<size_t>(first)];
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (size_t i = 0; i < column.size(); ++i)
  {
    if (column[i] >= 0)
    {
      entries.emplace_back(static_cast<int>(i), column[i], 1.0);
    }
  }
  Eigen::SparseMatrix<double> basis(rest.size(), columns);
  basis.setFromTriplets(entries.begin(), entries.end());
  return basis;
}

int CountInverted(const Points& x, const Tets& cells)
{
  int count = 0;
  for (int t = 0; t < static_cast<int>(cells.rows()); ++t)
  {
    count += TetSignedVolume(x, cells, t) > 0.0 ? 0 : 1;
  }
  return count;
}

/// A smooth distortion that keeps every face in its plane (each coordinate's displacement
/// vanishes where that coordinate is +-1) and every tet positive.
Points Distort(const Points& rest, double amplitude)
{
  Points x = rest;
  for (Eigen::Index v = 0; v < rest.rows(); ++v)
  {
    const Eigen::RowVector3d p = rest.row(v);
    for (int a = 0; a < 3; ++a)
    {
      const double bump = 1.0 - p[a] * p[a];
      x(v, a) += amplitude * bump * std::sin(2.0 * p[(a + 1) % 3] + 1.0) * (1.0 + 0.5 * p[(a + 2) % 3]);
    }
  }
  return x;
}

void TestDistortedMapReturnsToIdentity()
{
  const TetMesh cube = CubeGrid(5);
  const Eigen::SparseMatrix<double> basis = CubeFreeBasis(cube.Vertices);
  Points x = Distort(cube.Vertices, 0.15);
  PCH_CHECK(CountInverted(x, cube.Cells) == 0);
  PolycubeMapSmoothingResult result;
  PCH_CHECK(smoothPolycubeMap(cube.Vertices, cube.Cells, basis, {}, x, result));
  PCH_CHECK(result.Kept);
  PCH_CHECK(result.EnergyBefore > 1.05);
  // 1 is the energy of a similarity, the optimum here.
  PCH_CHECK(result.EnergyAfter < 1.0 + 1e-4);
  PCH_CHECK(result.InvertedTetsAfter == 0);
  double farthest = 0.0;
  bool planesHeld = true;
  for (Eigen::Index v = 0; v < x.rows(); ++v)
  {
    farthest = std::max(farthest, (x.row(v) - cube.Vertices.row(v)).norm());
    for (int a = 0; a < 3; ++a)
    {
      planesHeld = planesHeld && (!OnFace(cube.Vertices(v, a)) || x(v, a) == cube.Vertices(v, a));
    }
  }
  PCH_CHECK(planesHeld);
  std::cout << "distorted: energy " << result.EnergyBefore << " -> " << result.EnergyAfter
            << ", farthest from the identity " << farthest << ", " << result.Iterations
            << " iterations" << std::endl;
  PCH_CHECK(farthest < 1e-2);
}

void TestInvertedMapIsUntangled()
{
  const TetMesh cube = CubeGrid(4);
  const Eigen::SparseMatrix<double> basis = CubeFreeBasis(cube.Vertices);
  Points x = cube.Vertices;
  // The vertex at (0, 0, 0) pushed past its neighbour at (0.5, 0, 0) and a face vertex slid
  // past its neighbour in its plane.
  const int centre = (2 * 5 + 2) * 5 + 2;
  x.row(centre) << 0.8, 0.1, -0.05;
  const int onFace = (0 * 5 + 2) * 5 + 2; // (-1, 0, 0)
  x.row(onFace) << -1.0, 0.7, 0.0;
  PolycubeMapSmoothingResult result;
  PCH_CHECK(smoothPolycubeMap(cube.Vertices, cube.Cells, basis, {}, x, result));
  std::cout << "inverted: " << result.InvertedTetsBefore << " -> " << result.InvertedTetsAfter
            << " tets, " << result.Rounds << " rounds" << std::endl;
  PCH_CHECK(result.InvertedTetsBefore > 0);
  PCH_CHECK(result.InvertedTetsAfter == 0);
  PCH_CHECK(CountInverted(x, cube.Cells) == 0);
  PCH_CHECK(x(onFace, 0) == -1.0);
}

void TestMapLeftInvertedIsDiscarded()
{
  // Only the interior vertex nearest (1, 1, 1) is free; the corner (-1, -1, -1), held by its
  // planes, is pushed inside so that tets the free vertex does not touch are inverted.
  const TetMesh cube = CubeGrid(3);
  const int free = (2 * 4 + 2) * 4 + 2; // (1/3, 1/3, 1/3)
  std::vector<Eigen::Triplet<double>> entries;
  for (int a = 0; a < 3; ++a)
  {
    entries.emplace_back(3 * free + a, a, 1.0);
  }
  Eigen::SparseMatrix<double> basis(cube.Vertices.size(), 3);
  basis.setFromTriplets(entries.begin(), entries.end());
  Points x = cube.Vertices;
  x.row(0) << -0.2, -0.2, -0.2;
  x.row(free) << 0.5, 0.1, 0.3;
  const Points start = x;
  PolycubeMapSmoothingResult result;
  PCH_CHECK(smoothPolycubeMap(cube.Vertices, cube.Cells, basis, {}, x, result));
  PCH_CHECK(result.InvertedTetsBefore > 0);
  PCH_CHECK(!result.Kept);
  PCH_CHECK(result.InvertedTetsAfter == result.InvertedTetsBefore);
  PCH_CHECK(x == start);
  // It gives up as soon as a round leaves more than half of the inverted tets, instead of
  // running all its rounds for a map that is discarded.
  std::cout << "forced inversions: gave up after " << result.Rounds << " of "
            << PolycubeMapSmoothingParameters().MaxRounds << " rounds" << std::endl;
  PCH_CHECK(result.GaveUp);
  PCH_CHECK(result.Rounds < PolycubeMapSmoothingParameters().MaxRounds);
  // Without the requirement, the free vertex's improvement is kept.
  PolycubeMapSmoothingParameters params;
  params.RequireUntangled = false;
  PCH_CHECK(smoothPolycubeMap(cube.Vertices, cube.Cells, basis, params, x, result));
  PCH_CHECK(result.Kept);
  PCH_CHECK((x.row(free) - cube.Vertices.row(free)).norm() < (start.row(free) - cube.Vertices.row(free)).norm());
}

void TestSharedVariablesStayEqual()
{
  const TetMesh cube = CubeGrid(4);
  // The y of a vertex on the face x = -1 and the z of an interior vertex elsewhere: one
  // variable, as a cut relation makes a plus copy follow its minus copy.
  const int a = (0 * 5 + 1) * 5 + 3; // (-1, -0.5, 0.5)
  const int b = (3 * 5 + 2) * 5 + 1; // (0.5, 0, -0.5)
  const Eigen::SparseMatrix<double> basis = CubeFreeBasis(cube.Vertices, { { 3 * a + 1, 3 * b + 2 } });
  Points x = Distort(cube.Vertices, 0.1);
  x(b, 2) = x(a, 1); // consistent with the basis
  PolycubeMapSmoothingResult result;
  PCH_CHECK(smoothPolycubeMap(cube.Vertices, cube.Cells, basis, {}, x, result));
  PCH_CHECK(result.Kept);
  PCH_CHECK(x(a, 1) == x(b, 2));
  PCH_CHECK(x(a, 0) == -1.0);
}

void TestThreadCountsAgree()
{
  const TetMesh cube = CubeGrid(10); // 6000 tets: two chunks of the parallel loop
  const Eigen::SparseMatrix<double> basis = CubeFreeBasis(cube.Vertices);
  Points one = Distort(cube.Vertices, 0.15);
  Points two = one;
  PolycubeMapSmoothingParameters params;
  params.MaxRounds = 1;
  params.IterationsPerRound = 30;
  PolycubeMapSmoothingResult result;
  setenv("POLYCUBEHEX_THREADS", "1", 1);
  PCH_CHECK(smoothPolycubeMap(cube.Vertices, cube.Cells, basis, params, one, result));
  setenv("POLYCUBEHEX_THREADS", "2", 1);
  PCH_CHECK(smoothPolycubeMap(cube.Vertices, cube.Cells, basis, params, two, result));
  unsetenv("POLYCUBEHEX_THREADS");
  PCH_CHECK(one == two);
}

void TestBadSizesAreRefused()
{
  const TetMesh cube = CubeGrid(2);
  Points x = cube.Vertices;
  PolycubeMapSmoothingResult result;
  const Eigen::SparseMatrix<double> wrong(3, 1);
  PCH_CHECK(!smoothPolycubeMap(cube.Vertices, cube.Cells, wrong, {}, x, result));
  Points fewer = cube.Vertices.topRows(4);
  PCH_CHECK(!smoothPolycubeMap(fewer, cube.Cells, CubeFreeBasis(cube.Vertices), {}, x, result));
  PCH_CHECK(x == cube.Vertices);
}
} // namespace

int main()
{
  TestDistortedMapReturnsToIdentity();
  TestInvertedMapIsUntangled();
  TestMapLeftInvertedIsDiscarded();
  TestSharedVariablesStayEqual();
  TestThreadCountsAgree();
  TestBadSizesAreRefused();
  return PCH_TEST_RESULT();
}
