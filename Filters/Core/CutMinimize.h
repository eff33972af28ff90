// SPDX-License-Identifier: BSD-3-Clause
// Least-area surface in a cohomology class, by minimum cuts in a cyclic cover.
//
// An integer cocycle phi on the interior faces (value across a face from its first to its second
// tet) defines the infinite cyclic cover of the solid: tet copies (t, c), c in Z, with (a, c)
// joined to (b, c + phi(f)) across face f = (a, b). A surface in the class of phi is the boundary
// of a region R of the cover with R + 1 containing R; writing R = {(t, c) : c < h(t)} for an
// integer height h, its faces carry the cohomologous cocycle phi + dh (phi(f) + h(a) - h(b)), and
// its area is sum_f area(f) |phi(f) + h(a) - h(b)|.
// One round takes the window of `copies` consecutive sheets of the cover, joins every copy below
// the window to the source and every copy above it to the sink, and finds a minimum s-t cut with
// face areas as capacities (MaxFlow). The source side gives h (how many of a tet's copies it
// holds) and the new cocycle, whose area is at most the cut's capacity, itself at most the area
// of the current cocycle (the cut below the window). Rounds repeat until the area stops falling.
#pragma once

#include "MeshTypes.h"
#include "TopologyAdjacency.h"

#include <vector>

namespace polycubehex
{

/// Area of a cochain: sum over interior faces of area * |value|.
double CochainArea(const std::vector<double>& faceArea, const std::vector<int>& cochain);

/// Replaces `cocycle` by a cohomologous one of smaller support area, as above.
/// @param faceArea   per interior face
/// @param copies     sheets of the cover in the window (>= 1; 1 = the solid cut open along the
///                   current surface, source on one side, sink on the other)
/// @param maxRounds  at most this many minimum cuts
/// @param rounds     receives the number of minimum cuts computed (optional)
/// @return the final area
double MinimizeCocycleArea(const TetAdjacency& adjacency,
  const std::vector<double>& faceArea,
  std::vector<int>& cocycle,
  int copies,
  int maxRounds,
  int* rounds = nullptr);

} // namespace polycubehex
