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
// through tets overlapping the cube is taken.
//
// On a cut mesh M_c (a closed-form polycube, PolycubeSeams.h) each side of a cut has its own
// lattice frame, u_plus = Pi u_minus + t with t integer. The extraction is made seamless there:
// a point (or cube centre) on a cut face is found by the tets of both sides, at coordinates
// related by the transition, and the two groups are united into one vertex (one cube); the walk
// from a cube's centre to its corners crosses cut faces and carries the map from the centre's
// frame to the frame of each tet it reaches, so that a corner on the other side is looked up at
// its transformed coordinate. A vertex's lattice coordinate is then in the frame of one of its
// groups (its representative), and each hex records, per corner, the rotation from that frame
// to its own (the frame of its centre's tets).
#pragma once

#include "IntegerRounding.h"
#include "MeshTypes.h"
#include "PolycubeSeams.h"
#include "Status.h"

#include <Eigen/Core>

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
  HexMesh Mesh; ///< vertices in the original space; hexes in VTK order, positive
  /// #V by 3 lattice coordinates of each vertex (integers), in the vertex's representative
  /// frame: the frame of VertexTets[v] (one side of every cut the vertex lies on).
  Points LatticeVertices;
  Points HexCenters; ///< #H by 3 image in the original space of each hex's centre
  /// #H by 3: the lattice coordinate of each hex's minimum corner (VTK corner 0) in the hex's
  /// frame, the frame of the tets around its centre. Corner k is HexOrigins(h) + the k-th unit
  /// cube corner in VTK order, in that frame.
  Points HexOrigins;
  /// #H * 8 (row 8 h + k), empty without seams (then every entry is the identity): the rotation
  /// from the representative frame of vertex Cells(h, k) to the frame of hex h. Corner k of hex h
  /// is R LatticeVertices(Cells(h, k)) + an integer translation, so an offset d of the vertex
  /// (padding) is R d seen from the hex.
  std::vector<Eigen::Matrix3i> HexCornerRotations;
  /// #V: the charts of M_c each vertex lies on, sorted (empty for an interior vertex). A vertex on
  /// one chart slides on the surface, on two it follows a feature curve, on three it is a corner.
  /// A vertex on a seam lists the charts of both sides (see GlueChartsAcrossSeams).
  std::vector<std::vector<int>> VertexCharts;
  /// #V: parallel to VertexCharts, the label 0..5 of each of those charts expressed in the
  /// vertex's representative frame (a chart of the other side of a seam has its label in its
  /// own frame, mapped by the transition): the directions of the outward normals there. Two
  /// charts that continue each other across a seam have the same label here.
  std::vector<std::vector<int>> VertexChartLabels;
  /// #V: a tet that contains each vertex (its representative group's deepest), where a search
  /// near it starts; LatticeVertices(v) is in this tet's frame.
  std::vector<int> VertexTets;
  /// Cube corners chosen by the local search among several vertices at one lattice coordinate.
  int AmbiguousCornerCount = 0;
  /// Cube centres inside the volume with a corner missing (0 when every chart is on an integer
  /// plane and the map is locally injective).
  int IncompleteCubeCount = 0;
  /// Groups (vertices or centres) united across a seam whose frames disagree around a cycle of
  /// seams (0 when the translations are consistent).
  int InconsistentSeamCount = 0;
};

/// Extracts the unit cubes of the lattice.
/// @param original  #V by 3 input positions, positive tets
/// @param lattice   #V by 3 positions in lattice units, positive tets, every chart exactly on
///                  an integer plane (roundPolycubePlanes)
/// @param cells     #T by 4 tets
/// @param charts    from ComputeChartPlanes on these tets (on M_c: Neighbors -1 across a cut,
///                  FaceChart -1 on cut faces)
/// @param seams     the cuts of a closed-form polycube (nullptr or empty for a uniform one), with
///                  integer translations in lattice units (the rounding's); the positions of
///                  every copy pair must satisfy u_plus = Pi u_minus + t
/// @return Failure when the lattice is out of range or aborted; an empty result is a Success.
Status extractLatticeHexes(const Points& original,
  const Points& lattice,
  const Tets& cells,
  const ChartPlanes& charts,
  const LatticeExtractionParameters& params,
  LatticeHexMesh& out,
  const Progress& progress = {},
  const PolycubeSeams* seams = nullptr);

/// Maps a lattice point near a known one to the original space through the tet containing it,
/// found among the tets face-connected to `start` that overlap the box spanned by `from` and
/// `point` (the search stays in the region of `start`, so it is right where the map is not
/// injective as long as the segment from `from` to `point` lies in the volume).
/// With seams the search crosses cut faces, mapping the box by the transitions (`from` and
/// `point` are in the frame of `start`).
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
  Eigen::RowVector3d& image,
  const PolycubeSeams* seams = nullptr);

/// The charts of M that the charts of M_c make, for the smoothing: two charts that meet across a
/// seam (along an edge of a cut face on the boundary) with labels related by the transition are
/// one chart, so that the triangles a surface vertex near a seam slides on continue across it.
/// Two charts are not glued when their class would then hold two charts adjacent to each other
/// (a quarter-twisted ring's four sides are one chart of M that meets itself along the ring's
/// edges; chart ids cannot tell such a feature curve, so those charts stay apart).
/// @param cells   #T by 4 tets of M_c
/// @param charts  ComputeChartPlanes on M_c
/// @param seams   the seams of M_c (nullptr or empty: every chart is its own)
/// @return #C: for each chart of M_c, the smallest chart id of its glued class (a chart id of
///         M_c, so ChartLabel applies to it, in that chart's frame)
std::vector<int> GlueChartsAcrossSeams(const Tets& cells,
  const ChartPlanes& charts,
  const PolycubeSeams* seams);

/// The charts each vertex lies on for the smoothing (smoothHexMesh's vertexCharts) on a cut
/// polycube: VertexCharts through `glued`, and of the charts with one label in the vertex's
/// frame (one chart seen from both sides of a seam) only the smallest id, so that a vertex on a
/// seam counts one chart where M has one.
/// @param lattice  from extractLatticeHexes
/// @param glued    from GlueChartsAcrossSeams
/// @return #V (the rows of lattice.VertexCharts): sorted chart ids
std::vector<std::vector<int>> GluedVertexCharts(const LatticeHexMesh& lattice,
  const std::vector<int>& glued);

/// The points of M that the vertices of M_c stand for: each vertex's smallest copy across the
/// seams (the vertex itself without seams).
/// @param vertexCount  #V of M_c
/// @return #V
std::vector<int> SeamVertexIdentity(int vertexCount, const PolycubeSeams* seams);

} // namespace polycubehex
