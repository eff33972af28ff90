// SPDX-License-Identifier: BSD-3-Clause
#include "TetDistortionQuadratic.h"

namespace polycubehex
{

TetDistortionQuadratic::TetDistortionQuadratic(const Points& start,
  const Tets& cells,
  const std::vector<Eigen::Matrix<double, 4, 3>>& gradients,
  const std::vector<Eigen::Matrix3d>& targets,
  const std::vector<double>& weights)
  : L(start.rows(), start.rows())
  , X0(start)
  , U(start.rows(), 3)
  , LU(start.rows(), 3)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(16 * static_cast<size_t>(cells.rows()));
  Points linear = Points::Zero(start.rows(), 3);
  for (int t = 0; t < static_cast<int>(cells.rows()); ++t)
  {
    const Eigen::Matrix<double, 4, 3>& g = gradients[static_cast<size_t>(t)];
    const Eigen::Matrix3d& target = targets[static_cast<size_t>(t)];
    const double w = weights[static_cast<size_t>(t)];
    // |sum_i x_i g_i^T - J|^2 = sum_ij (g_i . g_j) x_i . x_j - 2 sum_i x_i . (J g_i) + |J|^2.
    const Eigen::Matrix4d gram = w * g * g.transpose();
    Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        entries.emplace_back(cells(t, i), cells(t, j), gram(i, j));
      }
      linear.row(cells(t, i)) += w * (target * g.row(i).transpose()).transpose();
      jacobian += start.row(cells(t, i)).transpose() * g.row(i);
    }
    // E0 term by term, as accurate as the direct sum.
    this->E0 += w * (jacobian - target).squaredNorm();
  }
  this->L.setFromTriplets(entries.begin(), entries.end());
  this->G0 = this->L * start - linear;
}

double TetDistortionQuadratic::Evaluate(const Points& positions, Points* gradient) const
{
  this->U = positions - this->X0;
  this->LU.noalias() = this->L * this->U;
  if (gradient)
  {
    *gradient = 2.0 * (this->G0 + this->LU);
  }
  return this->E0 + (this->U.cwiseProduct(2.0 * this->G0 + this->LU)).sum();
}

} // namespace polycubehex
