// SPDX-License-Identifier: BSD-3-Clause
// The foldover-free distortion energy of one 3 by 3 Jacobian (Garanzha, Kaporin, Kudryavtseva,
// Protais, Ray, Sokolov: "Foldover-free maps in 50 lines of code", 2021), shared by the hex
// untangling (HexUntangling.h) and the smoothing of the rounded polycube map
// (PolycubeMapSmoothing.h):
//
//   f(J) = (1 - VolumeWeight) (|J|_F^2 / 3)^(3/2) / chi(det J) + VolumeWeight (det^2 J + 1) / (2
//   chi(det J)), chi(D) = (D + sqrt(eps^2 + D^2)) / 2.
//
// The shape term is 1 exactly for a rotation times a scale and grows with the distortion; the
// volume term is smallest at det J = 1. chi keeps f finite on inverted Jacobians, so a map can
// be untangled, and becomes a barrier as eps goes to 0.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace polycubehex
{

// Both functions are forced inline: GCC left JacobianEnergy out of line, and it is a fifth of
// the hex stage's time (nine calls per hex per untangling evaluation); inlined, the untangling
// of fertility's closed form takes 2.0-2.1 s instead of 2.45-2.5 s with bit-identical results.

/// chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2, written without cancellation for D < 0, and its
/// derivative chi / sqrt(eps^2 + D^2).
[[gnu::always_inline]] inline void Chi(double d, double eps, double& chi, double& derivative)
{
  const double root = std::sqrt(eps * eps + d * d);
  chi = d >= 0.0 ? 0.5 * (d + root) : 0.5 * eps * eps / (root - d);
  derivative = chi / root;
}

/// The energy of one Jacobian J = [a b c] (columns) and its derivative with respect to the
/// columns; `det` receives det J.
[[gnu::always_inline]] inline double JacobianEnergy(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c,
  double eps,
  double volumeWeight,
  Eigen::Vector3d& ga,
  Eigen::Vector3d& gb,
  Eigen::Vector3d& gc,
  double& det)
{
  const Eigen::Vector3d bc = b.cross(c);
  const Eigen::Vector3d ca = c.cross(a);
  const Eigen::Vector3d ab = a.cross(b);
  det = a.dot(bc);
  double chi = 0.0;
  double chiPrime = 0.0;
  Chi(det, eps, chi, chiPrime);
  const double q = std::sqrt((a.squaredNorm() + b.squaredNorm() + c.squaredNorm()) / 3.0);
  const double inverseChi = 1.0 / chi;
  const double shape = q * q * q * inverseChi;          // >= 1
  const double volume = (det * det + 1.0) * inverseChi; // >= 2
  const double ws = 1.0 - volumeWeight;
  const double wv = 0.5 * volumeWeight;
  // dE/dJ = ws (q J / chi - shape chi' / chi cof J) + wv (2 det - volume chi') / chi cof J,
  // where the columns of cof J (d det / d J) are b x c, c x a, a x b.
  const double alpha = ws * q * inverseChi;
  const double beta = (-ws * shape * chiPrime + wv * (2.0 * det - volume * chiPrime)) * inverseChi;
  ga = alpha * a + beta * bc;
  gb = alpha * b + beta * ca;
  gc = alpha * c + beta * ab;
  return ws * shape + wv * volume;
}

} // namespace polycubehex
