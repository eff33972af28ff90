// SPDX-License-Identifier: BSD-3-Clause
// The rotation that best aligns a surface with the coordinate axes in the l1 sense of
// Huang et al. 2014: argmin over rotations R of sum_f area_f ||R n_f||_1.
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>

namespace polycubehex
{

/// @param x      #V by 3 positions
/// @param faces  #F by 3 triangles
/// @return a rotation R (det +1); R x aligns the surface. Deterministic: a grid search over
///         Euler angles (7.5 degrees) on binned normals, then a pattern search on all faces.
Eigen::Matrix3d ComputeAxisAligningRotation(const Points& x, const Triangles& faces);

/// sum_f area_f ||R n_f||_1 / sum_f area_f: 1 for a surface whose faces are all axis-aligned.
double AreaWeightedL1Norm(const Points& x, const Triangles& faces, const Eigen::Matrix3d& R);

} // namespace polycubehex
