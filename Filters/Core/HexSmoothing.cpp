// SPDX-License-Identifier: BSD-3-Clause
#include "HexSmoothing.h"

#include "HexScaledJacobian.h"
#include "HexSurfaceProjection.h"
#include "HexVertexMoves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <vector>

namespace polycubehex
{
namespace
{
double MeanOf(const Eigen::VectorXd& values)
{
  return values.size() > 0 ? values.mean() : 0.0;
}

using Local = HexVertexMoves::Local;

/// Accepts a move that does not lower the vertex's worst hex, nor invert another around it, and
/// that first of all has fewer inverted hexes, then a higher minimum, then a higher mean.
bool Better(const Local& a, const Local& b)
{
  return a.Inverted < b.Inverted ||
    (a.Inverted == b.Inverted &&
      (a.Min > b.Min + 1e-9 || (a.Min >= b.Min && a.Mean > b.Mean + 1e-9)));
}

/// Gauss-Seidel sweeps of Laplacian steps, with `meanStep` > 0 steps of that length (a fraction
/// of the vertex's mean edge length) for the mean along each vertex's directions, and near the
/// worst hexes pattern searches. Returns false when the caller aborted.
bool RunSweeps(HexVertexMoves& moves,
  int sweeps,
  double meanStep,
  const HexSmoothingParameters& params,
  HexSmoothingResult& result,
  const std::function<bool(double)>& report)
{
  const Points& x = moves.Mesh().Vertices;
  // The Laplacian step is taken when it raises the mean quality around the vertex without
  // creating a hex worse than both the vertex's worst and the mesh's worst at the start of the
  // sweep; the pattern search maximises the worst hex around the vertex, then the mean. Either
  // way the mesh's minimum never decreases. On a tangled mesh (a negative floor) neither may
  // invert another hex around the vertex: a move that keeps the worst hex but inverts a good
  // one above the floor trades validity for the mean (rockerarm Uniform gained inverted
  // interior hexes so).
  double floor = moves.Quality().minCoeff();
  auto smoother = [&floor](const Local& a, const Local& b)
  { return a.Mean > b.Mean + 1e-9 && a.Min >= std::min(b.Min, floor) && a.Inverted <= b.Inverted; };
  for (int sweep = 0; sweep < sweeps; ++sweep)
  {
    if (!report(static_cast<double>(sweep) / sweeps))
    {
      return false;
    }
    for (int v = 0; v < moves.VertexCount(); ++v)
    {
      if (moves.Kind(v) == HexVertexKind::Fixed)
      {
        continue;
      }
      // A feature vertex averages only its neighbours along the same curve (or at its corners).
      const std::vector<int> along = moves.CurveNeighbours(v);
      const std::vector<int>& averaged =
        moves.Kind(v) == HexVertexKind::Feature ? along : moves.Neighbours(v);
      if (averaged.size() < 2)
      {
        continue;
      }
      Eigen::Vector3d target = Eigen::Vector3d::Zero();
      for (int w : averaged)
      {
        target += x.row(w).transpose();
      }
      target /= static_cast<double>(averaged.size());
      const double edgeLength = moves.MeanEdgeLength(v);
      const Eigen::Vector3d old = x.row(v).transpose();
      Local current = moves.Cached(v);

      // 1. Laplacian: towards the mean of the neighbours, full step, then half, then a quarter.
      for (double step : { 1.0, 0.5, 0.25 })
      {
        if (moves.TryMove(v, old + step * (target - old), current, smoother))
        {
          break;
        }
      }

      // 2. Steps along its directions for the mean, one length, under the same rule.
      if (meanStep > 0.0 && current.Mean < params.MeanSearchBelow)
      {
        const double step = meanStep * edgeLength;
        for (const Eigen::Vector3d& d : moves.Directions(v))
        {
          const Eigen::Vector3d here = x.row(v).transpose();
          if (!moves.TryMove(v, here + step * d, current, smoother))
          {
            moves.TryMove(v, here - step * d, current, smoother);
          }
        }
      }

      // 3. Pattern search near the worst hexes: axis moves, in the tangent plane on the surface
      //    and along the curve on a feature, shrinking the step while nothing improves.
      if (current.Min >= floor + params.WorstBand && current.Min >= params.UntangleBelow)
      {
        continue;
      }
      const std::vector<Eigen::Vector3d> directions = moves.Directions(v);
      int tries = 0;
      for (double step = 0.25 * edgeLength; step > edgeLength / 256.0 && tries < 24; ++tries)
      {
        bool improved = false;
        for (const Eigen::Vector3d& d : directions)
        {
          const Eigen::Vector3d here = x.row(v).transpose();
          improved = moves.TryMove(v, here + step * d, current, Better) ||
            moves.TryMove(v, here - step * d, current, Better) || improved;
        }
        if (!improved)
        {
          step *= 0.5;
        }
      }
    }
    ++result.Sweeps;
    const double mean = moves.Quality().mean();
    const double minimum = moves.Quality().minCoeff();
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
  return true;
}

/// The nine corner values of hex h (HexCornerScaledJacobians).
std::array<double, 9> CornerValues(const HexMesh& mesh, int h)
{
  Eigen::Matrix<double, 8, 3> corners;
  for (int k = 0; k < 8; ++k)
  {
    corners.row(k) = mesh.Vertices.row(mesh.Cells(h, k));
  }
  return HexCornerScaledJacobians(corners);
}

/// Soft minimum of the corner values of the hexes around v with v at p: lowest - log(sum
/// exp(-sharpness (value - lowest))) / sharpness, smooth where the hard minimum has kinks.
double SoftMinimumAt(HexVertexMoves& moves, int v, const Eigen::Vector3d& p, double sharpness)
{
  HexMesh& mesh = moves.Mesh();
  const Eigen::RowVector3d old = mesh.Vertices.row(v);
  mesh.Vertices.row(v) = p.transpose();
  std::vector<double> values;
  values.reserve(9 * moves.HexesOf(v).size());
  double lowest = std::numeric_limits<double>::max();
  for (int h : moves.HexesOf(v))
  {
    for (double value : CornerValues(mesh, h))
    {
      values.push_back(value);
      lowest = std::min(lowest, value);
    }
  }
  mesh.Vertices.row(v) = old;
  double sum = 0.0;
  for (double value : values)
  {
    sum += std::exp(-sharpness * (value - lowest));
  }
  return lowest - std::log(sum) / sharpness;
}

/// One vertex climbs the soft minimum of its hexes: central differences along its directions,
/// then the longest of a few halving steps that Better accepts.
void ClimbVertex(HexVertexMoves& moves, int v, const HexSmoothingParameters& params)
{
  const std::vector<Eigen::Vector3d> directions = moves.Directions(v);
  const double edgeLength = moves.MeanEdgeLength(v);
  if (directions.empty() || !(edgeLength > 0.0))
  {
    return;
  }
  Local current = moves.Cached(v);
  const double delta = 1e-4 * edgeLength;
  for (int step = 0; step < params.PolishAscentSteps; ++step)
  {
    const Eigen::Vector3d here = moves.Mesh().Vertices.row(v).transpose();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& d : directions)
    {
      const double up =
        SoftMinimumAt(moves, v, moves.Landing(v, here + delta * d), params.PolishSharpness);
      const double down =
        SoftMinimumAt(moves, v, moves.Landing(v, here - delta * d), params.PolishSharpness);
      gradient += d * (up - down) / (2.0 * delta);
    }
    if (!(gradient.norm() > 0.0))
    {
      return;
    }
    gradient.normalize();
    bool moved = false;
    for (double length = 0.25 * edgeLength; length > edgeLength / 1024.0 && !moved; length *= 0.5)
    {
      moved = moves.TryMove(v, here + length * gradient, current, Better);
    }
    if (!moved)
    {
      return;
    }
  }
}

/// All of `vertices` step together along the gradient of the soft minimum of every hex they
/// touch (the softmax weights frozen at the start), projected back where they may be; kept
/// when the touched hexes' minimum rises and none more is inverted. False when no step was kept.
bool ClimbTogether(HexVertexMoves& moves,
  const std::vector<int>& vertices,
  const HexSmoothingParameters& params)
{
  HexMesh& mesh = moves.Mesh();
  std::vector<int> touched;
  for (int v : vertices)
  {
    touched.insert(touched.end(), moves.HexesOf(v).begin(), moves.HexesOf(v).end());
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  const double lowest = moves.Quality().minCoeff();
  std::map<int, std::array<double, 9>> weights;
  for (int h : touched)
  {
    const std::array<double, 9> values = CornerValues(mesh, h);
    for (int c = 0; c < 9; ++c)
    {
      weights[h][c] = std::exp(-params.PolishSharpness * (values[c] - lowest));
    }
  }
  // The weighted sum of the corner values around v; its gradient in v is the soft minimum's,
  // up to a positive factor, while the weights stay frozen.
  auto weightedSum = [&](int v)
  {
    double sum = 0.0;
    for (int h : moves.HexesOf(v))
    {
      const std::array<double, 9> values = CornerValues(mesh, h);
      for (int c = 0; c < 9; ++c)
      {
        sum += weights[h][c] * values[c];
      }
    }
    return sum;
  };
  std::vector<Eigen::Vector3d> start(vertices.size());
  std::vector<Eigen::Vector3d> gradient(vertices.size(), Eigen::Vector3d::Zero());
  double largest = 0.0;
  double edgeLength = 0.0;
  for (size_t i = 0; i < vertices.size(); ++i)
  {
    const int v = vertices[i];
    start[i] = mesh.Vertices.row(v).transpose();
    const double length = moves.MeanEdgeLength(v);
    edgeLength = std::max(edgeLength, length);
    const double delta = 1e-5 * length;
    for (int axis = 0; axis < 3; ++axis)
    {
      mesh.Vertices(v, axis) = start[i][axis] + delta;
      const double up = weightedSum(v);
      mesh.Vertices(v, axis) = start[i][axis] - delta;
      const double down = weightedSum(v);
      mesh.Vertices(v, axis) = start[i][axis];
      gradient[i][axis] = (up - down) / (2.0 * delta);
    }
    largest = std::max(largest, gradient[i].norm());
  }
  if (!(largest > 0.0))
  {
    return false;
  }
  auto touchedQuality = [&]()
  {
    Local local{ std::numeric_limits<double>::max(), 0.0, 0 };
    for (int h : touched)
    {
      const double q = HexScaledJacobian(mesh, h);
      local.Inverted += q <= 0.0 ? 1 : 0;
      local.Min = std::min(local.Min, q);
    }
    return local;
  };
  const Local before = touchedQuality();
  // The largest vertex moves a tenth of an edge at most, then halving.
  for (double length = 0.1 * edgeLength; length > 1e-4 * edgeLength; length *= 0.5)
  {
    for (size_t i = 0; i < vertices.size(); ++i)
    {
      const int v = vertices[i];
      mesh.Vertices.row(v) =
        moves.Landing(v, start[i] + length * gradient[i] / largest).transpose();
    }
    const Local after = touchedQuality();
    if (after.Inverted <= before.Inverted && after.Min > before.Min + 1e-9)
    {
      for (int v : vertices)
      {
        moves.Refresh(v);
      }
      return true;
    }
  }
  for (size_t i = 0; i < vertices.size(); ++i)
  {
    mesh.Vertices.row(vertices[i]) = start[i].transpose();
  }
  return false;
}

/// Releases onto the surface the corners and curve vertices of the hexes within
/// PolishReleaseBand of `lowest` where the input is smooth within PolishReleaseAngle about them
/// or has no edge sharper than PolishSharpEdgeAngle near them; returns how many.
int ReleaseSoftCorners(HexVertexMoves& moves,
  HexSurfaceProjection& projection,
  double lowest,
  const HexSmoothingParameters& params)
{
  const HexMesh& mesh = moves.Mesh();
  const Eigen::VectorXd& quality = moves.Quality();
  int released = 0;
  for (int h = 0; h < static_cast<int>(mesh.Cells.rows()); ++h)
  {
    if (quality[h] >= lowest + params.PolishReleaseBand)
    {
      continue;
    }
    for (int k = 0; k < 8; ++k)
    {
      const int v = mesh.Cells(h, k);
      const HexVertexKind kind = moves.Kind(v);
      const Eigen::Vector3d p = mesh.Vertices.row(v).transpose();
      if ((kind == HexVertexKind::Fixed || kind == HexVertexKind::Feature) &&
        (projection.SmoothAt(v, p, params.PolishReleaseAngle) ||
          projection.FreeOfSharpEdgesAt(v, p, params.PolishSharpEdgeAngle)) &&
        projection.Release(v, p))
      {
        ++released;
      }
    }
  }
  return released;
}

/// The polish: passes over the movable vertices of the hexes within PolishBand of the minimum,
/// each vertex climbing alone, then all of them together, until a pass lifts the minimum by
/// less than 1e-5. The minimum never decreases. Returns false when the caller aborted (checked
/// before each pass; the passes done so far are kept).
bool Polish(HexVertexMoves& moves,
  HexSurfaceProjection* releaseOnto,
  const HexSmoothingParameters& params,
  HexSmoothingResult& result,
  const std::function<bool(double)>& report)
{
  const HexMesh& mesh = moves.Mesh();
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  bool aborted = false;
  for (int pass = 0; pass < params.PolishPasses; ++pass)
  {
    if (!report(static_cast<double>(pass) / params.PolishPasses))
    {
      aborted = true;
      break;
    }
    const Eigen::VectorXd& quality = moves.Quality();
    const double lowest = quality.minCoeff();
    if (releaseOnto)
    {
      result.PolishReleased += ReleaseSoftCorners(moves, *releaseOnto, lowest, params);
    }
    std::vector<int> worst;
    for (int h = 0; h < hexCount; ++h)
    {
      if (quality[h] < lowest + params.PolishBand)
      {
        for (int k = 0; k < 8; ++k)
        {
          if (moves.Kind(mesh.Cells(h, k)) != HexVertexKind::Fixed)
          {
            worst.push_back(mesh.Cells(h, k));
          }
        }
      }
    }
    std::sort(worst.begin(), worst.end());
    worst.erase(std::unique(worst.begin(), worst.end()), worst.end());
    for (int v : worst)
    {
      ClimbVertex(moves, v, params);
    }
    for (int step = 0; step < params.PolishJointSteps; ++step)
    {
      if (!ClimbTogether(moves, worst, params))
      {
        break;
      }
    }
    ++result.PolishPasses;
    if (moves.Quality().minCoeff() < lowest + 1e-5)
    {
      break;
    }
  }
  result.MinAfter = moves.Quality().minCoeff();
  result.MeanAfter = moves.Quality().mean();
  return !aborted && report(1.0);
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
  HexSurfaceProjection projection(surface, vertexCharts, mesh, params.SoftFeatureAngle);
  return smoothHexMesh(mesh, projection, params, result, progress);
}

Status smoothHexMesh(HexMesh& mesh,
  HexSurfaceProjection& projection,
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
  HexVertexMoves moves(mesh, projection);
  result.MinBefore = hexCount > 0 ? moves.Quality().minCoeff() : 0.0;
  result.MeanBefore = MeanOf(moves.Quality());
  result.MinAfter = result.MinBefore;
  result.MeanAfter = result.MeanBefore;
  result.MinBeforePolish = result.MinBefore;
  result.Sweeps = 0;
  result.PolishPasses = 0;
  result.PolishReleased = 0;
  if (hexCount == 0 || params.Iterations <= 0)
  {
    return Status::Success();
  }

  // Laplacian sweeps; sweeps with the steps for the mean (after the Laplacian has converged:
  // interleaved from the first sweep they took 1.5 s more on rockerarm's closed form for the
  // same mean, and slowed a jiggled lattice's way back to cubes); the polish of the worst hexes;
  // a few sweeps, which take back for the mean what the polish's moves cost it, the new minimum
  // as their floor; the polish once more. With PolishReleaseAngle (or PolishSharpEdgeAngle),
  // the same polish, sweeps,
  // polish again, now releasing corners and curve vertices of the worst hexes: after the
  // others, so that the minimum ends no lower than without the release (releasing from the
  // start took other paths, some lower: kitten Uniform 0.479 -> 0.341). On the progress bar
  // each polish counts as PolishProgressShare sweeps.
  const bool polish = params.PolishPasses > 0;
  const bool release = params.PolishReleaseAngle > 0.0 || params.PolishSharpEdgeAngle > 0.0;
  const int rounds = polish ? (release ? 2 : 1) : 0;
  const int sweepsAfter = polish ? std::max(0, params.SweepsAfterPolish) : 0;
  constexpr double PolishProgressShare = 3.0;
  const double polishShare = polish ? PolishProgressShare : 0.0;
  const int meanSweeps = params.MeanSearchStep > 0.0 ? std::max(0, params.MeanSearchSweeps) : 0;
  const double meanStep = meanSweeps > 0 ? params.MeanSearchStep : 0.0;
  const double total = params.Iterations + meanSweeps + rounds * (sweepsAfter + 2.0 * polishShare);
  auto stage = [&](double begin, double length)
  {
    return [&progress, begin, length, total](double p)
    { return ReportProgress(progress, (begin + p * length) / total); };
  };
  if (!RunSweeps(moves, params.Iterations, 0.0, params, result, stage(0.0, params.Iterations)) ||
    !RunSweeps(moves, meanSweeps, meanStep, params, result, stage(params.Iterations, meanSweeps)))
  {
    return Status::Failure("hex smoothing aborted");
  }
  result.MinBeforePolish = result.MinAfter;
  for (int round = 0; round < rounds; ++round)
  {
    HexSurfaceProjection* releaseOnto = round > 0 ? &projection : nullptr;
    const double begin = params.Iterations + meanSweeps + round * (sweepsAfter + 2.0 * polishShare);
    if (!Polish(moves, releaseOnto, params, result, stage(begin, polishShare)) ||
      !RunSweeps(
        moves, sweepsAfter, meanStep, params, result, stage(begin + polishShare, sweepsAfter)) ||
      !Polish(
        moves, releaseOnto, params, result, stage(begin + polishShare + sweepsAfter, polishShare)))
    {
      return Status::Failure("hex smoothing aborted");
    }
  }
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
