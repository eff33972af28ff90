// SPDX-License-Identifier: BSD-3-Clause
// Cutting a tet mesh open along a set of interior faces: every vertex is split into one copy per
// group of its tets that stay connected through uncut interior faces around it. Tets keep their
// ids and local numbering; only vertex ids change, so cut faces become boundary faces.
#pragma once

#include "MeshTypes.h"
#include "TopologyAdjacency.h"

#include <vector>

namespace polycubehex
{

/// @param vertexCount  #V of `cells`
/// @param cut          one flag per interior face of `adjacency`: 1 = cut open
/// @param cutCells     #T by 4, the same tets on the split vertices
/// @param splitToOld   per vertex of the result: the vertex of `cells` it copies. A vertex keeps
///                     its id for its first group (in tet order); further copies are appended.
/// @return the number of vertices of the result
int SplitAlongFaces(int vertexCount,
  const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<char>& cut,
  Tets& cutCells,
  std::vector<int>& splitToOld);

} // namespace polycubehex
