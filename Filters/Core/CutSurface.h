// SPDX-License-Identifier: BSD-3-Clause
// Checks of a candidate cut: a set of interior faces of a tet mesh, each with a minus side.
// A valid cut is a connected, two-sided, properly embedded 2-manifold: every cut edge inside the
// solid holds exactly two cut faces, every cut edge on the boundary exactly one (so the cut's
// boundary lies on the boundary, and the cut meets it only there), the cut faces around every cut
// vertex form one fan (a cycle inside the solid, a path with both ends on the boundary at a
// boundary vertex), and the minus sides agree across every cut edge.
#pragma once

#include "MeshTypes.h"
#include "TopologyAdjacency.h"

#include <string>
#include <vector>

namespace polycubehex
{

/// One face of a cut: an interior face id and the side it is seen from: +1 when the minus side
/// is the face's first tet (TetAdjacency::InteriorFaces), -1 when it is the second.
struct CutFaceEntry
{
  int Face;
  int Side;
};

struct CutSurfaceReport
{
  bool Connected = false;
  bool Manifold = false; ///< edges and vertex fans as above, the boundary condition included
  bool TwoSided = false; ///< the minus sides agree across every interior cut edge
  std::string Problem;   ///< the first problem found, naming the edge or vertex
  double Area = 0.0;
  int EulerCharacteristic = 0; ///< V - E + F of the cut surface
  /// The cut's boundary loops as closed vertex polylines (first vertex not repeated at the end).
  std::vector<std::vector<int>> Loops;

  bool Valid() const { return this->Connected && this->Manifold && this->TwoSided; }
};

/// Analyses `faces` on the mesh (`cells`, `adjacency`, vertex positions `points`).
void AnalyzeCutSurface(const Tets& cells,
  const TetAdjacency& adjacency,
  const Points& points,
  const std::vector<CutFaceEntry>& faces,
  CutSurfaceReport& report);

/// The vertex ids of interior face `face` seen from its minus side: ordered so that the normal
/// points from the minus tet into the plus tet.
std::array<int, 3> OrientedCutFace(const Tets& cells,
  const TetAdjacency& adjacency,
  const CutFaceEntry& entry);

/// Section 5.3 of the paper: interior edges of the input where a cut's boundary runs along one
/// copy of an earlier cut only, i.e. the cut ends on the earlier cut from one side instead of
/// crossing it (then the transitions around such an edge compose to the cut's own transition,
/// not to the identity: a singular edge). A crossing cut runs along both copies of each edge.
/// @param input       adjacency of the uncut input mesh
/// @param loops       the cut's boundary loops in vertex ids of the cut mesh it was made on
/// @param toOriginal  per vertex of that cut mesh: the input vertex it copies
int CountMismatchedCutEdges(const TetAdjacency& input,
  const std::vector<std::vector<int>>& loops,
  const std::vector<int>& toOriginal);

/// Area of an interior face.
double InteriorFaceArea(const Tets& cells,
  const TetAdjacency& adjacency,
  const Points& points,
  int face);

} // namespace polycubehex
