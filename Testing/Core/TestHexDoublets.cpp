// SPDX-License-Identifier: BSD-3-Clause
// FindHexDoublets and RemoveBoundaryDoublets on a slab of cubes whose centre cube is split in two
// through a fold vertex on its bottom (and its copy on the top): the mesh is combinatorially
// valid, but no positions of the fold vertices make both halves positive; the worse half is
// removed, the rest stays valid and its split hex can be made a cube; a plain lattice has no
// doublets and stays as it is; a copy of one of its cubes is removed again (RemoveOverlappingHexes).
#include "HexDoublets.h"
#include "HexMeshValidity.h"
#include "HexScaledJacobian.h"

#include "TestAssert.h"

#include <algorithm>
#include <iostream>
#include <random>

using namespace polycubehex;

namespace
{
/// A slab of three by three unit cubes, its centre cube split in two through a fold vertex U on
/// its bottom and its copy U1 on its top (ids 32 and 33).
struct SplitSlab
{
  HexMesh Mesh;
  static int Id(int i, int j, int k) { return i + 4 * (j + 4 * k); }
  static constexpr int U = 32;
  static constexpr int U1 = 33;
};

SplitSlab MakeSplitSlab()
{
  SplitSlab slab;
  HexMesh& mesh = slab.Mesh;
  mesh.Vertices.resize(34, 3);
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        mesh.Vertices.row(SplitSlab::Id(i, j, k)) << i, j, k;
      }
    }
  }
  mesh.Vertices.row(SplitSlab::U) << 1.5, 1.5, 0.0;
  mesh.Vertices.row(SplitSlab::U1) << 1.5, 1.5, 1.0;
  auto id = &SplitSlab::Id;
  mesh.Cells.resize(10, 8);
  int h = 0;
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      if (i == 1 && j == 1)
      {
        continue;
      }
      mesh.Cells.row(h++) << id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0),
        id(i, j, 1), id(i + 1, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1);
    }
  }
  // The halves p c s u and p u s t of the centre cube share (u p p1 u1) and (s u u1 s1).
  const int p = id(1, 1, 0);
  const int c = id(2, 1, 0);
  const int s = id(2, 2, 0);
  const int t = id(1, 2, 0);
  mesh.Cells.row(h++) << p, c, s, SplitSlab::U, p + 16, c + 16, s + 16, SplitSlab::U1;
  mesh.Cells.row(h++) << p, SplitSlab::U, s, t, p + 16, SplitSlab::U1, s + 16, t + 16;
  return slab;
}

void TestFoldCannotBePositive()
{
  SplitSlab slab = MakeSplitSlab();
  HexMesh& mesh = slab.Mesh;
  const auto doublets = FindHexDoublets(mesh);
  PCH_CHECK(doublets.rows() == 1);
  PCH_CHECK(doublets(0, 0) == 8 && doublets(0, 1) == 9);
  // Wherever the fold vertices go, one half keeps a corner of the opposite sign.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-0.5, 1.5);
  double bestWorse = -1.0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    for (int v : { SplitSlab::U, SplitSlab::U1 })
    {
      mesh.Vertices.row(v) << 1.0 + coordinate(random), 1.0 + coordinate(random),
        (v == SplitSlab::U ? 0.0 : 1.0) + 0.5 * (coordinate(random) - 0.5);
    }
    const Eigen::VectorXd quality = ComputeHexScaledJacobians(mesh);
    bestWorse = std::max(bestWorse, std::min(quality[8], quality[9]));
  }
  std::cout << "split cube: best of the two halves' minimum over 2000 placements " << bestWorse
            << std::endl;
  PCH_CHECK(bestWorse <= 1e-12);
}

void TestRemoval()
{
  SplitSlab slab = MakeSplitSlab();
  HexMesh& mesh = slab.Mesh;
  HexMeshValidity validity;
  PCH_CHECK(checkHexMeshValidity(mesh, validity));
  PCH_CHECK(validity.IsValid()); // combinatorially valid, yet the halves cannot both be positive
  Eigen::VectorXd quality = Eigen::VectorXd::Ones(10);
  quality[8] = 0.2;
  quality[9] = 0.1;
  std::vector<int> removed;
  PCH_CHECK(RemoveBoundaryDoublets(mesh, quality, &removed) == 1);
  PCH_CHECK(removed.size() == 1 && removed[0] == 9); // the worse half
  PCH_CHECK(mesh.Cells.rows() == 9);
  PCH_CHECK(FindHexDoublets(mesh).rows() == 0);
  PCH_CHECK(checkHexMeshValidity(mesh, validity));
  PCH_CHECK(validity.IsValid());
  // The half left is a proper hex once its fold vertices take the removed half's corners.
  mesh.Vertices.row(SplitSlab::U) = mesh.Vertices.row(SplitSlab::Id(1, 2, 0));
  mesh.Vertices.row(SplitSlab::U1) = mesh.Vertices.row(SplitSlab::Id(1, 2, 1));
  PCH_CHECK_NEAR(ComputeHexScaledJacobians(mesh).minCoeff(), 1.0, 1e-12);
}

HexMesh MakeCubes()
{
  HexMesh mesh;
  mesh.Vertices.resize(27, 3);
  for (int k = 0; k < 3; ++k)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        mesh.Vertices.row(i + 3 * (j + 3 * k)) << i, j, k;
      }
    }
  }
  auto id = [](int i, int j, int k) { return i + 3 * (j + 3 * k); };
  mesh.Cells.resize(8, 8);
  int h = 0;
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        mesh.Cells.row(h++) << id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1);
      }
    }
  }
  return mesh;
}

void TestLatticeUntouched()
{
  // Two by two by two cubes: every hex pair shares at most one face.
  HexMesh mesh = MakeCubes();
  const Hexes before = mesh.Cells;
  PCH_CHECK(FindHexDoublets(mesh).rows() == 0);
  PCH_CHECK(RemoveBoundaryDoublets(mesh, ComputeHexScaledJacobians(mesh)) == 0);
  PCH_CHECK(mesh.Cells == before);
  PCH_CHECK(RemoveOverlappingHexes(mesh, ComputeHexScaledJacobians(mesh)) == 0);
  PCH_CHECK(mesh.Cells == before);
}

void TestOverlapRemoved()
{
  // Two by two by two cubes and a copy of the corner cube, its quads used three times.
  HexMesh mesh = MakeCubes();
  const Hexes cubes = mesh.Cells;
  mesh.Cells.conservativeResize(9, 8);
  mesh.Cells.row(8) = mesh.Cells.row(7);
  HexMeshValidity validity;
  PCH_CHECK(checkHexMeshValidity(mesh, validity));
  PCH_CHECK(!validity.IsValid());
  Eigen::VectorXd quality = Eigen::VectorXd::Ones(9);
  quality[8] = 0.5;
  PCH_CHECK(RemoveOverlappingHexes(mesh, quality) == 1);
  PCH_CHECK(mesh.Cells == cubes);
  PCH_CHECK(checkHexMeshValidity(mesh, validity));
  PCH_CHECK(validity.IsValid());
}
} // namespace

int main(int, char*[])
{
  TestFoldCannotBePositive();
  TestRemoval();
  TestLatticeUntouched();
  TestOverlapRemoved();
  return PCH_TEST_RESULT();
}
