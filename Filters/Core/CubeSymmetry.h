// SPDX-License-Identifier: BSD-3-Clause
// The chiral cubical symmetry group [Nieser et al. 2011]: the 24 rotations that map the unit
// cube onto itself, i.e. the signed permutation matrices with determinant +1. They are the
// transitions allowed between two frames (rows = axes, DESIGN.md section 2): Pi R_minus ~ R_plus.
#pragma once

#include <Eigen/Core>

namespace polycubehex
{

/// The size of the group.
constexpr int CubeRotationCount = 24;

/// A fixed, deterministic numbering of the group; index 0 is the identity.
/// @return the rotation with that index (index in [0, 24))
const Eigen::Matrix3i& CubeRotation(int index);

/// The same rotation as a double matrix.
Eigen::Matrix3d CubeRotationMatrix(int index);

/// The index of `pi`, or -1 when it is not a chiral cube rotation.
int CubeRotationIndex(const Eigen::Matrix3i& pi);

/// The index of the product Pi_a Pi_b (apply b first, then a).
int CubeRotationProduct(int a, int b);

/// The index of the inverse (= transpose) of Pi_a.
int CubeRotationInverse(int a);

/// The conjugacy class of a cube rotation, i.e. the kind of turn it makes.
enum class CubeRotationClass
{
  Identity = 0,
  QuarterTurn = 1,  ///< +-90 degrees about a face axis (a valence 3 or 5 singular edge)
  HalfTurnFace = 2, ///< 180 degrees about a face axis (valence 2 or 6)
  ThirdTurn = 3,    ///< +-120 degrees about a cube diagonal (improper)
  HalfTurnEdge = 4  ///< 180 degrees about an edge axis (improper)
};

/// The class of Pi_index.
CubeRotationClass ClassifyCubeRotation(int index);

/// argmax over the 24 rotations Pi of trace(Pi M).
/// @param m      any 3x3 matrix
/// @param trace  if given, receives the maximal trace
int BestCubeRotationOfProduct(const Eigen::Matrix3d& m, double* trace = nullptr);

/// The rotation Pi minimising ||Pi A - B||_F^2 for two frames A (from) and B (to): the best
/// re-expression of A in B's matching, i.e. argmax trace(Pi A B^T).
/// @param error  if given, receives the minimal ||Pi A - B||_F^2
int BestCubeRotation(const Eigen::Matrix3d& from,
  const Eigen::Matrix3d& to,
  double* error = nullptr);

} // namespace polycubehex
