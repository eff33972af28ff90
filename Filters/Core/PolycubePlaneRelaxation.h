// SPDX-License-Identifier: BSD-3-Clause
// Moves the chart planes of a flat polycube to given values (the integers chosen by the rounding
// of §4.3) without ever inverting a tet. The planes are variables shared by every coordinate on
// them (VariableReduction::ShareCoordinates), the free coordinates minimise ARAP towards the
// input shape plus the inversion barrier of PolycubeEnergy, and a penalty pulls each plane to its
// target with a weight that grows tenfold per round; the damped Newton line search keeps every
// tet positive along the way. At the end the planes are set to their targets exactly and the
// free coordinates relaxed once more with the planes fixed.
//
// Why not a linear solve: the deformation leaves slivers (volume ratios near 1e-6 next to
// sharp polycube edges), and moving a plane by 0.3 lattice units through a linear map flips
// them; the barrier instead lets the interior give way, and ARAP fattens the slivers on the way.
#pragma once

#include "IntegerRounding.h"
#include "MeshTypes.h"
#include "Status.h"

#include <Eigen/Core>

namespace polycubehex
{

struct PlaneRelaxationParameters
{
  /// Penalty rounds (weight x10 each from InitialWeight) before the planes are fixed.
  int Rounds = 10;
  double InitialWeight = 1.0;
  /// Newton iterations per round and for the final solve with the planes fixed.
  int IterationsPerRound = 4;
  /// Stop the rounds when every plane is this close to its target (lattice units).
  double Tolerance = 1e-7;
  /// Volume ratio (against the input tet scaled to the polycube's volume) below which the
  /// barrier acts.
  double BarrierThreshold = 0.1;
};

struct PlaneRelaxationResult
{
  double MinVolumeRatio = 0.0;   ///< smallest tet volume over its reference volume, at the end
  double MaxPlaneDeviation = 0.0; ///< before the final snap (lattice units)
  int Iterations = 0;
  int Rounds = 0;
  /// True when the planes moved as shared variables (the reference's charts were flat enough);
  /// false when every plane coordinate was pulled on its own.
  bool SharedPlanes = false;
};

/// @param rest       #V by 3 input positions (any scale), positive tets
/// @param reference  #V by 3 polycube positions with flat charts, positive tets
/// @param cells      #T by 4 tets
/// @param charts     from ComputeChartPlanes
/// @param targets    #P target plane values
/// @param positions  #V by 3 output: every chart exactly on its target plane
/// @return Failure when the reference has a non-positive tet or when snapping to the targets
///         would invert a tet (the penalty could not bring the planes close enough).
Status RelaxPolycubeToPlanes(const Points& rest,
  const Points& reference,
  const Tets& cells,
  const ChartPlanes& charts,
  const Eigen::VectorXd& targets,
  const PlaneRelaxationParameters& params,
  Points& positions,
  PlaneRelaxationResult& result,
  const Progress& progress = {});

} // namespace polycubehex
