// SPDX-License-Identifier: BSD-3-Clause
// The padding layer (pillowing) of polycube hex meshes: one layer of hexes between the boundary
// quads and the rest of the mesh, so that no hex keeps two faces on the boundary where the
// polycube has an edge or a corner (Fang et al. 2016 use it for the models marked with a dagger
// in Table 1; the paper gives no construction, this one is the classic pillow).
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace polycubehex
{

/// The boundary quads of a hex mesh, each oriented like its hex's face (normal pointing out of a
/// positive hex), in the order of (hex, local face).
/// @param mesh  #H by 8 hexes in VTK order
/// @return #B by 4 boundary quads
Quads ComputeHexBoundaryQuads(const HexMesh& mesh);

/// Where the inner copies of the boundary vertices go, as offsets: each boundary vertex moves
/// `thickness` along its direction, and the vertices of any hex (kept or new padding hex) that
/// this would leave with a scaled Jacobian below `minQuality` get half the offset, repeatedly. A
/// convex corner keeps the full diagonal move; a concave corner (seven octants full), whose
/// diagonal move of 1/3 would flatten the hex that touches the boundary only there, is shortened.
/// Works in any space where the hexes are near unit cubes (the lattice).
/// @param mesh        #V by 3 positions (lattice), #H by 8 hexes
/// @param directions  #V by 3 inward direction of each boundary vertex (sum of the inward
///                    normals of its charts; rows of interior vertices ignored)
/// @param thickness   offset along a unit direction component, in (0, 0.5)
/// @return #V by 3 offsets (zero rows for interior vertices)
Points ComputePaddingOffsets(const HexMesh& mesh,
  const Points& directions,
  double thickness,
  double minQuality = 0.3);

/// The same where the hexes' corners are not in one frame (a cut polycube: each side of a seam
/// has its lattice frame). Each hex's corners are given in its own frame, and the offset of
/// vertex v (in v's frame, like its direction) is seen from hex h as R_hk offset_v, R_hk the
/// rotation from the frame of vertex Cells(h, k) to the frame of hex h.
/// @param cells            #H by 8 hexes in VTK order (#V = the largest index + 1, or the rows
///                         of `directions`)
/// @param hexCorners       #H * 8 by 3: row 8 h + k the lattice coordinates of corner k of hex h
///                         in the hex's frame
/// @param cornerRotations  #H * 8 rotations R_hk (LatticeHexMesh::HexCornerRotations), or
///                         empty when every one is the identity
/// @param directions       #V by 3 inward direction of each boundary vertex, in its own frame
/// @return #V by 3 offsets, each in its vertex's frame (zero rows for interior vertices)
Points ComputePaddingOffsets(const Hexes& cells,
  const Points& hexCorners,
  const std::vector<Eigen::Matrix3i>& cornerRotations,
  const Points& directions,
  double thickness,
  double minQuality = 0.3);

/// What addPaddingLayer did.
struct HexPaddingResult
{
  /// #V (before padding): the inner copy of each boundary vertex, or -1 for interior vertices.
  std::vector<int> InnerCopy;
  /// #B by 4 boundary quads before padding; the padding hex of quad b is hex (#H before + b) and
  /// the boundary quads after padding are the same quads (same vertex ids).
  Quads BoundaryQuads;
};

/// Inserts the padding layer. Each boundary vertex keeps its index and position (it stays on the
/// surface); an inner copy replaces it in its hexes; each boundary quad becomes a hex joining it
/// to its inner copies.
/// @param mesh           #V by 3, #H by 8 positive hexes; on return #V + #Bv vertices (copies
///                       appended) and #H + #B hexes (padding hexes appended)
/// @param innerPosition  where the inner copy of boundary vertex v goes; a good choice moves v
///                       inwards by a fraction of a hex along the sum of the inward normals of
///                       its charts (along the diagonal at polycube edges and corners)
/// @return Failure when the mesh has no hexes.
Status addPaddingLayer(HexMesh& mesh,
  const std::function<Eigen::RowVector3d(int vertex)>& innerPosition,
  HexPaddingResult& result);

} // namespace polycubehex
