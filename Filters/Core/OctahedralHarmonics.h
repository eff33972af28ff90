// SPDX-License-Identifier: BSD-3-Clause
// Frames as octahedral functions in degree-4 spherical harmonics (Huang et al. 2011; Ray, Sokolov
// and Levy 2016): a frame R (rows = axes) is represented by the 9 coefficients
// q(R) = sum_a Y(r_a) of the real, orthonormal degree-4 harmonics Y evaluated at its three axes.
// By the addition theorem q(R) is, up to one constant factor, the degree-4 part of
// sum_a (r_a . x)^4, so q is blind to the 24 cube symmetries, rotates with R, and has the same
// norm for every frame; smoothing q is smoothing frames without a matching.
#pragma once

#include <Eigen/Core>

namespace polycubehex
{

/// 9 coefficients of a degree-4 spherical-harmonic function, order m = -4..4.
using OctahedralVector = Eigen::Matrix<double, 9, 1>;

/// The real degree-4 harmonics, orthonormal on the unit sphere, at the point x (any length: they
/// are homogeneous quartic polynomials).
OctahedralVector EvaluateDegree4Harmonics(const Eigen::Vector3d& x);

/// q(R) = sum_a Y(r_a) for the rows r_a of R (R need not be orthonormal).
OctahedralVector FrameToOctahedral(const Eigen::Matrix3d& frame);

/// ||q(R)|| for any rotation R.
double OctahedralNorm();

/// The projection onto the octahedral variety: the rotation R maximising q(R) . q, found from an
/// eigen-decomposition of the quartic's Hessian followed by Newton steps on SO(3). Exact (to
/// rounding) when q is a positive multiple of some q(R). Returns the identity for q = 0.
/// @param q       any coefficient vector
/// @param fit     if given, receives q(R) . q / (||q(R)|| ||q||), 1 for an exact octahedral q
Eigen::Matrix3d OctahedralToFrame(const OctahedralVector& q, double* fit = nullptr);

/// The coefficients of all frames with one axis along a unit normal n form a circle
/// q = Center + cos(4 t) U + sin(4 t) V, t the twist about n; Center, U, V are orthogonal and
/// ||U|| = ||V||. The plane of the circle is the relaxed boundary constraint of Huang et al. 2011.
struct NormalAlignedCircle
{
  OctahedralVector Center;
  OctahedralVector U;
  OctahedralVector V;
};

/// The circle of the unit normal n.
NormalAlignedCircle ComputeNormalAlignedCircle(const Eigen::Vector3d& n);

} // namespace polycubehex
