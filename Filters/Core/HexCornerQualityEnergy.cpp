// SPDX-License-Identifier: BSD-3-Clause
#include "HexCornerQualityEnergy.h"

#include "HexScaledJacobian.h"
#include "ThreadCount.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

namespace polycubehex
{
namespace
{
/// One column of a Jacobian as a signed sum of hex corners: a corner's edge is neighbour minus
/// corner, a principal axis at the centre is one face's four corners minus the opposite face's
/// (as HexScaledJacobian.cpp measures them).
struct JacobianColumn
{
  int Count = 0;
  std::array<int, 8> Corner{};
  std::array<double, 8> Weight{};
};
using JacobianColumns = std::array<std::array<JacobianColumn, 3>, 9>;

JacobianColumns MakeJacobianColumns()
{
  JacobianColumns columns{};
  auto add = [](JacobianColumn& column, int corner, double weight)
  {
    column.Corner[static_cast<size_t>(column.Count)] = corner;
    column.Weight[static_cast<size_t>(column.Count)] = weight;
    ++column.Count;
  };
  for (int corner = 0; corner < 8; ++corner)
  {
    for (int i = 0; i < 3; ++i)
    {
      add(columns[corner][i], HexCornerNeighbours[corner][i], 1.0);
      add(columns[corner][i], corner, -1.0);
    }
  }
  const int plus[3][4] = { { 1, 2, 5, 6 }, { 2, 3, 6, 7 }, { 4, 5, 6, 7 } };
  for (int i = 0; i < 3; ++i)
  {
    for (int corner = 0; corner < 8; ++corner)
    {
      const bool positive =
        std::find(std::begin(plus[i]), std::end(plus[i]), corner) != std::end(plus[i]);
      add(columns[8][i], corner, positive ? 1.0 : -1.0);
    }
  }
  return columns;
}

/// The energy of hex h and, when `gradient` is set, its gradient at the hex's eight corners.
double HexEnergy(const Points& x,
  const Hexes& cells,
  int h,
  double epsilon,
  Eigen::Matrix<double, 8, 3>* gradient)
{
  static const JacobianColumns columns = MakeJacobianColumns();
  std::array<Eigen::Vector3d, 8> corners;
  for (int k = 0; k < 8; ++k)
  {
    corners[static_cast<size_t>(k)] = x.row(cells(h, k)).transpose();
  }
  if (gradient)
  {
    gradient->setZero();
  }
  double energy = 0.0;
  for (const auto& jacobian : columns)
  {
    std::array<Eigen::Vector3d, 3> c;
    std::array<double, 3> length2;
    for (size_t i = 0; i < 3; ++i)
    {
      c[i].setZero();
      for (int j = 0; j < jacobian[i].Count; ++j)
      {
        c[i] += jacobian[i].Weight[static_cast<size_t>(j)] *
          corners[static_cast<size_t>(jacobian[i].Corner[static_cast<size_t>(j)])];
      }
      length2[i] = c[i].squaredNorm();
    }
    // An edge (nearly) of zero length next to the others has no direction to improve, and its
    // gradient would be all noise.
    const double longest = std::max({ length2[0], length2[1], length2[2] });
    const double shortest = std::min({ length2[0], length2[1], length2[2] });
    if (!(shortest > 1e-16 * longest) || !(shortest > 0.0))
    {
      continue;
    }
    const double lengths = std::sqrt(length2[0] * length2[1] * length2[2]);
    const std::array<Eigen::Vector3d, 3> cofactor = {
      c[1].cross(c[2]), c[2].cross(c[0]), c[0].cross(c[1])
    };
    const double s = c[0].dot(cofactor[0]) / lengths;
    const double root = std::sqrt(epsilon * epsilon + s * s);
    const double chi = 0.5 * (s + root);
    energy -= std::log(chi);
    if (!gradient)
    {
      continue;
    }
    // d(-log chi)/ds, then ds/dc_i = cofactor_i / lengths - s c_i / |c_i|^2.
    const double dEnergy = -0.5 * (1.0 + s / root) / chi;
    for (size_t i = 0; i < 3; ++i)
    {
      const Eigen::RowVector3d g =
        (dEnergy * (cofactor[i] / lengths - (s / length2[i]) * c[i])).transpose();
      for (int j = 0; j < jacobian[i].Count; ++j)
      {
        gradient->row(jacobian[i].Corner[static_cast<size_t>(j)]) +=
          jacobian[i].Weight[static_cast<size_t>(j)] * g;
      }
    }
  }
  return energy;
}
} // namespace

double HexCornerQualityEnergy(const Points& x,
  const Hexes& cells,
  const std::vector<int>& hexes,
  double epsilon,
  Points* gradient)
{
  // Per hex in parallel into its own slots, then summed and gathered in hex order, so that every
  // thread count gives the same bits.
  const int count = static_cast<int>(hexes.size());
  std::vector<double> energies(hexes.size());
  std::vector<Eigen::Matrix<double, 8, 3>> gradients(gradient ? hexes.size() : 0);
  ParallelChunks(count,
    256,
    [&](int begin, int end)
    {
      for (int i = begin; i < end; ++i)
      {
        energies[static_cast<size_t>(i)] = HexEnergy(x,
          cells,
          hexes[static_cast<size_t>(i)],
          epsilon,
          gradient ? &gradients[static_cast<size_t>(i)] : nullptr);
      }
    });
  double energy = 0.0;
  for (double e : energies)
  {
    energy += e;
  }
  if (gradient)
  {
    gradient->setZero(x.rows(), 3);
    for (size_t i = 0; i < hexes.size(); ++i)
    {
      for (int k = 0; k < 8; ++k)
      {
        gradient->row(cells(hexes[i], k)) += gradients[i].row(k);
      }
    }
  }
  return energy;
}

} // namespace polycubehex
