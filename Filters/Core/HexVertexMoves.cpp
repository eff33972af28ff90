// SPDX-License-Identifier: BSD-3-Clause
#include "HexVertexMoves.h"

#include "HexPadding.h"
#include "HexScaledJacobian.h"

#include <algorithm>
#include <limits>

namespace polycubehex
{
namespace
{
bool Contains(const std::vector<int>& sorted, int value)
{
  return std::binary_search(sorted.begin(), sorted.end(), value);
}
} // namespace

HexVertexMoves::HexVertexMoves(HexMesh& mesh, const HexSurfaceProjection& projection)
  : Target(mesh)
  , Projection(projection)
{
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  this->HexQuality.resize(hexCount);
  this->CornerValues.resize(static_cast<size_t>(hexCount));
  for (int h = 0; h < hexCount; ++h)
  {
    this->RefreshHex(h);
  }
  this->HexesOfVertex.resize(vertexCount);
  this->MeshNeighbours.resize(vertexCount);
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      this->HexesOfVertex[mesh.Cells(h, k)].push_back(h);
    }
    for (const auto& edge : HexEdges)
    {
      const int a = mesh.Cells(h, edge[0]);
      const int b = mesh.Cells(h, edge[1]);
      this->MeshNeighbours[a].push_back(b);
      this->MeshNeighbours[b].push_back(a);
    }
  }
  this->BoundaryQuads = ComputeHexBoundaryQuads(mesh);
  this->SurfaceNeighbours.resize(vertexCount);
  this->QuadsOfVertex.resize(vertexCount);
  for (int q = 0; q < this->BoundaryQuads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = this->BoundaryQuads(q, k);
      const int b = this->BoundaryQuads(q, (k + 1) % 4);
      this->QuadsOfVertex[a].push_back(q);
      this->SurfaceNeighbours[a].push_back(b);
      this->SurfaceNeighbours[b].push_back(a);
    }
  }
  for (auto* lists : { &this->MeshNeighbours, &this->SurfaceNeighbours })
  {
    for (auto& list : *lists)
    {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
  }
}

const std::vector<int>& HexVertexMoves::Neighbours(int v) const
{
  return this->Kind(v) == HexVertexKind::Interior ? this->MeshNeighbours[v]
                                                  : this->SurfaceNeighbours[v];
}

std::vector<int> HexVertexMoves::CurveNeighbours(int v) const
{
  std::vector<int> result;
  if (this->Kind(v) != HexVertexKind::Feature)
  {
    return result;
  }
  const std::vector<int>& charts = this->Projection.Charts(v);
  for (int w : this->SurfaceNeighbours[v])
  {
    if (Contains(this->Projection.Charts(w), charts[0]) &&
      Contains(this->Projection.Charts(w), charts[1]))
    {
      result.push_back(w);
    }
  }
  return result;
}

double HexVertexMoves::MeanEdgeLength(int v) const
{
  const std::vector<int>& around = this->Neighbours(v);
  double length = 0.0;
  for (int w : around)
  {
    length += (this->Target.Vertices.row(w) - this->Target.Vertices.row(v)).norm();
  }
  return around.empty() ? 0.0 : length / static_cast<double>(around.size());
}

HexVertexMoves::Local HexVertexMoves::Cached(int v) const
{
  Local local{ std::numeric_limits<double>::max(), 0.0, 0 };
  const std::vector<int>& hexes = this->HexesOfVertex[v];
  for (int h : hexes)
  {
    const double q = this->HexQuality[h];
    local.Inverted += q <= 0.0 ? 1 : 0;
    local.Min = std::min(local.Min, q);
    local.Mean += q / static_cast<double>(hexes.size());
  }
  return local;
}

