// SPDX-License-Identifier: BSD-3-Clause
// Where the inner copies of a padding layer go in the input's space. The layer is built in the
// lattice (HexLatticePadding.h): each inner copy is its boundary vertex's lattice position moved a
// fraction of a hex inwards, mapped back through the tets. Those tets, along the boundary, are
// where the polycube map is most distorted, so the thin padding hexes come out skewed (rockerarm
// Uniform at 24k hexes: padding hexes' mean scaled Jacobian 0.81 against 0.90 for the others).
// A padding hex is best when its inner face is its boundary quad pushed along the surface normal;
// the hex inside it is best with the mapped position. So each inner copy takes, of a few points
// between the two, the one that maximises the smallest (then the mean) scaled Jacobian of its
// hexes; a copy whose hexes are still poor then walks in space to where they are best (near a
// polycube corner on a nearly flat surface, the hexes inside need it deeper, or off the normal).
// The mapped position is the start, and only strictly better places are taken, so no hex's
// minimum can go down.
// Not in the paper, which gives no construction for its padding layer.
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <vector>

namespace polycubehex
{

struct HexPaddingPlacementParameters
{
  /// Length of the push along the normal, in mean boundary edges at the vertex (default 1/3,
  /// the padding's default thickness in the lattice).
  double Thickness = 1.0 / 3.0;
  /// Candidate points: (1 - b) mapped + b pushed, for each b (default 0, 1/4, 1/2, 3/4, 1).
  std::vector<double> Blends = { 0.0, 0.25, 0.5, 0.75, 1.0 };
  /// Gauss-Seidel sweeps over the inner copies (default 3).
  int Sweeps = 3;
  /// Then copies whose hexes' smallest scaled Jacobian is below SearchBelow walk along the axes
  /// to better places, the minimum counting up to SearchBelow and the mean beyond: SearchSweeps
  /// sweeps (default 3; 0 turns the walk off), steps from SearchStep mean boundary edges
  /// (default 1/4), halved SearchLevels times (default 5). SearchBelow 0.1 by measurement, raw
  /// extraction: kitten closed form min -0.327 -> -0.033 (inverted hexes 9 -> 5), rockerarm
  /// -0.595 -> -0.182 (22 -> 14), fertility l1 -0.307 -> -0.114 (35 -> 10), means within 0.001;
  /// at 0.3 or 0.5 the walk gives up the mean for the minimum (kitten 0.897 -> 0.891, 0.886).
  int SearchSweeps = 3;
  double SearchBelow = 0.1;
  double SearchStep = 0.25;
  int SearchLevels = 5;
  /// Last, all inner copies move together to minimise HexCornerQualityEnergy over their hexes
  /// (L-BFGS, at most OptimizationIterations iterations, default 200; 0 turns it off; the
  /// energy's eps OptimizationEpsilon, default 0.05), and a copy whose hexes end with a smaller
  /// minimum than before goes back, until none does. One copy at a time cannot reach what they
  /// reach together: at a polycube edge on a smooth part of the surface the hex inside needs the
  /// copies of the whole edge deeper at once. By measurement, raw extraction (mean scaled
  /// Jacobian without -> with; minima unchanged): kitten closed form at 11,941 hexes 0.8985 ->
  /// 0.9100 (the hexes inside the edges 0.44 -> 0.72), fertility l1 at 17,910 0.8449 -> 0.8672,
  /// fertility closed form 0.8798 -> 0.8970, rockerarm l1 0.8967 -> 0.9050.
  int OptimizationIterations = 200;
  double OptimizationEpsilon = 0.05;
};

struct HexPaddingPlacementResult
{
  int MovedCount = 0;     ///< inner copies that left their mapped position
  double MinBefore = 0.0; ///< smallest scaled Jacobian of the hexes at inner copies, before
  double MinAfter = 0.0;
  double MeanBefore = 0.0; ///< mean scaled Jacobian of the padding hexes, before
  double MeanAfter = 0.0;
  int OptimizedCount = 0;         ///< copies the joint optimisation moved and kept there
  int OptimizationIterations = 0; ///< its L-BFGS iterations
};

/// Moves the inner copies of the padding layer of `mesh` (its last `paddingHexCount` hexes, each
/// with its boundary quad as face 0-1-2-3 and the inner copies as 4-7, as addPaddingLayer makes
/// them).
/// @return Failure when paddingHexCount is out of range or a padding hex is malformed.
Status placePaddingCopies(HexMesh& mesh,
  int paddingHexCount,
  const HexPaddingPlacementParameters& params,
  HexPaddingPlacementResult& result);

} // namespace polycubehex
