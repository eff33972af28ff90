// SPDX-License-Identifier: BSD-3-Clause
// Carries coordinates of a tet mesh to prescribed values without inverting a tet: the last part
// of flattening the charts of a polycube onto their planes. Internal to ComputePolycube.
//
// The penalised flattening (a penalty on each chart coordinate's distance to its plane, weights
// growing to about 1e13) makes the Newton system stiff, and the inexact block-preconditioned CG
// returns poor directions there: fertility's charts stayed about 2e-3 of the diagonal off their
// planes. Here the anchored coordinates are not variables at all. Each step moves them by a
// fraction of their remaining distance, and the other coordinates follow by the Newton step of
// the energy (ARAP plus the barriers) with that move imposed (PolycubeNewtonSolver::Follow); the
// fraction halves until every tet stays positive and above a volume floor, every guarded chart
// face unfolded. A few Newton iterations with the anchors fixed then let the interior relax
// before the next step. Where a tet or a face blocks the move (a fold of the labels), the
// anchors of its vertices freeze; on fertility 90 froze about 2e-3 off, so the stiffness was not
// the whole story there, but 162 vertices off their planes became 57.
#pragma once

#include "PolycubeEnergy.h"
#include "PolycubeNewton.h"
#include "Status.h"

#include <Eigen/Core>

#include <vector>

namespace polycubehex
{

struct HomotopySettings
{
  int MaxSteps = 40;
  int RelaxIterations = 2; ///< Newton iterations with the anchors fixed after each step
  /// A step that can take less than this fraction of its move freezes the anchors of the
  /// vertices that block it (where the next larger fraction inverts a tet or folds a guarded
  /// face): they keep their values from then on, so that one fold does not hold back every
  /// other chart. 0: never freeze.
  double FreezeBelow = 1.0 / 16.0;
  /// Stop when every anchored coordinate that is not frozen is this close to its target (the
  /// energy's units: a fraction of the diagonal in ComputePolycube, 1000 times below the
  /// contract's flatness tolerance).
  double Tolerance = 1e-12;
  /// No step may leave a tet's volume ratio (deformed over rest volume) at or below this, or
  /// below the smallest ratio at the start when that is lower: a fold's tets would otherwise be
  /// crushed until hex extraction counts them as flat (1e-14 of the diagonal cubed). Anchors
  /// held back by it freeze like those held back by an inversion.
  double MinVolumeRatio = 1e-6;
  NewtonSettings::LinearSolverType LinearSolver = NewtonSettings::LinearSolverType::BlockPcg;
};

struct HomotopyStats
{
  int Steps = 0;
  int Halvings = 0;              ///< line-search halvings over all steps
  double SmallestFraction = 1.0; ///< the smallest fraction a step took
  int FrozenAnchors = 0;         ///< anchors frozen off their targets (FreezeBelow)
  double Deviation = 0.0;        ///< largest |x_i - target_i| at the end
};

/// Moves the coordinates x[anchorIndex[i]] towards anchorTarget[i], keeping x inside the
/// energy's feasible domain (x must start there). The energy should carry no anchor penalty.
Status FollowAnchors(const PolycubeEnergy& energy,
  const std::vector<int>& anchorIndex,
  const std::vector<double>& anchorTarget,
  const HomotopySettings& settings,
  Eigen::VectorXd& x,
  HomotopyStats& stats);

} // namespace polycubehex
