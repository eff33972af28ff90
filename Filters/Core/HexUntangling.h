// SPDX-License-Identifier: BSD-3-Clause
// Global untangling and shape optimisation of an extracted hex mesh (not in the paper, whose
// meshes are the raw extraction). All free vertex positions minimise one energy over the nine
// Jacobians of every hex (its eight corners and its centre, as the scaled Jacobian of
// HexScaledJacobian.h measures them), each J the corner's three edge vectors over the hex's mean
// edge length (the centre's axes over four of them):
//
//   E = sum (1 - VolumeWeight) (|J|_F^2 / 3)^(3/2) / chi(det J) + VolumeWeight (det^2 J + 1) / (2
//   chi(det J)), chi(D) = (D + sqrt(eps^2 + D^2)) / 2,
//
// which is finite on inverted corners and becomes a barrier as eps goes to 0 (Garanzha,
// Kaporin, Kudryavtseva, Protais, Ray, Sokolov: "Foldover-free maps in 50 lines of code", 2021;
// their shape term |J|^2 / chi^(2/3) to the power 3/2, still polyconvex, steeper on the worst
// corners and without a cube root). Rounds of L-BFGS alternate with that paper's update of eps
// from the smallest determinant. During a round a boundary vertex moves in its chart's tangent
// plane or along its feature curve, and it is projected back onto the input surface after it
// (HexSurfaceProjection.h); corners of three or more charts stay fixed. Corner vertices of hexes
// still below ReleaseBelow after a round are released onto the surface (their charts force a
// flat or inverted corner); when hexes are still inverted after the last main round, the curve
// vertices of those hexes are released too and a few more main rounds run (ReleaseCurvesBelow);
// a few last rounds move the interior only. The result is kept only when it is no worse than the
// input: fewer inverted hexes, or as many and at least its minimum scaled Jacobian (else the
// best round that is, else the input).
//
// Every thread count gives the same bits: the hexes' energies and gradients are computed in
// parallel chunks into per-hex slots, then summed in hex order and gathered per vertex in a
// fixed order.
#pragma once

#include "HexSurfaceProjection.h"
#include "MeshTypes.h"
#include "Status.h"

#include <functional>
#include <memory>
#include <vector>

