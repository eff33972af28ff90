// SPDX-License-Identifier: BSD-3-Clause
// The unit cubes of the integer lattice inside a polycube-deformed tet mesh, mapped back to the
// input: the extraction step of Fang et al. 2016 §4.3, HexEx style (Lyon et al. 2016).
//
// Integer points are enumerated per tet, never through a global point locator in lattice space:
// a closed-form map is not injective globally (a torus unrolls into a bar that may overlap
// itself), so one lattice coordinate may stand for several points of the input. A point found by
// several tets is one vertex only when those tets are connected around it (they share a mesh
// vertex): vertices are keyed by (lattice coordinate, connected group of tets). A cube is a hex
// when its centre lies in some tet; its corners are looked up among the vertices at the corner
// coordinates, and when several groups share a coordinate the one reached from the centre's tet
// through tets overlapping the cube is taken. Cuts (later) fit here: the walk across a cut face
// maps lattice coordinates by the transition u_plus = Pi u_minus + t.
#pragma once

#include "IntegerRounding.h"
#include "MeshTypes.h"
#include "Status.h"

#include <vector>

namespace polycubehex
{

/// Settings of extractLatticeHexes.
struct LatticeExtractionParameters
{
  /// A point belongs to a tet when all its barycentric coordinates are >= -tolerance (default
  /// 1e-9): points on shared faces, edges and vertices are found by every tet around them and
  /// then merged, never lost between two tets.
  double BarycentricTolerance = 1e-9;
};

/// The lattice hexes and what later steps (padding, smoothing, output arrays) need about them.
struct LatticeHexMesh
{
  HexMesh Mesh;           ///< vertices in the original space; hexes in VTK order, positive
  Points LatticeVertices; ///< #V by 3 lattice coordinates of each vertex (integers)
  Points HexCenters;      ///< #H by 3 image in the original space of each hex's centre
  /// #V: the charts each vertex lies on, sorted (empty for an interior vertex). A vertex on one
  /// chart slides on the surface, on two it follows a feature curve, on three it is a corner.
  std::vector<std::vector<int>> VertexCharts;
  /// #V: a tet that contains each vertex (its region's deepest), where a search near it starts.
  std::vector<int> VertexTets;
  /// Cube corners chosen by the local search among several vertices at one lattice coordinate.
  int AmbiguousCornerCount = 0;
  /// Cube centres inside the volume with a corner missing (0 when every chart is on an integer
  /// plane and the map is locally injective).
  int IncompleteCubeCount = 0;
};

/// Extracts the unit cubes of the lattice.
/// @param original  #V by 3 input positions, positive tets
/// @param lattice   #V by 3 positions in lattice units, positive tets, every chart exactly on
///                  an integer plane (roundPolycubePlanes)
/// @param cells     #T by 4 tets
/// @param charts    from ComputeChartPlanes on these tets
/// @return Failure when the lattice is out of range or aborted; an empty result is a Success.
Status extractLatticeHexes(const Points& original,
  const Points& lattice,
  const Tets& cells,
  const ChartPlanes& charts,
  const LatticeExtractionParameters& params,
  LatticeHexMesh& out,
  const Progress& progress = {});

/// Maps a lattice point near a known one to the original space through the tet containing it,
/// found among the tets face-connected to `start` that overlap the box spanned by `from` and
/// `point` (the search stays in the region of `start`, so it is right where the map is not
/// injective as long as the segment from `from` to `point` lies in the volume).
/// @param start  a tet containing `from`
/// @param image  on success, the image of `point` in the original space
/// @return false when no such tet contains `point`
bool MapLatticePoint(const Points& original,
  const Points& lattice,
  const Tets& cells,
  const ChartPlanes& charts,
  int start,
  const Eigen::Vector3d& from,
  const Eigen::Vector3d& point,
  double tolerance,
  Eigen::RowVector3d& image);

} // namespace polycubehex
