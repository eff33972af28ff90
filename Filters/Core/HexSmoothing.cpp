// SPDX-License-Identifier: BSD-3-Clause
#include "HexSmoothing.h"

#include "HexPadding.h"
#include "HexScaledJacobian.h"
#include "HexSurfaceProjection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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

double MeanOf(const Eigen::VectorXd& values)
{
  return values.size() > 0 ? values.mean() : 0.0;
}
} // namespace

Status smoothHexMesh(HexMesh& mesh,
  const std::vector<std::vector<int>>& vertexCharts,
  const HexSmoothingSurface& surface,
  const HexSmoothingParameters& params,
  HexSmoothingResult& result,
  const Progress& progress)
{
  if (static_cast<Eigen::Index>(vertexCharts.size()) != mesh.Vertices.rows())
  {
    return Status::Failure("smoothing needs the charts of every hex vertex");
  }
  if (surface.FaceChart.size() != static_cast<size_t>(surface.Faces.rows()))
  {
    return Status::Failure("smoothing needs the chart of every surface triangle");
  }
  const HexSurfaceProjection projection(surface, vertexCharts, mesh, params.SoftFeatureAngle);
  return smoothHexMesh(mesh, projection, params, result, progress);
}

Status smoothHexMesh(HexMesh& mesh,
  const HexSurfaceProjection& projection,
  const HexSmoothingParameters& params,
  HexSmoothingResult& result,
  const Progress& progress)
{
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  if (projection.VertexCount() != vertexCount)
  {
    return Status::Failure("smoothing needs the kind of every hex vertex");
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
  std::vector<std::vector<int>> quadsOf(vertexCount);
  for (int q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = quads(q, k);
      quadsOf[a].push_back(q);
      const int b = quads(q, (k + 1) % 4);
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

  auto project = [&projection](int v, const Eigen::Vector3d& p)
  { return projection.Project(v, p); };
  auto kind = [&projection](int v) { return projection.Kind(v); };

  // A feature vertex averages only its neighbours along the same curve (or at its corners).
  auto contains = [](const std::vector<int>& sorted, int value)
  { return std::binary_search(sorted.begin(), sorted.end(), value); };

  // The local quality of a vertex: the smallest and the mean scaled Jacobian of its hexes.
  struct Local
  {
    double Min;
    double Mean;
    int Inverted; ///< hexes with scaled Jacobian <= 0
  };
  // The last evaluation's values per hex, so that an accepted move need not recompute them.
  std::vector<double> evaluated;
  auto evaluate = [&](int v)
  {
    Local local{ std::numeric_limits<double>::max(), 0.0, 0 };
    evaluated.clear();
    for (int h : hexesOf[v])
    {
      const double q = HexScaledJacobian(mesh, h);
      evaluated.push_back(q);
      local.Inverted += q <= 0.0 ? 1 : 0;
      local.Min = std::min(local.Min, q);
      local.Mean += q / static_cast<double>(hexesOf[v].size());
    }
    return local;
  };
  // The Laplacian step is taken when it raises the mean quality around the vertex without
  // creating a hex worse than both the vertex's worst and the mesh's worst at the start of the
  // sweep; the pattern search maximises the worst hex around the vertex, then the mean. Either
  // way the mesh's minimum never decreases. On a tangled mesh (a negative floor) neither may
  // invert another hex around the vertex: a move that keeps the worst hex but inverts a good
  // one above the floor trades validity for the mean (rockerarm Uniform gained inverted
  // interior hexes so).
  double floor = result.MinBefore;
  auto smoother = [&floor](const Local& a, const Local& b)
  {
    return a.Mean > b.Mean + 1e-9 && a.Min >= std::min(b.Min, floor) && a.Inverted <= b.Inverted;
  };
  auto better = [](const Local& a, const Local& b)
  {
    return a.Inverted < b.Inverted ||
      (a.Inverted == b.Inverted &&
        (a.Min > b.Min + 1e-9 || (a.Min >= b.Min && a.Mean > b.Mean + 1e-9)));
  };
  // The same from `quality`, which always holds the current value of every hex.
  auto cached = [&](int v)
  {
    Local local{ std::numeric_limits<double>::max(), 0.0, 0 };
    for (int h : hexesOf[v])
    {
      local.Inverted += quality[h] <= 0.0 ? 1 : 0;
      local.Min = std::min(local.Min, quality[h]);
      local.Mean += quality[h] / static_cast<double>(hexesOf[v].size());
    }
    return local;
  };
  // Moves a vertex to `candidate` (projected for boundary vertices) if `accept` approves.
  auto tryMove = [&](int v, Eigen::Vector3d candidate, Local& current, auto&& accept)
  {
    if (kind(v) != HexVertexKind::Interior)
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
      if (kind(v) == HexVertexKind::Fixed)
      {
        continue;
      }
      const std::vector<int>& around =
        kind(v) == HexVertexKind::Interior ? neighbours[v] : surfaceNeighbours[v];
      Eigen::Vector3d target = Eigen::Vector3d::Zero();
      along.clear();
      int count = 0;
      double edgeLength = 0.0;
      for (int w : around)
      {
        edgeLength += (mesh.Vertices.row(w) - mesh.Vertices.row(v)).norm();
        if (kind(v) == HexVertexKind::Feature &&
          !(contains(projection.Charts(w), projection.Charts(v)[0]) &&
            contains(projection.Charts(w), projection.Charts(v)[1])))
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
      if (kind(v) == HexVertexKind::Interior)
      {
        directions = {
          Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()
        };
      }
      else if (kind(v) == HexVertexKind::Surface)
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
