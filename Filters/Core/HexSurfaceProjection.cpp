// SPDX-License-Identifier: BSD-3-Clause
#include "HexSurfaceProjection.h"

#include "DisjointSets.h"
#include "HexPadding.h"
#include "HexScaledJacobian.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace polycubehex
{
namespace
{
Eigen::Vector3d ClosestPointOnSegment(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b)
{
  const Eigen::Vector3d ab = b - a;
  const double length = ab.squaredNorm();
  const double t = length > 0.0 ? std::clamp((p - a).dot(ab) / length, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

} // namespace

HexSmoothingSurface MakeChartSurface(const Points& vertices,
  const Tets& cells,
  const Tets& faceChart,
  const std::vector<int>& chartIds,
  const std::vector<int>& identity)
{
  constexpr int FaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };
  HexSmoothingSurface surface;
  surface.Vertices = vertices;
  std::vector<std::array<int, 3>> faces;
  for (int t = 0; t < cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int chart = faceChart(t, k);
      if (chart < 0)
      {
        continue;
      }
      std::array<int, 3> face;
      for (int i = 0; i < 3; ++i)
      {
        const int v = cells(t, FaceTable[k][i]);
        face[i] = identity.empty() ? v : identity[static_cast<size_t>(v)];
      }
      faces.push_back(face);
      surface.FaceChart.push_back(chartIds.empty() ? chart : chartIds[static_cast<size_t>(chart)]);
    }
  }
  surface.Faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
  {
    for (int c = 0; c < 3; ++c)
    {
      surface.Faces(static_cast<Eigen::Index>(f), c) = faces[f][c];
    }
  }
  return surface;
}

HexSurfaceProjection::HexSurfaceProjection(const HexSmoothingSurface& surface,
  const std::vector<std::vector<int>>& vertexCharts,
  const HexMesh& mesh,
  double softAngle)
  : Surface(surface)
  , VertexCharts(&vertexCharts)
  , CellSize(MeanHexEdgeLength(mesh))
{
  const int faceCount = static_cast<int>(surface.Faces.rows());
  std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
  int chartCount = 0;
  for (int f = 0; f < faceCount; ++f)
  {
    this->ChartFaces[surface.FaceChart[f]].push_back(f);
    chartCount = std::max(chartCount, surface.FaceChart[f] + 1);
    const Eigen::Vector3d a = surface.Vertices.row(surface.Faces(f, 0)).transpose();
    this->FaceNormal.push_back((surface.Vertices.row(surface.Faces(f, 1)).transpose() - a)
                                 .cross(surface.Vertices.row(surface.Faces(f, 2)).transpose() - a)
                                 .normalized());
    for (int e = 0; e < 3; ++e)
    {
      const int a = surface.Faces(f, e);
      const int b = surface.Faces(f, (e + 1) % 3);
      edgeFaces[{ std::min(a, b), std::max(a, b) }].push_back(f);
    }
  }
  // How sharp the input is at each triangle's edges.
  this->EdgeCosine.assign(static_cast<size_t>(faceCount), { 1.0, 1.0, 1.0 });
  for (int f = 0; f < faceCount; ++f)
  {
    for (int e = 0; e < 3; ++e)
    {
      const int a = surface.Faces(f, e);
      const int b = surface.Faces(f, (e + 1) % 3);
      const std::vector<int>& both = edgeFaces[{ std::min(a, b), std::max(a, b) }];
      if (both.size() == 2)
      {
        this->EdgeCosine[static_cast<size_t>(f)][static_cast<size_t>(e)] =
          this->FaceNormal[static_cast<size_t>(both[0])].dot(
            this->FaceNormal[static_cast<size_t>(both[1])]);
      }
    }
  }
  // The segments of each feature curve (chart pair).
  for (const auto& entry : edgeFaces)
  {
    if (entry.second.size() != 2)
    {
      continue;
    }
    const int c0 = surface.FaceChart[entry.second[0]];
    const int c1 = surface.FaceChart[entry.second[1]];
    if (c0 != c1)
    {
      this->FeatureSegments[{ std::min(c0, c1), std::max(c0, c1) }].push_back(
        { entry.first.first, entry.first.second });
    }
  }
  if (faceCount > 0)
  {
    this->Grid = std::make_shared<const TriangleGrid>(surface.Vertices, surface.Faces, this->CellSize);
  }
  this->ChartParent.resize(static_cast<size_t>(chartCount));
  for (int c = 0; c < chartCount; ++c)
  {
    this->ChartParent[static_cast<size_t>(c)] = c;
  }
  this->SoftFace.assign(static_cast<size_t>(faceCount), 0);

  // Kinds. A vertex on two or more charts is released where the surface is smooth about it.
  const size_t vertexCount = vertexCharts.size();
  std::vector<bool> onBoundary(vertexCount, false);
  const Quads quads = ComputeHexBoundaryQuads(mesh);
  for (Eigen::Index q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (quads(q, k) < static_cast<int>(vertexCount))
      {
        onBoundary[static_cast<size_t>(quads(q, k))] = true;
      }
    }
  }
  const double cosine = std::cos(softAngle * 3.14159265358979323846 / 180.0);
  this->VertexKinds.assign(vertexCount, HexVertexKind::Interior);
  this->VertexChart.assign(vertexCount, -1);
  this->VertexCurve.assign(vertexCount, { -1, -1 });
  this->ReferenceNormal.assign(vertexCount, Eigen::Vector3d::Zero());
  for (size_t v = 0; v < vertexCount; ++v)
  {
    const auto& charts = vertexCharts[v];
    if (!onBoundary[v])
    {
      continue;
    }
    const bool known = !charts.empty() &&
      std::all_of(charts.begin(),
        charts.end(),
        [this](int chart) { return chart >= 0 && this->ChartFaces.count(chart) > 0; });
    HexVertexKind& kind = this->VertexKinds[v];
    if (known && charts.size() == 1)
    {
      kind = HexVertexKind::Surface;
      this->VertexChart[v] = charts.front();
      this->SetReferenceNormal(
        static_cast<int>(v), mesh.Vertices.row(static_cast<Eigen::Index>(v)).transpose());
      continue;
    }
    kind = charts.size() == 2 && this->FeatureSegments.count({ charts[0], charts[1] })
      ? HexVertexKind::Feature
      : HexVertexKind::Fixed;
    if (kind == HexVertexKind::Feature)
    {
      this->VertexCurve[v] = { charts[0], charts[1] };
    }
    const Eigen::Vector3d p = mesh.Vertices.row(static_cast<Eigen::Index>(v)).transpose();
    if (known && softAngle > 0.0 && this->Smooth(p, charts, this->CellSize, cosine))
    {
      this->Release(static_cast<int>(v), p);
    }
  }
}

