// SPDX-License-Identifier: BSD-3-Clause
// Where the boundary vertices of an extracted hex mesh may go: the input's boundary triangles
// with their charts, and the projection that the smoothing (HexSmoothing.h) and the untangling
// (HexUntangling.h) share. A vertex on one chart stays on that chart's triangles, a vertex on two
// charts on their common feature curve, a vertex on three or more charts (a polycube corner) is
// fixed; interior vertices are free. Where the input surface is smooth across the charts of a
// curve or corner vertex (a polycube edge drawn on a smooth part of the surface), the vertex is
// released onto the union of its charts' triangles instead: the curve is no feature there, and
// holding the vertex on it can force a flat hex corner (three charts meeting in a T leave one
// quad a 180 degree angle at the corner).
#pragma once

#include "MeshTypes.h"
#include "TriangleGrid.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace polycubehex
{

/// The surface boundary vertices stay on: the input's boundary triangles with their charts.
struct HexSmoothingSurface
{
  Points Vertices;            ///< #S by 3 positions (same space as the hex mesh)
  Triangles Faces;            ///< #F by 3 boundary triangles
  std::vector<int> FaceChart; ///< #F chart of each triangle
};

/// The boundary triangles of a tet mesh with their charts, for the smoothing and untangling.
/// @param vertices   #V by 3 positions of the surface (the input's)
/// @param cells      #T by 4 tets
/// @param faceChart  #T by 4 chart of local face k (vtkTetra order) or -1 (ChartPlanes::FaceChart)
/// @param chartIds   #C: the number each chart gets in the surface (its glued chart across the
///                   seams of a cut polycube, GlueChartsAcrossSeams), or empty for the charts'
///                   own numbers
/// @param identity   #V: the vertex each one stands for (the copies across a seam as one,
///                   SeamVertexIdentity, so that feature curves continue across it), or empty
HexSmoothingSurface MakeChartSurface(const Points& vertices,
  const Tets& cells,
  const Tets& faceChart,
  const std::vector<int>& chartIds = {},
  const std::vector<int>& identity = {});

/// The default of the smoothing's and untangling's SoftFeatureAngle (degrees): the normals of the
/// input's triangles about a curve or corner vertex vary by less than this on a smooth surface
/// (a hex edge spans a few degrees of its curvature), and a crease this mild costs the
/// distance to the input little when a quad crosses it.
constexpr double DefaultSoftFeatureAngle = 20.0;

/// How a hex vertex may move.
enum class HexVertexKind
{
  Interior, ///< anywhere
  Surface,  ///< on its charts' triangles (one chart, or the released ones)
  Feature,  ///< on the feature curve between its two charts
  Fixed     ///< not at all (three or more charts, or charts the surface does not have)
};

/// The kinds of the hex vertices and their projections onto the chart surface. A released vertex
/// stays on the triangles of its region (its charts and those joined to them through released
/// vertices); any other Surface vertex on its chart's triangles and, within three hex edges of a
/// released vertex, on its region's, so that a vertex next to a released one can follow it
/// across a chart boundary. Const methods are safe to call from several threads; the surface
/// and vertexCharts must outlive the object.
class HexSurfaceProjection
{
public:
  /// @param surface       the input's boundary triangles with their charts
  /// @param vertexCharts  #V: sorted charts each hex vertex lies on (empty for interior ones)
  /// @param mesh          the hex mesh: its boundary quads tell the boundary vertices, its
  ///                      positions where smoothness is judged, its mean edge the search grid's
  ///                      cell size and the radius of the smoothness test
  /// @param softAngle     a vertex on two or more charts is released when the normals of its
  ///                      charts' triangles within one hex edge differ by at most this from
  ///                      their mean (degrees; 0 releases none)
  HexSurfaceProjection(const HexSmoothingSurface& surface,
    const std::vector<std::vector<int>>& vertexCharts,
    const HexMesh& mesh,
    double softAngle);
  ~HexSurfaceProjection();
  /// A copy shares the search grid (immutable) and releases on its own from then on.
  HexSurfaceProjection(const HexSurfaceProjection&);
  HexSurfaceProjection& operator=(const HexSurfaceProjection&) = delete;

  int VertexCount() const { return static_cast<int>(this->VertexKinds.size()); }
  HexVertexKind Kind(int v) const { return this->VertexKinds[static_cast<size_t>(v)]; }
  /// The sorted charts of vertex v.
  const std::vector<int>& Charts(int v) const
  {
    return (*this->VertexCharts)[static_cast<size_t>(v)];
  }
  /// Vertices on two or more charts released onto the surface so far.
  int ReleasedCount() const { return this->Released; }

  /// Releases a Feature or Fixed vertex at p onto its region's triangles (a Surface vertex from
  /// now on; one that knows no chart onto the whole surface). False when v is not such a vertex
  /// or one of its charts is not in the surface.
  bool Release(int v, const Eigen::Vector3d& p);
  /// Whether the input's normals within one hex edge of p, over v's charts, differ by at most
  /// `angle` degrees from their mean (the test that releases soft vertices at construction).
  bool SmoothAt(int v, const Eigen::Vector3d& p, double angle) const;
  /// Whether no edge of the input within one hex edge of p, on v's charts' triangles, is sharp:
  /// the normals of its two triangles differ by more than `angle` degrees. A curved part of a
  /// coarse surface turns a lot within a hex edge without a sharp edge (rockerarm: normals 50
  /// to 60 degrees apart, edges at most 36), where a box's edge is one sharp edge (90).
  bool FreeOfSharpEdgesAt(int v, const Eigen::Vector3d& p, double angle) const;

  /// The closest point to p where vertex v may be (p itself for interior and fixed vertices).
  /// @param direction  if set, receives the unit normal of the closest triangle (Surface) or the
  ///                   unit direction of the closest feature segment (Feature); zero otherwise
  Eigen::Vector3d Project(int v,
    const Eigen::Vector3d& p,
    Eigen::Vector3d* direction = nullptr) const;

private:
  const HexSmoothingSurface& Surface;
  const std::vector<std::vector<int>>* VertexCharts = nullptr;
  double CellSize = 0.0;
  std::vector<HexVertexKind> VertexKinds;
  std::map<int, std::vector<int>> ChartFaces;
  std::map<std::pair<int, int>, std::vector<std::array<int, 2>>> FeatureSegments;
  /// Per chart: the charts joined to it through released vertices (union-find parents).
  std::vector<int> ChartParent;
  /// #F: whether the triangle lies within three hex edges of a released vertex.
  std::vector<char> SoftFace;
  std::vector<int> VertexChart;                 ///< #V: first chart of a Surface vertex, else -1
  std::vector<std::pair<int, int>> VertexCurve; ///< #V: chart pair of a Feature vertex
  std::shared_ptr<const TriangleGrid> Grid;
  int Released = 0;
  std::vector<Eigen::Vector3d> FaceNormal; ///< #F unit normals
  /// #F: per edge e (from corner e to e + 1), the cosine between the normals of its two
  /// triangles (1 on a border).
  std::vector<std::array<double, 3>> EdgeCosine;
  /// #V: the normal of a Surface vertex's nearest triangle when it became one; beyond its own
  /// chart it only takes triangles facing the same side.
  std::vector<Eigen::Vector3d> ReferenceNormal;

  /// Whether the surface is smooth within `radius` of p across all of `charts`.
  bool Smooth(const Eigen::Vector3d& p,
    const std::vector<int>& charts,
    double radius,
    double cosine) const;
  /// The accepted triangle nearest to p (-1 if none) and the closest point on it.
  template<class Accept>
  int Nearest(const Eigen::Vector3d& p, const Accept& accept, Eigen::Vector3d& closest) const
  {
    return this->Grid ? this->Grid->Nearest(p, accept, closest) : (closest = p, -1);
  }
  int Region(int chart) const;
  void SetReferenceNormal(int v, const Eigen::Vector3d& p);
};

} // namespace polycubehex
