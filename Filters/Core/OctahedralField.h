// SPDX-License-Identifier: BSD-3-Clause
// The initial frame field of Fang et al. 2016, §3.2: a smooth, boundary-aligned octahedral field
// per tet after Huang et al. 2011, as one sparse linear least-squares problem in degree-4
// spherical harmonics followed by a projection of each tet's coefficients onto the frames.
// Internal to ComputeFrameField (FrameField.h).
#pragma once

#include "MeshTypes.h"
#include "Status.h"
#include "TetGeometry.h"

#include <Eigen/Core>

#include <vector>

namespace polycubehex
{

struct OctahedralFieldParameters
{
  /// Weight of the boundary alignment against smoothness (Fang et al. §5.2 compare 100 and 1000).
  /// Both terms are normalised: smoothness by the volume (lengths in units of the bounding-box
  /// diagonal), alignment by the boundary area, so the weight is dimensionless. A lower weight
  /// gives a straighter field whose singular lines hug the boundary; a higher one follows the
  /// boundary more tightly and may leave singular lines deep inside.
  double BoundaryAlignmentWeight = 30.0; // FrameFieldParameters documents the measurements
  /// Relative residual of the conjugate-gradient solve (the field is projected per tet
  /// afterwards, so a coarse solve suffices).
  double SolverTolerance = 1e-6;
  /// Iteration cap of the conjugate-gradient solve.
  int MaxSolverIterations = 500;
};

/// Minimises
///   sum_{interior faces ij} (V_i + V_j) / d_ij^2 ||q_i - q_j||^2 * D^2 / V
///   + w sum_{boundary faces f of tet t} A_f / A ||q_t - Pi_f(q_t)||^2
/// over the 9 harmonic coefficients q_t of every tet, where Pi_f projects onto the plane of the
/// circle of frames aligned with the face normal (OctahedralHarmonics.h), D is the bounding-box
/// diagonal, V the volume and A the boundary area; then projects each q_t onto a rotation.
/// @param mesh      #V by 3 vertices, #T by 4 positively oriented tets
/// @param topology  ComputeTetTopology(mesh)
/// @param frames    output: #T rotations, rows = axes
/// @param fits      if given, receives #T values of q(R_t) . q_t / (|q(R_t)| |q_t|) (1 = exactly
///                  octahedral; low near singularities)
Status ComputeOctahedralField(const TetMesh& mesh,
  const TetTopology& topology,
  const OctahedralFieldParameters& parameters,
  std::vector<Eigen::Matrix3d>& frames,
  std::vector<double>* fits = nullptr,
  const Progress& progress = {});

} // namespace polycubehex