void HexSurfaceProjection::SetReferenceNormal(int v, const Eigen::Vector3d& p)
{
  const auto& charts = this->Charts(v);
  Eigen::Vector3d closest;
  const int nearest = this->Nearest(
    p,
    [&](int f)
    {
      return charts.empty() ||
        std::find(charts.begin(), charts.end(), this->Surface.FaceChart[f]) != charts.end();
    },
    closest);
  this->ReferenceNormal[static_cast<size_t>(v)] =
    nearest >= 0 ? this->FaceNormal[static_cast<size_t>(nearest)] : Eigen::Vector3d::Zero();
}

int HexSurfaceProjection::Region(int chart) const
{
  while (this->ChartParent[static_cast<size_t>(chart)] != chart)
  {
    chart = this->ChartParent[static_cast<size_t>(chart)];
  }
  return chart;
}

bool HexSurfaceProjection::SmoothAt(int v, const Eigen::Vector3d& p, double angle) const
{
  return this->Grid && angle > 0.0 &&
    this->Smooth(
      p, this->Charts(v), this->CellSize, std::cos(angle * 3.14159265358979323846 / 180.0));
}

bool HexSurfaceProjection::FreeOfSharpEdgesAt(int v, const Eigen::Vector3d& p, double angle) const
{
  if (!this->Grid || !(angle > 0.0))
  {
    return false;
  }
  const HexSmoothingSurface& surface = this->Surface;
  const std::vector<int>& charts = this->Charts(v);
  const double cosine = std::cos(angle * 3.14159265358979323846 / 180.0);
  bool seen = false;
  bool sharp = false;
  // The grid's cells are at least a hex edge wide, so one ring holds every triangle within it.
  this->Grid->Visit(p,
    1,
    -1,
    [&](int f)
    {
      if (sharp || std::find(charts.begin(), charts.end(), surface.FaceChart[f]) == charts.end() ||
        (ClosestPointOnTriangle(p,
           surface.Vertices.row(surface.Faces(f, 0)).transpose(),
           surface.Vertices.row(surface.Faces(f, 1)).transpose(),
           surface.Vertices.row(surface.Faces(f, 2)).transpose()) -
          p)
            .norm() > this->CellSize)
      {
        return;
      }
      seen = true;
      for (int e = 0; e < 3 && !sharp; ++e)
      {
        const Eigen::Vector3d a = surface.Vertices.row(surface.Faces(f, e)).transpose();
        const Eigen::Vector3d b = surface.Vertices.row(surface.Faces(f, (e + 1) % 3)).transpose();
        sharp = this->EdgeCosine[static_cast<size_t>(f)][static_cast<size_t>(e)] < cosine &&
          (ClosestPointOnSegment(p, a, b) - p).norm() <= this->CellSize;
      }
    });
  return seen && !sharp;
}

