// SPDX-License-Identifier: BSD-3-Clause
// The hex scaled Jacobian of shared/DESIGN.md section 4, computed in the core so that extraction
// and smoothing can measure what they do without VTK. It follows Verdict's definition (the one
// vtkMeshQuality reports): the minimum over the 8 corners and the centre of the determinant of
// three edge (or principal axis) vectors divided by the product of their lengths.
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>

#include <array>

namespace polycubehex
{

/// For each corner c of a hex in VTK's node order, the three corners joined to it by an edge,
/// ordered so that the triple product of the edge vectors is positive on a positive hex.
inline constexpr int HexCornerNeighbours[8][3] = { { 1, 3, 4 },
  { 2, 0, 5 },
  { 3, 1, 6 },
  { 0, 2, 7 },
  { 7, 5, 0 },
  { 4, 6, 1 },
  { 5, 7, 2 },
  { 6, 4, 3 } };

/// The 12 edges of a hex as pairs of corners in VTK's node order: the bottom face's four, the
/// top face's four, then the four joining them.
inline constexpr int HexEdges[12][2] = { { 0, 1 },
  { 1, 2 },
  { 2, 3 },
  { 3, 0 },
  { 4, 5 },
  { 5, 6 },
  { 6, 7 },
  { 7, 4 },
  { 0, 4 },
  { 1, 5 },
  { 2, 6 },
  { 3, 7 } };

/// The nine values whose minimum is the scaled Jacobian: the normalised Jacobian determinant at
/// each corner (VTK's node order) and, last, at the centre.
std::array<double, 9> HexCornerScaledJacobians(const Eigen::Matrix<double, 8, 3>& corners);

/// One of those nine values: corner `which` (0 to 7, VTK's node order) or the centre (8). Moving
/// one hex vertex changes only five of them (its corner, its three edge neighbours and the
/// centre), so the smoothing recomputes just those.
double HexCornerScaledJacobian(const Eigen::Matrix<double, 8, 3>& corners, int which);

/// Scaled Jacobian of one hex given its 8 corners in VTK's node order. 1 for a box, <= 0 for a
/// hex inverted or flat at some corner; 0 when an edge has zero length.
double HexScaledJacobian(const Eigen::Matrix<double, 8, 3>& corners);

/// Scaled Jacobian of hex `h` of `mesh`.
double HexScaledJacobian(const HexMesh& mesh, int h);

/// Scaled Jacobian of every hex.
/// @return #H scaled Jacobians
Eigen::VectorXd ComputeHexScaledJacobians(const HexMesh& mesh);

/// The minimum, mean and inverted count of a set of scaled Jacobians.
struct HexQualitySummary
{
  double Min = 0.0;
  double Mean = 0.0;
  int Inverted = 0; ///< values <= 0
};

/// Summary of #H scaled Jacobians (all zero when there are none).
HexQualitySummary SummarizeHexQuality(const Eigen::VectorXd& quality);

/// Whether `quality` is better than `other`: fewer inverted hexes, then a minimum larger by more
/// than `minimumMargin`, then (minima within the margin of each other) a larger mean, then a
/// larger minimum. The margin keeps a gain of a thousandth in the worst hex from costing a
/// hundredth of the mean (torus l1: 0.768 / 0.949 against 0.767 / 0.957).
bool BetterHexQuality(const HexQualitySummary& quality,
  const HexQualitySummary& other,
  double minimumMargin = 0.0);

/// The mean over hexes of the diagonal 0-6 over sqrt(3): about one hex edge (0 without hexes).
double MeanHexEdgeLength(const HexMesh& mesh);

} // namespace polycubehex
