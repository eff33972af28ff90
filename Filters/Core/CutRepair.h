// SPDX-License-Identifier: BSD-3-Clause
// Local repair of the surface carried by an integer cocycle so that it becomes a properly
// embedded 2-manifold near every vertex, without changing the cohomology class.
//
// Around a vertex v the cocycle is the difference of a local level function on the tets of v's
// star (the star is simply connected). The surface is proper at v when the star holds at most two
// level sets, each connected through the faces at v, with levels one apart, and, when v is on the
// boundary, both touching the boundary at v (then the cut faces at v form a single fan ending on
// the boundary; a level set not touching it means the cut touches the boundary at an isolated
// vertex, and more level sets mean several sheets through v). A repair move shifts one level set
// of a bad star to the level of a neighbouring one: this adds the coboundary of the level set's
// indicator, so the class is kept, and moves the surface off v onto the far faces of those tets.
// Among all moves at a bad vertex the one adding the least area is taken; the vertices of the
// moved tets are checked again, until every vertex is proper or the move budget is spent.
#pragma once

#include "MeshTypes.h"
#include "TopologyAdjacency.h"

#include <vector>

namespace polycubehex
{

/// True when the surface of `cocycle` is proper at vertex v (as above).
bool IsCocycleProperAtVertex(const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<int>& cocycle,
  int vertex);

/// Repairs `cocycle` in place. Returns true when every vertex ends proper.
/// @param maxMoves  budget of moves; `moves` (optional) receives the number made
bool RepairCocycleSurface(const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<double>& faceArea,
  std::vector<int>& cocycle,
  int maxMoves,
  int* moves = nullptr);

} // namespace polycubehex