std::vector<Eigen::Vector3d> HexVertexMoves::Directions(int v) const
{
  const Points& x = this->Target.Vertices;
  switch (this->Kind(v))
  {
    case HexVertexKind::Interior:
      return { Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ() };
    case HexVertexKind::Surface:
    {
      const Quads& quads = this->BoundaryQuads;
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      for (int q : this->QuadsOfVertex[v])
      {
        normal += (x.row(quads(q, 2)) - x.row(quads(q, 0)))
                    .cross(x.row(quads(q, 3)) - x.row(quads(q, 1)))
                    .transpose();
      }
      const std::vector<int>& around = this->SurfaceNeighbours[v];
      if (!(normal.norm() > 0.0) || around.empty())
      {
        // Any three directions will do; the projection corrects.
        return { Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ() };
      }
      normal.normalize();
      // Any two directions spanning the tangent plane will do; the projection corrects.
      Eigen::Vector3d u = (x.row(around[0]) - x.row(v)).transpose();
      u -= normal * normal.dot(u);
      if (!(u.norm() > 0.0))
      {
        return {};
      }
      u.normalize();
      return { u, normal.cross(u) };
    }
    case HexVertexKind::Feature:
    {
      const std::vector<int> along = this->CurveNeighbours(v);
      if (along.size() < 2)
      {
        return {};
      }
      const Eigen::Vector3d tangent = (x.row(along.front()) - x.row(along.back())).transpose();
      if (!(tangent.norm() > 0.0))
      {
        return {};
      }
      return { tangent.normalized() };
    }
    case HexVertexKind::Fixed:
      break;
  }
  return {};
}

Eigen::Vector3d HexVertexMoves::Landing(int v, const Eigen::Vector3d& p) const
{
  return this->Kind(v) == HexVertexKind::Interior ? p : this->Projection.Project(v, p);
}

Eigen::Matrix<double, 8, 3> HexVertexMoves::Corners(int h) const
{
  Eigen::Matrix<double, 8, 3> corners;
  for (int k = 0; k < 8; ++k)
  {
    corners.row(k) = this->Target.Vertices.row(this->Target.Cells(h, k));
  }
  return corners;
}

void HexVertexMoves::RefreshHex(int h)
{
  std::array<double, 9>& values = this->CornerValues[static_cast<size_t>(h)];
  values = HexCornerScaledJacobians(this->Corners(h));
  this->HexQuality[h] = *std::min_element(values.begin(), values.end());
}

void HexVertexMoves::Refresh(int v)
{
  for (int h : this->HexesOfVertex[v])
  {
    this->RefreshHex(h);
  }
}

HexVertexMoves::Local HexVertexMoves::Evaluate(int v)
{
  Local local{ std::numeric_limits<double>::max(), 0.0, 0 };
  this->Evaluated.clear();
  const std::vector<int>& hexes = this->HexesOfVertex[v];
  for (int h : hexes)
  {
    const Eigen::Matrix<double, 8, 3> corners = this->Corners(h);
    std::array<double, 9> values = this->CornerValues[static_cast<size_t>(h)];
    int where = -1;
    int times = 0;
    for (int k = 0; k < 8; ++k)
    {
      if (this->Target.Cells(h, k) == v)
      {
        where = k;
        ++times;
      }
    }
    if (times == 1)
    {
      // v's own corner, the three corners joined to it by an edge, and the centre.
      for (int which : { where,
             HexCornerNeighbours[where][0],
             HexCornerNeighbours[where][1],
             HexCornerNeighbours[where][2],
             8 })
      {
        values[static_cast<size_t>(which)] = HexCornerScaledJacobian(corners, which);
      }
    }
    else
    {
      values = HexCornerScaledJacobians(corners); // a hex holding v twice: all of them
    }
    this->Evaluated.push_back(values);
    const double q = *std::min_element(values.begin(), values.end());
    local.Inverted += q <= 0.0 ? 1 : 0;
    local.Min = std::min(local.Min, q);
    local.Mean += q / static_cast<double>(hexes.size());
  }
  return local;
}

void HexVertexMoves::KeepEvaluated(int v)
{
  const std::vector<int>& hexes = this->HexesOfVertex[v];
  for (size_t i = 0; i < hexes.size(); ++i)
  {
    const std::array<double, 9>& values = this->Evaluated[i];
    this->CornerValues[static_cast<size_t>(hexes[i])] = values;
    this->HexQuality[hexes[i]] = *std::min_element(values.begin(), values.end());
  }
}

} // namespace polycubehex
