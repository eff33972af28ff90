// SPDX-License-Identifier: BSD-3-Clause
// The cut mesh M_c of the closed-form polycube (Fang et al. §4.1): the input opened along its
// cuts, each vertex of a cut face copied once per side, and the copies related by the cut's
// transition x_plus = Pi_c x_minus + t_c (eq. 8) with t_c unknown. The relations survive edge
// splits (a split on one side is mirrored on the other, and the two midpoints are copies too).
//
// Every vertex of M_c also carries an identity: the same number for all copies of one point of
// M. Faces written with identities are the faces of M, which glues charts across the cuts and
// tells the faces of the cuts (two copies of one face of M) from the faces of the boundary of M.
#pragma once

#include "CoordinateRelations.h"
#include "MeshTypes.h"
#include "PolycubeCharts.h"
#include "Status.h"
#include "TetGeometry.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace polycubehex
{

/// The cuts of the input and their transitions (vtkHandleCutFilter's CutFaces and CutSide,
/// vtkFrameFieldFilter's CutTransitions).
struct PolycubeCuts
{
  Tets FaceCut;  ///< #T by 4: cut id of local face k, -1 if none (both tets of a cut face)
  Tets FaceSide; ///< #T by 4: -1 on the minus side, +1 on the plus side
  std::vector<Eigen::Matrix3i> Transitions; ///< Pi_c per cut, a cube rotation
  int Count() const { return static_cast<int>(this->Transitions.size()); }
};

/// x_Plus = Pi_Cut x_Minus + t_Cut.
struct CopyRelation
{
  int Minus = -1;
  int Plus = -1;
  int Cut = -1;
};

struct PolycubeCutMesh
{
  Tets Cells;                       ///< #T by 4, the input's tets on the copies
  std::vector<int> CopiedVertex;    ///< per vertex: the input vertex it copies
  std::vector<CopyRelation> Copies; ///< one per copy pair across a cut face
};

/// Opens `input` along the faces of `cuts`. Fails when the arrays disagree in size, a cut face
/// is not marked on both of its tets with opposite sides, or a transition is not a rotation.
Status BuildPolycubeCutMesh(const TetMesh& input, const PolycubeCuts& cuts, PolycubeCutMesh& out);

/// The edges to split so that M_c stays a cut mesh: `edges` and, for each, its copies across
/// every cut (transitively). `partnerEdges` receives, for each added copy, the pair of edge
/// indices (into the result) it mirrors and the relation: (index of the minus edge, index of the
/// plus edge, cut).
std::vector<std::array<int, 2>> MirrorEdgesAcrossCuts(const std::vector<std::array<int, 2>>& edges,
  const std::vector<CopyRelation>& copies,
  int vertexCount,
  std::vector<std::array<int, 3>>& partnerEdges);

/// Orders the edges to split by the points of M they join, so that every copy of an edge is
/// split at the same step. The halves a face gets when two of its edges are split depend on the
/// order: a cut face whose copies were split in different orders would be triangulated
/// differently on the two sides, its pieces would no longer be copies of each other, and they
/// would count as (folded) boundary faces of M. `partnerEdges` (indices into `edges`) follow.
void SortCopiesAlike(std::vector<std::array<int, 2>>& edges,
  std::vector<std::array<int, 3>>& partnerEdges,
  const std::vector<int>& identity);

/// After SplitTetEdges on `edges` (midpoint i is vertex firstNew + i, in `midpointParents`
/// order), the copy relations of the new midpoints and their identities.
void AddMidpointCopies(const std::vector<std::array<int, 2>>& edges,
  const std::vector<std::array<int, 3>>& partnerEdges,
  const std::vector<std::array<int, 2>>& midpointParents,
  int firstNew,
  std::vector<CopyRelation>& copies,
  std::vector<int>& identity);

/// Keeps in `topology` only the boundary faces of M: a boundary face of M_c whose identity
/// triple occurs twice is a face of a cut. IsBoundaryVertex then marks the vertices of M's
/// boundary only; TetFaceToBoundaryFace follows the new numbering.
void KeepInputBoundary(TetTopology& topology, const std::vector<int>& identity);

/// `faces` with every vertex replaced by its identity (for face adjacency and corners of M).
Triangles IdentityFaces(const Triangles& faces, const std::vector<int>& identity);

/// The label (0..5 = +X,-X,+Y,-Y,+Z,-Z) of direction Pi d for d the direction of `label`.
int TransformLabel(const Eigen::Matrix3i& pi, int label);

/// For each pair of boundary faces that are neighbours across a cut's boundary loop (in
/// `adjacency`, built on identities): (face on the minus side, face on the plus side, cut).
std::vector<std::array<int, 3>> FacesAcrossCuts(const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<CopyRelation>& copies);

/// Makes the labels agree across every cut's loop where that costs no fold: of two neighbours
/// across it whose labels are not related by Pi_c, one takes the other's label transformed, but
/// only a face that then keeps a neighbour of that label on its own side or whose normal (in
/// positions `x`) lies within 60 degrees of the new label. Chart boundaries then cross the loop
/// at copies of one vertex. A pair where neither face may give way (the loop runs along a crease
/// of M: the faces' normals differ by 90 degrees) keeps its labels: forcing one face would make
/// a one-face chart on its side of the cut whose normal is perpendicular to its label, which the
/// flattening collapses (it cannot be flat without two of its edges on one crease line). Returns
/// the changes.
int MatchLabelsAcrossCuts(const std::vector<std::array<int, 3>>& across,
  const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<Eigen::Matrix3i>& transitions,
  std::vector<int>& labels);

/// The labels of the boundary of a cut mesh cleaned up (CleanUpPolycubeCharts on `adjacency`,
/// built on identities), then matched across the cuts (MatchLabelsAcrossCuts) where that folds
/// no face; a pair left unmatched is a chart boundary along the cut's loop. Without copies, the
/// clean-up alone. Returns the number of changes.
int CleanUpCutMeshLabels(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<CopyRelation>& copies,
  const std::vector<Eigen::Matrix3i>& transitions,
  const PolycubeChartCleanup& settings,
  std::vector<int>& labels);

/// Per face, its chart with charts that continue across a cut (labels related by the
/// transition) given one number, for counting the corners of M.
std::vector<int> ChartsAcrossCuts(const std::vector<std::array<int, 3>>& across,
  const std::vector<Eigen::Matrix3i>& transitions,
  const std::vector<int>& labels,
  const std::vector<int>& faceChart,
  int chartCount);

/// The copy relations as hard relations on the coordinates, with 3 unknown translations per cut
/// (extras 3c, 3c+1, 3c+2, in the normalised units of the positions).
void AddCopyRelations(const std::vector<CopyRelation>& copies,
  const std::vector<Eigen::Matrix3i>& transitions,
  CoordinateRelations& relations);

} // namespace polycubehex
