// SPDX-License-Identifier: BSD-3-Clause
#include "HexSmoothing.h"

#include "HexPadding.h"
#include "HexScaledJacobian.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace polycubehex
{
namespace
{
constexpr int HexEdges[12][2] = { { 0, 1 },
  { 1, 2 },
  { 2, 3 },
  { 3, 0 },
  { 4, 5 },
  { 5, 6 },
  { 6, 7 },
  { 7, 4 },
  { 0, 4 },
  { 1, 5 },
  { 2, 6 },
  { 3, 7 } };

/// Closest point of triangle (a, b, c) to p, by the Voronoi region of p (vertex, edge or face).
Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const double d1 = ab.dot(p - a);
  const double d2 = ac.dot(p - a);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return a;
  }
  const double d3 = ab.dot(p - b);
  const double d4 = ac.dot(p - b);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return a + (d1 / (d1 - d3)) * ab;
  }
  const double d5 = ab.dot(p - c);
  const double d6 = ac.dot(p - c);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denominator = va + vb + vc;
  return a + ab * (vb / denominator) + ac * (vc / denominator);
}

Eigen::Vector3d ClosestPointOnSegment(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b)
{
  const Eigen::Vector3d ab = b - a;
  const double length = ab.squaredNorm();
  const double t = length > 0.0 ? std::clamp((p - a).dot(ab) / length, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

/// Surface triangles binned in a uniform grid, so that projecting a vertex looks only at the
/// triangles near it.
class TriangleGrid
{
public:
  TriangleGrid(const Points& vertices, const Triangles& faces, double cellSize)
  {
    const Eigen::Vector3d low = vertices.colwise().minCoeff().transpose();
    const Eigen::Vector3d high = vertices.colwise().maxCoeff().transpose();
    const Eigen::Vector3d extent = (high - low).cwiseMax(1e-12);
    // At most about 2^21 cells.
    this->Cell = std::max(cellSize, std::cbrt(extent.prod() / 2097152.0));
    this->Origin = low;
    for (int a = 0; a < 3; ++a)
    {
      this->Dims[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / this->Cell)));
    }
    std::vector<std::vector<int>> bins(
      static_cast<size_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2]);
    for (int f = 0; f < faces.rows(); ++f)
    {
      Eigen::Vector3d fl = vertices.row(faces(f, 0)).transpose();
      Eigen::Vector3d fh = fl;
      for (int c = 1; c < 3; ++c)
      {
        fl = fl.cwiseMin(vertices.row(faces(f, c)).transpose());
        fh = fh.cwiseMax(vertices.row(faces(f, c)).transpose());
      }
      const std::array<int, 3> from = this->CellOf(fl);
      const std::array<int, 3> to = this->CellOf(fh);
      for (int i = from[0]; i <= to[0]; ++i)
      {
        for (int j = from[1]; j <= to[1]; ++j)
        {
          for (int k = from[2]; k <= to[2]; ++k)
          {
            bins[this->Index(i, j, k)].push_back(f);
          }
        }
      }
    }
    this->Start.assign(bins.size() + 1, 0);
    for (size_t b = 0; b < bins.size(); ++b)
    {
      this->Start[b + 1] = this->Start[b] + static_cast<int>(bins[b].size());
    }
    this->Items.reserve(this->Start.back());
    for (const auto& bin : bins)
    {
      this->Items.insert(this->Items.end(), bin.begin(), bin.end());
    }
  }

  double CellSize() const { return this->Cell; }
  int MaxRing() const { return std::max({ this->Dims[0], this->Dims[1], this->Dims[2] }); }

  /// Calls visit(f) for the triangles binned within `ring` cells of p's cell.
  template<class Visitor>
  void Visit(const Eigen::Vector3d& p, int ring, Visitor&& visit) const
  {
    const std::array<int, 3> centre = this->CellOf(p);
    for (int i = std::max(0, centre[0] - ring); i <= std::min(this->Dims[0] - 1, centre[0] + ring);
         ++i)
    {
      for (int j = std::max(0, centre[1] - ring);
           j <= std::min(this->Dims[1] - 1, centre[1] + ring);
           ++j)
      {
        for (int k = std::max(0, centre[2] - ring);
             k <= std::min(this->Dims[2] - 1, centre[2] + ring);
             ++k)
        {
          const size_t b = this->Index(i, j, k);
          for (int item = this->Start[b]; item < this->Start[b + 1]; ++item)
          {
            visit(this->Items[item]);
          }
        }
      }
    }
  }

