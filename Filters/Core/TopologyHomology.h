// SPDX-License-Identifier: BSD-3-Clause
// First (co)homology of a tet mesh from its dual complex, independent of the boundary.
//
// The solid M is homotopy equivalent to its dual block complex D: a 0-cell per tet, a 1-cell per
// interior face, a 2-cell per interior edge (the ring of tets around it), a 3-cell per interior
// vertex. (Every simplex not on the boundary has its relative interior inside M, so its link is
// a sphere and its dual block a ball; M minus its boundary retracts onto the union of these
// blocks.) Hence H^1(M; Z) = integer cochains on the interior faces whose signed sum around
// every interior edge is 0 (cocycles), modulo differences of functions on tets.
//
// Computation: a spanning forest of the dual graph fixes the gauge (a cocycle is made 0 on tree
// faces). The other faces C are then collapsed greedily: an interior edge with exactly one face
// of C left forces that face's value to 0, so the face leaves C (this is the collapse of the
// 2-complex C through a free edge, and keeps M \ C simply connected). Around an interior edge
// with exactly two faces of C left the two values agree up to sign, so C splits into sheets with
// one unknown each; the interior edges with three or more faces of C (seams) give a small
// integer linear system on the sheet unknowns. Its kernel, solved exactly, is H^1(M; Z) and its
// dimension is beta_1(M).
#pragma once

#include "MeshTypes.h"
#include "Status.h"
#include "TopologyAdjacency.h"

#include <vector>

namespace polycubehex
{

struct CohomologyBasis
{
  /// beta_1 = dim H^1(M; Q) = dim H_1(M; Q).
  int Beta1 = 0;
  /// Beta1 integer cocycles forming a basis of H^1(M; Q), each one value per interior face
  /// (TetAdjacency::InteriorFaces), read across the face from its first to its second tet.
  /// Filled only when asked for.
  std::vector<std::vector<int>> Cocycles;
  /// Diagnostics of the reduction: faces left after the collapse, sheets, seam relations.
  int RemainingFaceCount = 0;
  int SheetCount = 0;
  int RelationCount = 0;
};

/// Computes beta_1 and, when `computeCocycles`, a basis of integer cocycles. Fails only when
/// the exact integer arithmetic would overflow or when a produced cocycle fails its own check.
Status ComputeCohomologyBasis(const Tets& cells,
  const TetAdjacency& adjacency,
  bool computeCocycles,
  CohomologyBasis& basis);

/// True when `cochain` (one value per interior face) sums to 0 around every interior edge;
/// otherwise false with the first offending edge id in `badEdge` (if given).
bool IsCocycle(const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<int>& cochain,
  int* badEdge = nullptr);

} // namespace polycubehex
