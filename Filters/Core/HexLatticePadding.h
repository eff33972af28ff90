// SPDX-License-Identifier: BSD-3-Clause
// The padding layer (HexPadding.h) of a mesh fresh from the lattice extraction: the inner copy of
// each boundary vertex moves a fraction of a hex inwards along the inward normals of its charts,
// in the lattice, and is mapped back through the tets around the vertex, so that the layer
// follows the map (at a concave polycube edge the copy moves along the bisector as far as its
// neighbours on either chart). On a cut polycube the hexes around a vertex on a seam are in
// different lattice frames: the offsets are computed per vertex in its own frame and seen from
// each hex through the rotations the extraction recorded.
#pragma once

#include "HexLatticeExtraction.h"
#include "IntegerRounding.h"
#include "MeshTypes.h"
#include "PolycubeSeams.h"
#include "Status.h"

namespace polycubehex
{

/// What addLatticePaddingLayer did.
struct LatticePaddingResult
{
  int PaddingHexCount = 0;
  /// Inner copies placed by the fallback rule (towards the mean of the vertex's hex centres)
  /// because their lattice position could not be located in the tets (0 normally).
  int UnmappedVertexCount = 0;
};

/// The inward direction of each vertex in its representative frame: for each distinct label of
/// VertexChartLabels, minus that label's axis direction (rows of interior vertices are zero).
/// @return #V by 3
Points LatticeInwardDirections(const LatticeHexMesh& lattice);

/// Adds the padding layer to `lattice` in place.
/// @param original   #V_tet by 3 input positions
/// @param positions  #V_tet by 3 tet vertices in lattice units (the extraction's input)
/// @param cells      #T by 4 tets
/// @param charts     the charts the extraction used
/// @param thickness  the layer's thickness in hex edges, in (0, 0.5)
/// @param lattice    from extractLatticeHexes on the same input; on return Mesh holds the padded
///                   mesh (copies and padding hexes appended, as addPaddingLayer), and
///                   LatticeVertices, VertexCharts, VertexChartLabels and VertexTets have a row per
///                   vertex (an inner copy: its lattice position in its vertex's frame, no
///                   charts, its vertex's tet). HexCenters, HexOrigins and HexCornerRotations
///                   keep describing the extracted hexes only.
/// @param seams      as given to extractLatticeHexes
/// @return Failure when the mesh has no hexes.
Status addLatticePaddingLayer(const Points& original,
  const Points& positions,
  const Tets& cells,
  const ChartPlanes& charts,
  double thickness,
  LatticeHexMesh& lattice,
  LatticePaddingResult& result,
  const PolycubeSeams* seams = nullptr);

} // namespace polycubehex
