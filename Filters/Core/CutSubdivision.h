// SPDX-License-Identifier: BSD-3-Clause
// Local refinement for the handle cuts: when no candidate cut is proper, split the interior edges
// whose two endpoints lie on the boundary of M. Such an edge is what lets a cut surface pass
// through a boundary vertex without ending there (the cut then touches the boundary at a vertex
// inside it, CutSurface); in a handle one tet thick every vertex is on the boundary and every
// cut is made of such edges. The midpoint of such an edge is an interior vertex, so after the
// split a cut can go around the boundary vertex instead of through it.
#pragma once

#include "MeshTypes.h"
#include "TopologyAdjacency.h"

#include <array>
#include <vector>

namespace polycubehex
{

/// Interior edges of the mesh (on no boundary face) whose two endpoints lie on the boundary,
/// as vertex pairs, smaller id first, in edge-id order.
/// @param near  one flag per vertex: keep only edges with a flagged endpoint; empty keeps all
std::vector<std::array<int, 2>> BoundaryChordEdges(const TetAdjacency& adjacency,
  const std::vector<char>& near);

/// Splits `edges` at their midpoints (SplitTetEdges): the new vertices are appended after the
/// mesh's, every tet keeps its id for one of its halves, and the children are appended.
/// @param mesh          #V by 3 vertices, #T by 4 positive tets; on return #V' and #T'
/// @param originalCell  #T on input (the input tet each tet comes from), #T' on return
/// @param midpointParents  appended: per new vertex, the two vertices whose midpoint it is
/// @return the number of tets of `mesh` that were split
int SubdivideEdges(TetMesh& mesh,
  const std::vector<std::array<int, 2>>& edges,
  std::vector<int>& originalCell,
  std::vector<std::array<int, 2>>& midpointParents);

} // namespace polycubehex
