// SPDX-License-Identifier: BSD-3-Clause
// FollowAnchors (PolycubeHomotopy.h): squashing a tet cube to a twentieth of its width by
// moving one face's coordinates, a move that inverts tets when applied to the face alone. The
// homotopy must land every anchored coordinate exactly on its target with every tet positive,
// and stop where no fraction of the move keeps the tets above its volume floor (a target that
// turns the cube inside out).
#include "PolycubeHomotopy.h"
#include "TetGeometry.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <iostream>
#include <vector>

using namespace polycubehex;
using namespace polycubehex_test;

namespace
{
int NonPositiveTets(const TetMesh& mesh, const Eigen::VectorXd& x)
{
  Points current(mesh.Vertices.rows(), 3);
  for (Eigen::Index v = 0; v < current.rows(); ++v)
  {
    current.row(v) << x(3 * v), x(3 * v + 1), x(3 * v + 2);
  }
  int count = 0;
  for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
  {
    count += TetSignedVolume(current, mesh.Cells, static_cast<int>(t)) > 0.0 ? 0 : 1;
  }
  return count;
}

Eigen::VectorXd Flat(const Points& points)
{
  Eigen::VectorXd x(3 * points.rows());
  for (Eigen::Index v = 0; v < points.rows(); ++v)
  {
    x.segment<3>(3 * v) = points.row(v).transpose();
  }
  return x;
}

Triangles BoundaryOf(const TetMesh& mesh)
{
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, topology);
  return topology.BoundaryFaces;
}

/// ARAP to the cube and the inversion barrier: the energy the flattening's homotopy sees.
PolycubeEnergy BarrierEnergy(const TetMesh& cube)
{
  PolycubeEnergy energy(cube.Vertices, cube.Cells, BoundaryOf(cube));
  PolycubeEnergyWeights weights;
  weights.Barrier = 1.0;
  energy.SetWeights(weights);
  return energy;
}

/// The x coordinates of the cube's faces x = -1 (held) and x = 1 (moved to `movedTo`).
void SquashAnchors(const TetMesh& cube,
  double movedTo,
  std::vector<int>& index,
  std::vector<double>& target)
{
  for (Eigen::Index v = 0; v < cube.Vertices.rows(); ++v)
  {
    if (cube.Vertices(v, 0) == -1.0 || cube.Vertices(v, 0) == 1.0)
    {
      index.push_back(static_cast<int>(3 * v));
      target.push_back(cube.Vertices(v, 0) == 1.0 ? movedTo : -1.0);
    }
  }
}

void TestSquash()
{
  const TetMesh cube = CubeGrid(4);
  const PolycubeEnergy energy = BarrierEnergy(cube);
  std::vector<int> index;
  std::vector<double> target;
  SquashAnchors(cube, -0.9, index, target);

  // Moving the face alone inverts the tets next to it: the test needs the interior to follow.
  Eigen::VectorXd snapped = Flat(cube.Vertices);
  for (size_t i = 0; i < index.size(); ++i)
  {
    snapped(index[i]) = target[i];
  }
  PCH_CHECK(NonPositiveTets(cube, snapped) > 0);

  Eigen::VectorXd x = Flat(cube.Vertices);
  HomotopySettings settings;
  settings.MaxSteps = 40;
  HomotopyStats stats;
  const Status status = FollowAnchors(energy, index, target, settings, x, stats);
  PCH_CHECK(status.Ok());
  std::cout << "squash: " << stats.Steps << " steps, " << stats.Halvings
            << " halvings, smallest fraction " << stats.SmallestFraction << ", deviation "
            << stats.Deviation << std::endl;
  PCH_CHECK(stats.Deviation == 0.0);
  PCH_CHECK(NonPositiveTets(cube, x) == 0);
  PCH_CHECK(stats.Steps < settings.MaxSteps);
  int offTarget = 0;
  for (size_t i = 0; i < index.size(); ++i)
  {
    offTarget += x(index[i]) == target[i] ? 0 : 1;
  }
  PCH_CHECK(offTarget == 0);
  // The free coordinates followed: every vertex lies between the two planes.
  int outside = 0;
  for (Eigen::Index v = 0; v < cube.Vertices.rows(); ++v)
  {
    outside += x(3 * v) >= -1.0 && x(3 * v) <= -0.9 ? 0 : 1;
  }
  PCH_CHECK(outside == 0);
}

void TestInsideOut()
{
  // Moving the face x = 1 past the face x = -1 cannot keep the tets positive: the homotopy gets
  // close to the opposite face and stops there, every tet still positive.
  const TetMesh cube = CubeGrid(3);
  const PolycubeEnergy energy = BarrierEnergy(cube);
  std::vector<int> index;
  std::vector<double> target;
  SquashAnchors(cube, -1.5, index, target);
  Eigen::VectorXd x = Flat(cube.Vertices);
  HomotopySettings settings;
  HomotopyStats stats;
  PCH_CHECK(FollowAnchors(energy, index, target, settings, x, stats).Ok());
  std::cout << "inside out: " << stats.Steps << " steps, deviation " << stats.Deviation
            << std::endl;
  PCH_CHECK(NonPositiveTets(cube, x) == 0);
  // Not crushed either: no tet below the volume floor that later stages need.
  PCH_CHECK(energy.MinVolumeRatio(x.data()) > settings.MinVolumeRatio);
  PCH_CHECK(stats.Deviation > 0.5 - 1e-9);
  PCH_CHECK(stats.SmallestFraction < 1.0);
}
} // namespace

int main(int, char*[])
{
  TestSquash();
  TestInsideOut();
  return PCH_TEST_RESULT();
}