bool HexSurfaceProjection::Release(int v, const Eigen::Vector3d& p)
{
  HexVertexKind& kind = this->VertexKinds[static_cast<size_t>(v)];
  const auto& charts = this->Charts(v);
  if ((kind != HexVertexKind::Feature && kind != HexVertexKind::Fixed) || !this->Grid ||
    !std::all_of(charts.begin(),
      charts.end(),
      [this](int chart) { return chart >= 0 && this->ChartFaces.count(chart) > 0; }))
  {
    return false;
  }
  // A boundary vertex that knows no chart may go anywhere on the surface.
  this->VertexChart[static_cast<size_t>(v)] = charts.empty() ? -1 : charts.front();
  this->SetReferenceNormal(v, p);
  kind = HexVertexKind::Surface;
  ++this->Released;
  for (int chart : charts)
  {
    const int r0 = FindRoot(this->ChartParent, chart);
    const int r1 = FindRoot(this->ChartParent, charts.front());
    this->ChartParent[static_cast<size_t>(std::max(r0, r1))] = std::min(r0, r1);
  }
  // The soft zone: triangles within three hex edges, where Surface vertices may cross from their
  // chart to the others of its region.
  const HexSmoothingSurface& surface = this->Surface;
  this->Grid->Visit(p,
    3,
    -1,
    [&](int f)
    {
      if ((ClosestPointOnTriangle(p,
             surface.Vertices.row(surface.Faces(f, 0)).transpose(),
             surface.Vertices.row(surface.Faces(f, 1)).transpose(),
             surface.Vertices.row(surface.Faces(f, 2)).transpose()) -
            p)
            .norm() <= 3.0 * this->CellSize)
      {
        this->SoftFace[static_cast<size_t>(f)] = 1;
      }
    });
  return true;
}

