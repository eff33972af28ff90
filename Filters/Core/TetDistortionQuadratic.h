// SPDX-License-Identifier: BSD-3-Clause
// The distortion energy of a tet map, E(X) = sum_t w_t |grad X_t - J_t|_F^2 (grad X_t the
// Jacobian of tet t's linear map, J_t its target), written once as a quadratic form so that an
// evaluation is one sparse product instead of a pass over the tets. The integer rounding's
// nonlinear untangling evaluates it thousands of times per hex stage.
//
// The form is taken about start positions X0, E(X) = E0 + sum_a (2 G0_a + L U_a) . U_a with
// U = X - X0, L = sum_t w_t G_t G_t^T (G_t the tet's 4 by 3 shape gradients) and G0 the energy's
// half-gradient at X0. About the origin the two large terms x^T L x and 2 b^T x nearly cancel:
// for a map near its targets they keep none of the energy's digits (TestTetDistortionQuadratic),
// and an L-BFGS line search compares energies to 1e-12.
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <vector>

namespace polycubehex
{

class TetDistortionQuadratic
{
public:
  /// @param start      #V by 3 positions X0 about which the form is taken
  /// @param cells      #T by 4 tets (vertex indices into start)
  /// @param gradients  #T: rows i = the gradient of tet t's i-th barycentric coordinate
  /// @param targets    #T target Jacobians J_t
  /// @param weights    #T weights w_t
  TetDistortionQuadratic(const Points& start,
    const Tets& cells,
    const std::vector<Eigen::Matrix<double, 4, 3>>& gradients,
    const std::vector<Eigen::Matrix3d>& targets,
    const std::vector<double>& weights);

  /// E(X); with `gradient`, also dE/dX (#V by 3, overwritten). Uses buffers of its own, so one
  /// object must not be evaluated from two threads at once.
  double Evaluate(const Points& positions, Points* gradient = nullptr) const;

private:
  Eigen::SparseMatrix<double> L;
  Points X0;
  Points G0; ///< L X0 - sum_t w_t G_t J_t^T: half the gradient at X0
  double E0 = 0.0;
  mutable Points U;
  mutable Points LU;
};

} // namespace polycubehex
