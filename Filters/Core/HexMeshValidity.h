// SPDX-License-Identifier: BSD-3-Clause
// The combinatorial half of "valid hex mesh" (shared/DESIGN.md section 4): distinct corners,
// quads shared by at most two hexes, and a closed, manifold, consistently oriented boundary.
// The geometric half (scaled Jacobian > 0, no two vertices closer than 1e-9 of the diagonal)
// needs Verdict and a point locator and lives in the VTK layer (vtkHexMeshQuality).
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <array>
#include <string>

namespace polycubehex
{

/// VTK's vtkHexahedron face table: local face k has these 4 local vertices, ordered so that the
/// normal (right-hand rule) points out of a positively oriented hex.
constexpr std::array<std::array<int, 4>, 6> HexFaces = {
  { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 }, { 0, 3, 2, 1 }, { 4, 5, 6, 7 } }
};

/// What checkHexMeshValidity found. Counts are 0 on a valid mesh except the informative ones
/// (HexCount, BoundaryQuadCount, IrregularBoundaryVertexCount).
struct HexMeshValidity
{
  int HexCount = 0;
  /// Hexes whose 8 vertex indices are not all distinct.
  int DegenerateHexCount = 0;
  /// Distinct quads (as vertex sets) used by three or more hex faces.
  int OverSharedQuadCount = 0;
  /// Quads used by exactly two hex faces with the same orientation: both hexes lie on the same
  /// side of the quad, so they overlap (or one is inverted) and the quad is not truly interior.
  int MisorientedQuadCount = 0;
  /// Quads used by exactly one hex face.
  int BoundaryQuadCount = 0;
  /// Boundary edges not shared by exactly two boundary quads traversing it in opposite
  /// directions (open boundary, edge touching, or inconsistent orientation).
  int NonManifoldBoundaryEdgeCount = 0;
  /// Boundary vertices whose boundary quads form more than one fan (cubes touching at a vertex).
  int NonManifoldBoundaryVertexCount = 0;
  /// Boundary vertices with a number of boundary quads other than 4.
  int IrregularBoundaryVertexCount = 0;

  /// #B by 4 boundary quads (the faces used once), counter-clockwise seen from outside for
  /// positively oriented hexes, in the order of (hex, local face).
  Quads BoundaryQuads;

  /// One line per kind of defect, naming the first offender; a one-line summary when valid.
  std::string Report;

  /// True when every combinatorial condition of DESIGN.md section 4 holds.
  bool IsValid() const
  {
    return this->HexCount > 0 && this->DegenerateHexCount == 0 && this->OverSharedQuadCount == 0 &&
      this->MisorientedQuadCount == 0 && this->NonManifoldBoundaryEdgeCount == 0 &&
      this->NonManifoldBoundaryVertexCount == 0;
  }
};

/// Checks the combinatorial validity of a hex mesh and extracts its boundary quads.
/// @param mesh    #V by 3 vertices and #H by 8 hexes in VTK's node order
/// @param result  counts, boundary quads and a readable report
/// @return Failure only when the input cannot be checked (no hexes, or an index out of range);
///         an invalid mesh is a Success whose result.IsValid() is false.
Status checkHexMeshValidity(const HexMesh& mesh, HexMeshValidity& result);

} // namespace polycubehex
