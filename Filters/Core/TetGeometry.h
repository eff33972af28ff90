// SPDX-License-Identifier: BSD-3-Clause
// Small geometric and combinatorial helpers on tetrahedral meshes shared by the core algorithms:
// the local face table, signed volumes, boundary extraction, edges, polar decomposition and the
// unit-diagonal normalisation of DESIGN.md ("Scale").
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace polycubehex
{

/// Local faces of a tet, VTK's vtkTetra order: face k holds these local vertices, ordered so that
/// the normal (p1 - p0) x (p2 - p0) points out of a positively oriented tet.
constexpr int TetFaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

/// Signed volume of the tet (a, b, c, d); positive for VTK's node order.
double TetSignedVolume(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c,
  const Eigen::Vector3d& d);

/// Signed volume of tet `t` of a mesh whose vertex positions are `x`.
double TetSignedVolume(const Points& x, const Tets& cells, int t);

/// The boundary of a tet mesh and the face adjacency of its tets.
struct TetTopology
{
  /// #T by 4: the tet across local face k, or -1 when the face is on the boundary.
  Tets Neighbors;
  /// #F by 3 boundary triangles, each oriented like its tet's local face (normal points out).
  Triangles BoundaryFaces;
  std::vector<int> BoundaryFaceTet;   ///< #F: the tet owning boundary face f
  std::vector<int> BoundaryFaceLocal; ///< #F: the local face index (0..3) in that tet
  /// #T by 4: boundary face id of local face k of tet t, or -1.
  Tets TetFaceToBoundaryFace;
  /// Unique undirected edges, each stored (smaller id, larger id), sorted lexicographically.
  std::vector<std::array<int, 2>> Edges;
  /// #V: true for a vertex of a boundary face.
  std::vector<bool> IsBoundaryVertex;
  /// Number of faces shared by more than two tets (0 for a valid manifold mesh).
  int NonManifoldFaceCount = 0;
};

/// Builds the face adjacency, the oriented boundary and the edge list of `cells`.
/// @param vertexCount  #V, the number of vertices the indices refer to
/// @param cells        #T by 4 vertex indices
void ComputeTetTopology(int vertexCount, const Tets& cells, TetTopology& topology);

/// For each boundary face f (in `faces`), the boundary faces across its local edges
/// e = 0..2 (edge e joins corner e and corner (e+1)%3), or -1 when the boundary edge is not shared
/// by exactly two boundary faces.
/// @param faces  #F by 3 oriented boundary triangles
/// @return #F by 3 neighbour face indices
Triangles ComputeFaceAdjacency(int vertexCount, const Triangles& faces);

/// Polar decomposition of a 3x3 matrix: J = R S with R a rotation (det +1) and S symmetric. The
/// singular values in `sigma` are signed so that sum (sigma_i - 1)^2 = ||J - R||_F^2 also holds
/// for det J < 0.
void PolarRotation(const Eigen::Matrix3d& J, Eigen::Matrix3d& R, Eigen::Vector3d& sigma);

/// The similarity that centres a point set at the origin and scales its bounding-box diagonal to
/// 1: normalised = (x - Center) / Scale, and back x = normalised * Scale + Center.
struct UnitDiagonalFrame
{
  Eigen::RowVector3d Center = Eigen::RowVector3d::Zero();
  double Scale = 1.0; ///< the bounding-box diagonal of the input
};

/// Computes the frame of `x` (Scale = 1 for a degenerate point set).
UnitDiagonalFrame ComputeUnitDiagonalFrame(const Points& x);

/// Applies the frame: returns (x - Center) / Scale.
Points ToUnitDiagonal(const UnitDiagonalFrame& frame, const Points& x);

/// Inverts the frame: returns x * Scale + Center.
Points FromUnitDiagonal(const UnitDiagonalFrame& frame, const Points& x);

/// Area and unit outward normal of every face of `faces` (#F by 3, indices into `x`).
/// A face of zero area gets `zeroAreaNormal`. Returns the total area.
double ComputeFaceAreasAndNormals(const Points& x,
  const Triangles& faces,
  const Eigen::Vector3d& zeroAreaNormal,
  std::vector<double>& area,
  std::vector<Eigen::Vector3d>& normal);

} // namespace polycubehex
