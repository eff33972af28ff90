// SPDX-License-Identifier: BSD-3-Clause
// Moves of one hex vertex that are kept only when a rule approves the scaled Jacobians of its
// hexes: the building block of the smoothing sweeps and of the polish of the worst hexes
// (HexSmoothing.h). Holds the incidence of the mesh, the current scaled Jacobian of every hex,
// and the directions a vertex may move in: any for an interior vertex, the tangent plane for a
// vertex on the surface, the curve's tangent for a vertex on a feature curve; a boundary vertex
// is projected back onto where it may be (HexSurfaceProjection.h) after each move.
#pragma once

#include "HexSurfaceProjection.h"
#include "MeshTypes.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace polycubehex
{

class HexVertexMoves
{
public:
  /// The quality of the hexes around a vertex.
  struct Local
  {
    double Min = 0.0;  ///< smallest scaled Jacobian
    double Mean = 0.0; ///< mean scaled Jacobian
    int Inverted = 0;  ///< hexes with scaled Jacobian <= 0
  };

  /// `mesh` and `projection` must outlive the object; the mesh's positions change through it.
  HexVertexMoves(HexMesh& mesh, const HexSurfaceProjection& projection);

  int VertexCount() const { return static_cast<int>(this->HexesOfVertex.size()); }
  HexVertexKind Kind(int v) const { return this->Projection.Kind(v); }
  const HexSurfaceProjection& Surface() const { return this->Projection; }
  HexMesh& Mesh() { return this->Target; }
  /// The current scaled Jacobian of every hex.
  const Eigen::VectorXd& Quality() const { return this->HexQuality; }
  const std::vector<int>& HexesOf(int v) const { return this->HexesOfVertex[v]; }
  /// Edge neighbours through hexes (interior vertices) or through boundary quads (others).
  const std::vector<int>& Neighbours(int v) const;
  /// A Feature vertex's neighbours on the same curve (or at its ends); empty for other kinds.
  std::vector<int> CurveNeighbours(int v) const;
  /// Mean length of the edges to Neighbours(v).
  double MeanEdgeLength(int v) const;

  /// The quality around v from the cached scaled Jacobians.
  Local Cached(int v) const;
  /// Unit directions v may move in: three axes inside, two spanning the tangent plane of its
  /// boundary quads on the surface, the tangent of its curve on a feature; none when fixed or
  /// when the geometry gives no direction.
  std::vector<Eigen::Vector3d> Directions(int v) const;
  /// Where v lands when sent to p: p inside, its projection on the boundary.
  Eigen::Vector3d Landing(int v, const Eigen::Vector3d& p) const;

  /// Moves v to Landing(v, candidate) when accept(moved, current) holds for the quality of its
  /// hexes there, and then updates `current` and the cache; else leaves v where it was.
  template<class Accept>
  bool TryMove(int v, const Eigen::Vector3d& candidate, Local& current, const Accept& accept)
  {
    const Eigen::RowVector3d old = this->Target.Vertices.row(v);
    this->Target.Vertices.row(v) = this->Landing(v, candidate).transpose();
    const Local moved = this->Evaluate(v);
    if (accept(moved, current))
    {
      current = moved;
      this->KeepEvaluated(v);
      return true;
    }
    this->Target.Vertices.row(v) = old;
    return false;
  }

  /// Recomputes the cached scaled Jacobians of the hexes around v (after moving v directly).
  void Refresh(int v);

private:
  /// The quality around v at its present position; remembers each hex's values for
  /// KeepEvaluated. Recomputes only the corner values that depend on v.
  Local Evaluate(int v);
  void KeepEvaluated(int v);
  /// Recomputes all nine corner values of hex h and its scaled Jacobian.
  void RefreshHex(int h);
  Eigen::Matrix<double, 8, 3> Corners(int h) const;

  HexMesh& Target;
  const HexSurfaceProjection& Projection;
  Eigen::VectorXd HexQuality;
  /// #H: the nine values whose minimum is each hex's scaled Jacobian (HexCornerScaledJacobians),
  /// so that a move recomputes only the five that depend on the moved vertex.
  std::vector<std::array<double, 9>> CornerValues;
  std::vector<std::vector<int>> HexesOfVertex;
  std::vector<std::vector<int>> MeshNeighbours;
  std::vector<std::vector<int>> SurfaceNeighbours;
  std::vector<std::vector<int>> QuadsOfVertex;
  Quads BoundaryQuads;
  std::vector<std::array<double, 9>> Evaluated; ///< corner values at the evaluated position
};

} // namespace polycubehex