bool HexSurfaceProjection::Smooth(const Eigen::Vector3d& p,
  const std::vector<int>& charts,
  double radius,
  double cosine) const
{
  const HexSmoothingSurface& surface = this->Surface;
  std::vector<Eigen::Vector3d> normals;
  std::vector<bool> seen(charts.size(), false);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  // The grid's cells are at least `radius` wide, so one ring holds every triangle within it.
  this->Grid->Visit(p,
    1,
    -1,
    [&](int f)
    {
      const auto found = std::find(charts.begin(), charts.end(), surface.FaceChart[f]);
      if (found == charts.end())
      {
        return;
      }
      const Eigen::Vector3d a = surface.Vertices.row(surface.Faces(f, 0)).transpose();
      const Eigen::Vector3d b = surface.Vertices.row(surface.Faces(f, 1)).transpose();
      const Eigen::Vector3d c = surface.Vertices.row(surface.Faces(f, 2)).transpose();
      if ((ClosestPointOnTriangle(p, a, b, c) - p).norm() > radius)
      {
        return;
      }
      const Eigen::Vector3d normal = (b - a).cross(c - a); // twice the area
      if (normal.norm() > 0.0)
      {
        seen[static_cast<size_t>(found - charts.begin())] = true;
        normals.push_back(normal.normalized());
        mean += normal;
      }
    });
  if (std::find(seen.begin(), seen.end(), false) != seen.end() || !(mean.norm() > 0.0))
  {
    return false;
  }
  mean.normalize();
  return std::all_of(normals.begin(),
    normals.end(),
    [&mean, cosine](const Eigen::Vector3d& n) { return n.dot(mean) >= cosine; });
}

HexSurfaceProjection::~HexSurfaceProjection() = default;
HexSurfaceProjection::HexSurfaceProjection(const HexSurfaceProjection&) = default;

Eigen::Vector3d HexSurfaceProjection::Project(int v,
  const Eigen::Vector3d& p,
  Eigen::Vector3d* direction) const
{
  const HexSmoothingSurface& surface = this->Surface;
  Eigen::Vector3d closest = p;
  Eigen::Vector3d along = Eigen::Vector3d::Zero();
  const HexVertexKind kind = this->Kind(v);
  if (kind == HexVertexKind::Surface)
  {
    const std::vector<int>& charts = this->Charts(v);
    const int first = this->VertexChart[static_cast<size_t>(v)];
    const int region = first >= 0 ? this->Region(first) : -1;
    const Eigen::Vector3d& reference = this->ReferenceNormal[static_cast<size_t>(v)];
    const int nearest = this->Nearest(
      p,
      [&](int f)
      {
        // Beyond its own chart a vertex takes only triangles facing its side of the surface,
        // never the far side of a thin part.
        const int chart = surface.FaceChart[f];
        const bool own = charts.size() == 1 && chart == first;
        return own ||
          ((first < 0 ||
             (charts.size() > 1 || this->SoftFace[static_cast<size_t>(f)]) &&
               this->Region(chart) == region) &&
            this->FaceNormal[static_cast<size_t>(f)].dot(reference) > 0.0);
      },
      closest);
    if (direction && nearest >= 0)
    {
      const Eigen::Vector3d a = surface.Vertices.row(surface.Faces(nearest, 0)).transpose();
      along = (surface.Vertices.row(surface.Faces(nearest, 1)).transpose() - a)
                .cross(surface.Vertices.row(surface.Faces(nearest, 2)).transpose() - a);
    }
  }
  else if (kind == HexVertexKind::Feature)
  {
    double best = std::numeric_limits<double>::max();
    for (const auto& segment : this->FeatureSegments.at(this->VertexCurve[static_cast<size_t>(v)]))
    {
      const Eigen::Vector3d a = surface.Vertices.row(segment[0]).transpose();
      const Eigen::Vector3d b = surface.Vertices.row(segment[1]).transpose();
      const Eigen::Vector3d x = ClosestPointOnSegment(p, a, b);
      const double d = (x - p).squaredNorm();
      if (d < best)
      {
        best = d;
        closest = x;
        along = b - a;
      }
    }
  }
  if (direction)
  {
    const double length = along.norm();
    *direction = length > 0.0 ? Eigen::Vector3d(along / length) : Eigen::Vector3d::Zero();
  }
  return closest;
}

} // namespace polycubehex
