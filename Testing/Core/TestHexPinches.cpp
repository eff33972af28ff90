// SPDX-License-Identifier: BSD-3-Clause
// RemovePinchingHexes (HexDoublets.h): on a slab of 4 x 4 cubes with two 2 x 2 blocks on top
// that touch along one vertical edge only (the pinch a rounding with inverted tets leaves in the
// lattice), the worst cube at the pinch is removed and the mesh becomes valid; a valid grid is
// left as it is; two lone cubes touching along an edge are kept, since removing either would
// leave vertices unused.
#include "HexDoublets.h"
#include "HexMeshValidity.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <iostream>
#include <vector>

using namespace polycubehex;

namespace
{
/// Index of cube (i, j, k) in HexCubeGrid(4).
int Cube(int i, int j, int k)
{
  return i + 4 * (j + 4 * k);
}

/// The 4 x 4 slab (k = 0) of HexCubeGrid(4) and the cubes `top` of the layer above it.
HexMesh SlabWith(const std::vector<std::array<int, 2>>& top)
{
  const HexMesh grid = polycubehex_test::HexCubeGrid(4);
  HexMesh mesh;
  mesh.Vertices = grid.Vertices;
  std::vector<int> kept;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      kept.push_back(Cube(i, j, 0));
    }
  }
  for (const auto& cube : top)
  {
    kept.push_back(Cube(cube[0], cube[1], 1));
  }
  mesh.Cells.resize(static_cast<Eigen::Index>(kept.size()), 8);
  for (size_t h = 0; h < kept.size(); ++h)
  {
    mesh.Cells.row(static_cast<Eigen::Index>(h)) = grid.Cells.row(kept[h]);
  }
  return mesh;
}
} // namespace

int main()
{
  // Blocks {0,1}^2 and {2,3}^2 on top: cubes (1,1) and (2,2) touch along the edge x = y = 2.
  HexMesh pinched = SlabWith({ { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1, 1 }, { 2, 2 }, { 3, 2 }, { 2, 3 }, { 3, 3 } });
  HexMeshValidity validity;
  PCH_CHECK(checkHexMeshValidity(pinched, validity));
  std::cout << validity.Report << std::endl;
  PCH_CHECK(!validity.IsValid());
  PCH_CHECK(validity.NonManifoldBoundaryEdgeCount > 0);
  // Cube (2,2) on top (row 16 + 4) is the worst: it is the one removed.
  Eigen::VectorXd quality = Eigen::VectorXd::Ones(pinched.Cells.rows());
  quality[20] = 0.5;
  const Eigen::Matrix<int, 1, 8> worst = pinched.Cells.row(20);
  std::vector<int> removed;
  PCH_CHECK(RemovePinchingHexes(pinched, quality, &removed) == 1);
  PCH_CHECK(removed.size() == 1 && removed[0] == 20);
  PCH_CHECK(pinched.Cells.rows() == 23);
  for (Eigen::Index h = 0; h < pinched.Cells.rows(); ++h)
  {
    PCH_CHECK(pinched.Cells.row(h) != worst);
  }
  PCH_CHECK(checkHexMeshValidity(pinched, validity));
  std::cout << "after: " << validity.Report << std::endl;
  PCH_CHECK(validity.IsValid());

  // A valid mesh is left as it is.
  HexMesh grid = polycubehex_test::HexCubeGrid(3);
  const Hexes before = grid.Cells;
  PCH_CHECK(RemovePinchingHexes(grid, Eigen::VectorXd::Ones(grid.Cells.rows())) == 0);
  PCH_CHECK(grid.Cells == before);

  // Two lone cubes on top touching along an edge: removing either would orphan its top corners.
  HexMesh lone = SlabWith({ { 1, 1 }, { 2, 2 } });
  PCH_CHECK(RemovePinchingHexes(lone, Eigen::VectorXd::Ones(lone.Cells.rows())) == 0);
  PCH_CHECK(lone.Cells.rows() == 18);
  return 0;
}