namespace polycubehex
{

/// Settings of untangleHexMesh.
struct HexUntanglingParameters
{
  /// Rounds at most, each one L-BFGS solve for one eps followed by the projection of the
  /// boundary vertices (default 12, >= 0; 0 turns the step off).
  int MaxRounds = 12;
  /// Rounds at most when no hex of the input is inverted (default 4): then only the quality
  /// is at stake, and the local smoothing after the untangling does much of it for less.
  int MaxRoundsValid = 4;
  /// Rounds after those, at most, with the boundary vertices held where the last projection
  /// put them (default 2, >= 0), so that the interior settles on the final boundary.
  int FinalRounds = 2;
  /// L-BFGS iterations per round at most (default 20, >= 1). Short rounds keep the boundary
  /// vertices' slides in their tangent planes short, so that the projection after the round
  /// changes little.
  int IterationsPerRound = 20;
  /// Share of the volume term, in [0, 1) (default 0.1): the shape term alone is blind to size.
  double VolumeWeight = 0.1;
  /// The rounds stop once no Jacobian is inverted and a round lowers the energy by less than
  /// this fraction (default 1e-3).
  double Tolerance = 1e-3;
  /// A boundary vertex on a polycube edge or corner moves on the surface across its charts
  /// where the input's normals about it vary by at most this (degrees, default 20; 0 holds
  /// every such vertex on its curve or in place; HexSurfaceProjection).
  double SoftFeatureAngle = DefaultSoftFeatureAngle;
  /// After each round, the corner vertices (three or more charts) of every hex whose scaled
  /// Jacobian is below this are released onto the surface (HexSurfaceProjection::Release;
  /// default 0.3, a value <= -1 releases none): where the charts meet in a way that forces a
  /// flat or inverted hex corner, the corner gives way. Curve vertices are released only where
  /// the surface is smooth (SoftFeatureAngle).
  double ReleaseBelow = 0.3;
  /// When hexes are still inverted after the last main round, the curve vertices of every hex
  /// whose scaled Jacobian is below this are released onto the surface too, and CurveRounds
  /// more main rounds run (default 0: those of the inverted hexes; a value <= -1 releases
  /// none). Only then: a curve vertex released from a crease lets the padding layer pull away
  /// from it (bunny's base, 3x the Hausdorff distance), and releasing them from the first
  /// round took rockerarm closed form's Hausdorff distance from 8.4 to 12.4.
  double ReleaseCurvesBelow = 0.0;
  /// Main rounds after that release (default 4, >= 0; 0 turns the release off).
  int CurveRounds = 4;
  /// When hexes stay inverted, the main rounds end early once this many pass without a new
  /// low in the count of inverted hexes (the curve release and its rounds then follow once,
  /// then the final rounds); 0 (the default) runs them all. Where the untangling stops changes
  /// what the smoothing reaches, either way (HexExtractionParameters::UntanglingPaths).
  int StallRounds = 0;
  /// With an onStall callback (untangleHexMesh), the first main round at which the count of
  /// inverted hexes has set no new low for this many rounds forks the untangling (default 2,
  /// 0 never): the callback receives a copy of the rounds there, which resumeUntangling
  /// finishes as a run with StallRounds = ForkStallRounds would, while this run goes on. The
  /// two paths share their rounds up to the fork, so the second costs only its own.
  int ForkStallRounds = 2;
};

/// What the step did.
struct HexUntanglingResult
{
  double MinBefore = 0.0;  ///< scaled Jacobian, minimum over hexes
  double MeanBefore = 0.0; ///< scaled Jacobian, mean over hexes
  int InvertedBefore = 0;  ///< hexes with scaled Jacobian <= 0
  double MinAfter = 0.0;
  double MeanAfter = 0.0;
  int InvertedAfter = 0;
  int Rounds = 0;           ///< rounds run
  int Iterations = 0;       ///< L-BFGS iterations over all rounds
  int ReleasedVertices = 0; ///< curve and corner vertices released onto the surface in all
  /// False when the optimised positions were worse than the input (smaller minimum scaled
  /// Jacobian or more inverted hexes) and the input's were kept.
  bool Kept = false;
};

/// A second path of the untangling, split off where the inverted count stalled
/// (HexUntanglingParameters::ForkStallRounds); resumeUntangling runs it. Movable, not copyable.
class UntanglingFork
{
public:
  UntanglingFork();
  ~UntanglingFork();
  UntanglingFork(UntanglingFork&&) noexcept;
  UntanglingFork& operator=(UntanglingFork&&) noexcept;
  /// The path's own projection, with the releases of its rounds (for the smoothing after it);
  /// null for an empty fork.
  HexSurfaceProjection* Projection() const;

  struct Data;
  std::unique_ptr<Data> Impl;
};

/// Untangles and optimises `mesh` in place.
/// @param mesh          #V by 3 positions, #H by 8 hexes in VTK order
/// @param vertexCharts  #V: sorted charts each vertex lies on (empty for interior vertices)
/// @param surface       the input's boundary triangles, each with the chart it belongs to
/// @return Failure when the sizes disagree or the caller aborted (the mesh is then unchanged).
Status untangleHexMesh(HexMesh& mesh,
  const std::vector<std::vector<int>>& vertexCharts,
  const HexSmoothingSurface& surface,
  const HexUntanglingParameters& params,
  HexUntanglingResult& result,
  const Progress& progress = {});

/// The same with the boundary vertices' kinds and projections given (params.SoftFeatureAngle
/// is then unused); the vertices the untangling releases stay released in `projection`, so
/// that a smoothing after it (smoothHexMesh) moves them the same way. When `onStall` is set, it
/// is called once, on this thread, with the fork of ForkStallRounds (if the rounds get there);
/// it may hand the fork to another thread, as the fork shares nothing mutable with this run.
Status untangleHexMesh(HexMesh& mesh,
  HexSurfaceProjection& projection,
  const HexUntanglingParameters& params,
  HexUntanglingResult& result,
  const Progress& progress = {},
  const std::function<void(UntanglingFork&&)>& onStall = {});

/// Runs the rest of a fork's rounds: `mesh` receives its hexes and the kept positions, `result`
/// counts the rounds and iterations of the whole path, the shared ones too.
Status resumeUntangling(UntanglingFork& fork,
  HexMesh& mesh,
  HexUntanglingResult& result,
  const Progress& progress = {});

} // namespace polycubehex
