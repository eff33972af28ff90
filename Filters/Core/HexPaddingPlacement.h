// SPDX-License-Identifier: BSD-3-Clause
// Where the inner copies of a padding layer go in the input's space. The layer is built in the
// lattice (HexLatticePadding.h): each inner copy is its boundary vertex's lattice position moved a
// fraction of a hex inwards, mapped back through the tets. Those tets, along the boundary, are
// where the polycube map is most distorted, so the thin padding hexes come out skewed (rockerarm
// Uniform at 24k hexes: padding hexes' mean scaled Jacobian 0.81 against 0.90 for the others).
// A padding hex is best when its inner face is its boundary quad pushed along the surface normal;
// the hex inside it is best with the mapped position. So each inner copy takes, of a few points
// between the two, the one that maximises the smallest (then the mean) scaled Jacobian of its
// hexes. The mapped position is one of the candidates, so no hex's minimum can go down.
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
};

struct HexPaddingPlacementResult
{
  int MovedCount = 0; ///< inner copies that left their mapped position
  double MinBefore = 0.0; ///< smallest scaled Jacobian of the hexes at inner copies, before
  double MinAfter = 0.0;
  double MeanBefore = 0.0; ///< mean scaled Jacobian of the padding hexes, before
  double MeanAfter = 0.0;
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
