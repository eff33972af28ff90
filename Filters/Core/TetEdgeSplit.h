// SPDX-License-Identifier: BSD-3-Clause
// Splits edges of a tet mesh at their midpoints, every tet around an edge into two.
#pragma once

#include "MeshTypes.h"

#include <array>
#include <vector>

namespace polycubehex
{

/// Splits each edge of `edges`, in order, by a new vertex at its midpoint: every tet around the
/// edge is replaced by its two halves (the half that keeps the edge's first vertex keeps the tet's
/// index, the other is appended). Orientation is preserved: a positive tet has positive halves.
///
/// @param vertexCount       #V before the split
/// @param cells             #T by 4 tets; on return #T' by 4
/// @param edges             vertex pairs to split; an edge no tet contains is skipped
/// @param parentTet         #T' on return: the input tet each tet comes from
/// @param newVertexParents  on return, one entry per new vertex (ids #V, #V+1, ...): the two
///                          vertices whose midpoint it is (either may itself be a new vertex)
void SplitTetEdges(int vertexCount,
  Tets& cells,
  const std::vector<std::array<int, 2>>& edges,
  std::vector<int>& parentTet,
  std::vector<std::array<int, 2>>& newVertexParents);

/// Adds the new vertices of a split to per-vertex data: row #V + i is the mean of the rows of its
/// two parents.
/// @param points  #V by 3 on input, #V + #new by 3 on return
void AppendSplitMidpoints(Points& points, const std::vector<std::array<int, 2>>& newVertexParents);

/// Splits each tet of `tetsToSplit` into four by a new vertex at its centroid; the first child
/// keeps the tet's index, the others are appended. Orientation is preserved.
/// @param parentTet          #T on input (the origin of each tet), #T' on return
/// @param newVertexCorners   on return, the four corners of each new vertex (ids #V, #V+1, ...)
void SplitTetsAtCentroid(int vertexCount,
  Tets& cells,
  const std::vector<int>& tetsToSplit,
  std::vector<int>& parentTet,
  std::vector<std::array<int, 4>>& newVertexCorners);

/// Adds the centroids of SplitTetsAtCentroid to per-vertex data.
void AppendSplitCentroids(Points& points, const std::vector<std::array<int, 4>>& newVertexCorners);

} // namespace polycubehex