private:
  std::array<int, 3> CellOf(const Eigen::Vector3d& p) const
  {
    std::array<int, 3> cell;
    for (int a = 0; a < 3; ++a)
    {
      const double x = std::floor((p[a] - this->Origin[a]) / this->Cell);
      cell[a] = static_cast<int>(std::clamp(x, 0.0, static_cast<double>(this->Dims[a] - 1)));
    }
    return cell;
  }
  size_t Index(int i, int j, int k) const
  {
    return (static_cast<size_t>(k) * this->Dims[1] + j) * this->Dims[0] + i;
  }

  Eigen::Vector3d Origin;
  double Cell = 1.0;
  std::array<int, 3> Dims = { 1, 1, 1 };
  std::vector<int> Start;
  std::vector<int> Items;
};

enum class Kind
{
  Interior,
  Surface,
  Feature,
  Fixed
};

double MeanOf(const Eigen::VectorXd& values)
{
  return values.size() > 0 ? values.mean() : 0.0;
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

Status smoothHexMesh(HexMesh& mesh,
  const std::vector<std::vector<int>>& vertexCharts,
  const HexSmoothingSurface& surface,
  const HexSmoothingParameters& params,
  HexSmoothingResult& result,
  const Progress& progress)
{
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  if (static_cast<int>(vertexCharts.size()) != vertexCount)
  {
    return Status::Failure("smoothing needs the charts of every hex vertex");
  }
  if (surface.FaceChart.size() != static_cast<size_t>(surface.Faces.rows()))
  {
    return Status::Failure("smoothing needs the chart of every surface triangle");
  }
  Eigen::VectorXd quality = ComputeHexScaledJacobians(mesh);
  result.MinBefore = hexCount > 0 ? quality.minCoeff() : 0.0;
  result.MeanBefore = MeanOf(quality);
  result.MinAfter = result.MinBefore;
  result.MeanAfter = result.MeanBefore;
  result.Sweeps = 0;
  if (hexCount == 0 || params.Iterations <= 0)
  {
    return Status::Success();
  }

  // Incidence: hexes and edge neighbours of each vertex; boundary neighbours through quads.
  std::vector<std::vector<int>> hexesOf(vertexCount);
  std::vector<std::vector<int>> neighbours(vertexCount);
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      hexesOf[mesh.Cells(h, k)].push_back(h);
    }
    for (const auto& edge : HexEdges)
    {
      const int a = mesh.Cells(h, edge[0]);
      const int b = mesh.Cells(h, edge[1]);
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  }
  const Quads quads = ComputeHexBoundaryQuads(mesh);
  std::vector<std::vector<int>> surfaceNeighbours(vertexCount);
  std::vector<bool> onBoundary(vertexCount, false);
  std::vector<std::vector<int>> quadsOf(vertexCount);
  for (int q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = quads(q, k);
      quadsOf[a].push_back(q);
      const int b = quads(q, (k + 1) % 4);
      onBoundary[a] = true;
      surfaceNeighbours[a].push_back(b);
      surfaceNeighbours[b].push_back(a);
    }
  }
  for (auto* lists : { &neighbours, &surfaceNeighbours })
  {
    for (auto& list : *lists)
    {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
  }

  // The triangles of each chart and the segments of each feature curve (chart pair).
  std::map<int, std::vector<int>> chartFaces;
  std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    chartFaces[surface.FaceChart[f]].push_back(f);
    for (int e = 0; e < 3; ++e)
    {
      const int a = surface.Faces(f, e);
      const int b = surface.Faces(f, (e + 1) % 3);
      edgeFaces[{ std::min(a, b), std::max(a, b) }].push_back(f);
    }
  }
  std::map<std::pair<int, int>, std::vector<std::array<int, 2>>> featureSegments;
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
      featureSegments[{ std::min(c0, c1), std::max(c0, c1) }].push_back(
        { entry.first.first, entry.first.second });
    }
  }

  std::vector<Kind> kinds(vertexCount, Kind::Interior);
  for (int v = 0; v < vertexCount; ++v)
  {
    const auto& charts = vertexCharts[v];
    if (!onBoundary[v])
    {
      kinds[v] = Kind::Interior;
    }
    else if (charts.size() == 1 && chartFaces.count(charts[0]))
    {
      kinds[v] = Kind::Surface;
    }
    else if (charts.size() == 2 && featureSegments.count({ charts[0], charts[1] }))
    {
      kinds[v] = Kind::Feature;
    }
    else
    {
      kinds[v] = Kind::Fixed;
    }
  }

  // Cells about one hex edge wide.
  double meanEdge = 0.0;
  for (int h = 0; h < hexCount; ++h)
  {
    meanEdge += (mesh.Vertices.row(mesh.Cells(h, 0)) - mesh.Vertices.row(mesh.Cells(h, 6))).norm() /
      (std::sqrt(3.0) * hexCount);
  }
  const TriangleGrid grid(surface.Vertices, surface.Faces, meanEdge);

  auto project = [&](int v, const Eigen::Vector3d& p) -> Eigen::Vector3d
  {
    double best = std::numeric_limits<double>::max();
    Eigen::Vector3d closest = p;
    const auto& charts = vertexCharts[v];
    if (kinds[v] == Kind::Surface)
    {
      const int chart = charts[0];
      auto consider = [&](int f)
      {
        if (surface.FaceChart[f] != chart)
        {
          return;
        }
        const Eigen::Vector3d x = ClosestPointOnTriangle(p,
          surface.Vertices.row(surface.Faces(f, 0)).transpose(),
          surface.Vertices.row(surface.Faces(f, 1)).transpose(),
          surface.Vertices.row(surface.Faces(f, 2)).transpose());
        const double d = (x - p).squaredNorm();
        if (d < best)
        {
          best = d;
          closest = x;
        }
      };
      // The nearest triangle found within `ring` cells is the nearest overall once it is
      // closer than `ring` cells: any closer triangle would have been binned in the searched
      // cells.
      for (int ring = 1;; ring *= 2)
      {
        grid.Visit(p, ring, consider);
        if (std::sqrt(best) <= ring * grid.CellSize())
        {
          break;
        }
        if (ring > grid.MaxRing())
        {
          for (int f : chartFaces.at(chart))
          {
            consider(f);
          }
          break;
        }
      }
    }
    else if (kinds[v] == Kind::Feature)
    {
      for (const auto& segment : featureSegments.at({ charts[0], charts[1] }))
      {
        const Eigen::Vector3d x = ClosestPointOnSegment(p,
          surface.Vertices.row(segment[0]).transpose(),
          surface.Vertices.row(segment[1]).transpose());
        const double d = (x - p).squaredNorm();
        if (d < best)
        {
          best = d;
          closest = x;
        }
      }
    }
    return closest;
  };

  // A feature vertex averages only its neighbours along the same curve (or at its corners).
  auto contains = [](const std::vector<int>& sorted, int value)
  { return std::binary_search(sorted.begin(), sorted.end(), value); };

  // The local quality of a vertex: the smallest and the mean scaled Jacobian of its hexes.
  struct Local
  {
    double Min;
    double Mean;
  };
  // The last evaluation's values per hex, so that an accepted move need not recompute them.
  std::vector<double> evaluated;
  auto evaluate = [&](int v)
  {
    Local local{ std::numeric_limits<double>::max(), 0.0 };
    evaluated.clear();
    for (int h : hexesOf[v])
    {
      const double q = HexScaledJacobian(mesh, h);
      evaluated.push_back(q);
      local.Min = std::min(local.Min, q);
      local.Mean += q / static_cast<double>(hexesOf[v].size());
    }
    return local;
  };
  // The Laplacian step is taken when it raises the mean quality around the vertex without
  // creating a hex worse than both the vertex's worst and the mesh's worst at the start of the
  // sweep; the pattern search maximises the worst hex around the vertex, then the mean. Either
  // way the mesh's minimum never decreases.
  double floor = result.MinBefore;
  auto smoother = [&floor](const Local& a, const Local& b)
  { return a.Mean > b.Mean + 1e-9 && a.Min >= std::min(b.Min, floor); };
  auto better = [](const Local& a, const Local& b)
  { return a.Min > b.Min + 1e-9 || (a.Min >= b.Min && a.Mean > b.Mean + 1e-9); };
  // The same from `quality`, which always holds the current value of every hex.
  auto cached = [&](int v)
  {
    Local local{ std::numeric_limits<double>::max(), 0.0 };
    for (int h : hexesOf[v])
    {
      local.Min = std::min(local.Min, quality[h]);
      local.Mean += quality[h] / static_cast<double>(hexesOf[v].size());
    }
    return local;
  };
  // Moves a vertex to `candidate` (projected for boundary vertices) if `accept` approves.
  auto tryMove = [&](int v, Eigen::Vector3d candidate, Local& current, auto&& accept)
  {
    if (kinds[v] != Kind::Interior)
    {
      candidate = project(v, candidate);
    }
    const Eigen::RowVector3d old = mesh.Vertices.row(v);
    mesh.Vertices.row(v) = candidate.transpose();
    const Local moved = evaluate(v);
    if (accept(moved, current))
    {
      current = moved;
      for (size_t i = 0; i < hexesOf[v].size(); ++i)
      {
        quality[hexesOf[v][i]] = evaluated[i];
      }
      return true;
    }
    mesh.Vertices.row(v) = old;
    return false;
  };

  std::vector<Eigen::Vector3d> along; // feature neighbours, for the curve's tangent
  std::vector<Eigen::Vector3d> directions;
  for (int sweep = 0; sweep < params.Iterations; ++sweep)
  {
    if (!ReportProgress(progress, static_cast<double>(sweep) / params.Iterations))
    {
      return Status::Failure("hex smoothing aborted");
    }
    for (int v = 0; v < vertexCount; ++v)
    {
      if (kinds[v] == Kind::Fixed)
      {
        continue;
      }
      const std::vector<int>& around =
        kinds[v] == Kind::Interior ? neighbours[v] : surfaceNeighbours[v];
      Eigen::Vector3d target = Eigen::Vector3d::Zero();
      along.clear();
      int count = 0;
      double edgeLength = 0.0;
      for (int w : around)
      {
        edgeLength += (mesh.Vertices.row(w) - mesh.Vertices.row(v)).norm();
        if (kinds[v] == Kind::Feature &&
          !(contains(vertexCharts[w], vertexCharts[v][0]) &&
            contains(vertexCharts[w], vertexCharts[v][1])))
        {
          continue;
        }
        target += mesh.Vertices.row(w).transpose();
        along.push_back(mesh.Vertices.row(w).transpose());
        ++count;
      }
      if (count < 2)
      {
        continue;
      }
      target /= count;
      edgeLength /= static_cast<double>(around.size());
      const Eigen::Vector3d old = mesh.Vertices.row(v).transpose();
      Local current = cached(v);

      // 1. Laplacian: towards the mean of the neighbours, full step, then half, then a quarter.
      for (double step : { 1.0, 0.5, 0.25 })
      {
        if (tryMove(v, old + step * (target - old), current, smoother))
        {
          break;
        }
      }

      // 2. Pattern search near the worst hexes: axis moves, in the tangent plane on the surface
      //    and along the curve on a feature, shrinking the step while nothing improves.
      if (current.Min >= floor + params.WorstBand && current.Min >= params.UntangleBelow)
      {
        continue;
      }
      directions.clear();
      if (kinds[v] == Kind::Interior)
      {
        directions = {
          Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()
        };
      }
      else if (kinds[v] == Kind::Surface)
      {
        Eigen::Vector3d normal = Eigen::Vector3d::Zero();
        for (int q : quadsOf[v])
        {
          normal += (mesh.Vertices.row(quads(q, 2)) - mesh.Vertices.row(quads(q, 0)))
                      .cross(mesh.Vertices.row(quads(q, 3)) - mesh.Vertices.row(quads(q, 1)))
                      .transpose();
        }
        // Any two directions spanning the tangent plane will do; the projection corrects.
        Eigen::Vector3d u = (mesh.Vertices.row(around[0]) - mesh.Vertices.row(v)).transpose();
        if (normal.norm() > 0.0)
        {
          normal.normalize();
          u = (u - normal * normal.dot(u)).normalized();
          directions = { u, normal.cross(u) };
        }
        else
        {
          directions = {
            Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()
          };
        }
      }
      else
      {
        const Eigen::Vector3d tangent = along.front() - along.back();
        if (tangent.norm() > 0.0)
        {
          directions = { tangent.normalized() };
        }
      }
      int moves = 0;
      for (double step = 0.25 * edgeLength; step > edgeLength / 256.0 && moves < 24; ++moves)
      {
        bool improved = false;
        for (const Eigen::Vector3d& d : directions)
        {
          const Eigen::Vector3d here = mesh.Vertices.row(v).transpose();
          improved = tryMove(v, here + step * d, current, better) ||
            tryMove(v, here - step * d, current, better) || improved;
        }
        if (!improved)
        {
          step *= 0.5;
        }
      }
    }
    ++result.Sweeps;
    const double mean = MeanOf(quality);
    const double minimum = quality.minCoeff();
    const bool progressed =
      mean - result.MeanAfter >= params.Tolerance || minimum - result.MinAfter >= params.Tolerance;
    result.MinAfter = minimum;
    result.MeanAfter = mean;
    floor = minimum;
    if (!progressed)
    {
      break;
    }
  }
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
