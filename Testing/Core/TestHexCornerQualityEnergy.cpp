// SPDX-License-Identifier: BSD-3-Clause
// HexCornerQualityEnergy (HexCornerQualityEnergy.h): a cube and a box of any proportions have the
// same, smallest energy (nine Jacobians at s = 1), the energy does not depend on the hex's size,
// a sheared hex costs more and an inverted one more still, its gradient matches finite
// differences, a hex with a zero-length edge contributes nothing where that edge is, and a
// gradient step lowers the energy and raises the scaled Jacobian.
#include "HexCornerQualityEnergy.h"
#include "HexScaledJacobian.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <cmath>
#include <iostream>
#include <random>

using namespace polycubehex;

int main()
{
  constexpr double eps = 0.05;
  const double atOne = -std::log(0.5 * (1.0 + std::sqrt(1.0 + eps * eps)));
  const HexMesh cube = polycubehex_test::HexCubeGrid(1);
  const std::vector<int> one = { 0 };
  PCH_CHECK_NEAR(HexCornerQualityEnergy(cube.Vertices, cube.Cells, one, eps), 9.0 * atOne, 1e-12);

  // Blind to size and to the proportions of a box.
  {
    Points box = cube.Vertices;
    box.col(0) *= 3.0;
    box.col(2) /= 3.0;
    PCH_CHECK_NEAR(HexCornerQualityEnergy(box, cube.Cells, one, eps), 9.0 * atOne, 1e-12);
    const Points big = 7.0 * cube.Vertices;
    PCH_CHECK_NEAR(HexCornerQualityEnergy(big, cube.Cells, one, eps), 9.0 * atOne, 1e-12);
  }

  // A sheared hex costs more, an inverted one more still.
  Points sheared = cube.Vertices;
  for (int v = 0; v < sheared.rows(); ++v)
  {
    sheared(v, 0) += 0.6 * sheared(v, 2);
  }
  Points inverted = cube.Vertices;
  inverted.row(6) = Eigen::RowVector3d(0.2, 0.2, 0.2); // the top corner pushed through
  const double eCube = HexCornerQualityEnergy(cube.Vertices, cube.Cells, one, eps);
  const double eSheared = HexCornerQualityEnergy(sheared, cube.Cells, one, eps);
  const double eInverted = HexCornerQualityEnergy(inverted, cube.Cells, one, eps);
  std::cout << "energy: cube " << eCube << ", sheared " << eSheared << ", inverted " << eInverted
            << std::endl;
  PCH_CHECK(eSheared > eCube + 0.1);
  PCH_CHECK(eInverted > eSheared);
  PCH_CHECK(std::isfinite(eInverted));

  // The gradient against central differences, on a jittered 2x2x2 grid (shared vertices).
  {
    HexMesh grid = polycubehex_test::HexCubeGrid(2);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> noise(-0.2, 0.2);
    for (int v = 0; v < grid.Vertices.rows(); ++v)
    {
      grid.Vertices.row(v) += Eigen::RowVector3d(noise(random), noise(random), noise(random));
    }
    std::vector<int> all(static_cast<size_t>(grid.Cells.rows()));
    for (size_t h = 0; h < all.size(); ++h)
    {
      all[h] = static_cast<int>(h);
    }
    Points gradient;
    const double e0 = HexCornerQualityEnergy(grid.Vertices, grid.Cells, all, eps, &gradient);
    PCH_CHECK(gradient.rows() == grid.Vertices.rows());
    double worst = 0.0;
    const double h = 1e-6;
    for (int v = 0; v < grid.Vertices.rows(); ++v)
    {
      for (int a = 0; a < 3; ++a)
      {
        Points plus = grid.Vertices;
        Points minus = grid.Vertices;
        plus(v, a) += h;
        minus(v, a) -= h;
        const double numeric = (HexCornerQualityEnergy(plus, grid.Cells, all, eps) -
                                 HexCornerQualityEnergy(minus, grid.Cells, all, eps)) /
          (2.0 * h);
        worst = std::max(worst, std::abs(numeric - gradient(v, a)));
      }
    }
    std::cout << "jittered grid: energy " << e0 << ", largest gradient error " << worst
              << std::endl;
    PCH_CHECK(worst < 1e-5);

    // A small step against the gradient lowers the energy and raises the mean scaled Jacobian.
    HexMesh stepped = grid;
    stepped.Vertices -= 1e-3 * gradient;
    PCH_CHECK(HexCornerQualityEnergy(stepped.Vertices, grid.Cells, all, eps) < e0);
    PCH_CHECK(ComputeHexScaledJacobians(stepped).mean() > ComputeHexScaledJacobians(grid).mean());
  }

  // A zero-length edge: the Jacobians that use it are left out, the others still count, and
  // nothing is infinite.
  {
    Points collapsed = cube.Vertices;
    collapsed.row(1) = collapsed.row(0);
    Points gradient;
    const double e = HexCornerQualityEnergy(collapsed, cube.Cells, one, eps, &gradient);
    PCH_CHECK(std::isfinite(e));
    PCH_CHECK(gradient.allFinite());
    PCH_CHECK(e != 0.0);
  }

  // No hexes: zero, and a zero gradient of the right size.
  {
    Points gradient;
    PCH_CHECK(HexCornerQualityEnergy(cube.Vertices, cube.Cells, {}, eps, &gradient) == 0.0);
    PCH_CHECK(gradient.rows() == cube.Vertices.rows() && gradient.isZero());
  }
  return polycubehex_test::FailureCount();
}
