// SPDX-License-Identifier: BSD-3-Clause
#include "HexPaddingPlacement.h"

#include "HexCornerQualityEnergy.h"
#include "HexScaledJacobian.h"

#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace polycubehex
{

namespace
{
/// Smallest and mean scaled Jacobian of `hexes`.
std::pair<double, double> HexQuality(const HexMesh& mesh, const std::vector<int>& hexes)
{
  double minimum = std::numeric_limits<double>::max();
  double sum = 0.0;
  for (int h : hexes)
  {
    const double q = HexScaledJacobian(mesh, h);
    minimum = std::min(minimum, q);
    sum += q;
  }
  return { minimum, hexes.empty() ? 0.0 : sum / static_cast<double>(hexes.size()) };
}

/// HexCornerQualityEnergy of the hexes at the inner copies as a function of the copies'
/// positions alone (everything else stays where `mesh` has it).
class CopiesEnergy final : public ceres::FirstOrderFunction
{
public:
  CopiesEnergy(const HexMesh& mesh,
    const std::vector<int>& copies,
    const std::vector<int>& hexes,
    double epsilon)
    : Mesh(mesh)
    , Copies(copies)
    , HexList(hexes)
    , Epsilon(epsilon)
  {
  }

  int NumParameters() const override { return 3 * static_cast<int>(this->Copies.size()); }

  bool Evaluate(const double* parameters, double* cost, double* gradient) const override
  {
    Points x = this->Mesh.Vertices;
    for (size_t i = 0; i < this->Copies.size(); ++i)
    {
      x.row(this->Copies[i]) = Eigen::Map<const Eigen::RowVector3d>(parameters + 3 * i);
    }
    Points g;
    cost[0] = HexCornerQualityEnergy(
      x, this->Mesh.Cells, this->HexList, this->Epsilon, gradient ? &g : nullptr);
    if (gradient)
    {
      for (size_t i = 0; i < this->Copies.size(); ++i)
      {
        Eigen::Map<Eigen::RowVector3d>(gradient + 3 * i) = g.row(this->Copies[i]);
      }
    }
    return std::isfinite(cost[0]);
  }

private:
  const HexMesh& Mesh;
  const std::vector<int>& Copies;
  const std::vector<int>& HexList;
  double Epsilon;
};

/// The joint optimisation of the copies (HexPaddingPlacementParameters::OptimizationIterations):
/// returns how many copies it moved and kept, and its iterations in `iterations`.
int OptimizeCopies(HexMesh& mesh,
  const std::vector<int>& copies,
  const std::vector<std::vector<int>>& hexesAt,
  const HexPaddingPlacementParameters& params,
  int& iterations)
{
  iterations = 0;
  if (copies.empty() || params.OptimizationIterations <= 0)
  {
    return 0;
  }
  std::vector<int> hexes;
  for (int v : copies)
  {
    hexes.insert(
      hexes.end(), hexesAt[static_cast<size_t>(v)].begin(), hexesAt[static_cast<size_t>(v)].end());
  }
  std::sort(hexes.begin(), hexes.end());
  hexes.erase(std::unique(hexes.begin(), hexes.end()), hexes.end());
  // A copy's floor: the smallest scaled Jacobian of its hexes, and how many of them are
  // inverted, in one pass over them.
  auto floorAt = [&](int v)
  {
    std::pair<double, int> result(std::numeric_limits<double>::max(), 0);
    for (int h : hexesAt[static_cast<size_t>(v)])
    {
      const double q = HexScaledJacobian(mesh, h);
      result.first = std::min(result.first, q);
      result.second += q <= 0.0 ? 1 : 0;
    }
    return result;
  };
  std::vector<std::pair<double, int>> floorBefore(copies.size());
  for (size_t i = 0; i < copies.size(); ++i)
  {
    floorBefore[i] = floorAt(copies[i]);
  }
  const double meanBefore = HexQuality(mesh, hexes).second;
  const Points start = mesh.Vertices;

  std::vector<double> parameters(3 * copies.size());
  for (size_t i = 0; i < copies.size(); ++i)
  {
    Eigen::Map<Eigen::RowVector3d>(parameters.data() + 3 * i) = mesh.Vertices.row(copies[i]);
  }
  ceres::GradientProblem problem(
    new CopiesEnergy(mesh, copies, hexes, params.OptimizationEpsilon)); // owns the function
  ceres::GradientProblemSolver::Options options;
  options.line_search_direction_type = ceres::LBFGS;
  options.max_num_iterations = params.OptimizationIterations;
  options.logging_type = ceres::SILENT;
  options.function_tolerance = 1e-7;
  options.gradient_tolerance = 1e-10;
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(options, problem, parameters.data(), &summary);
  iterations = static_cast<int>(summary.iterations.size());
  for (size_t i = 0; i < copies.size(); ++i)
  {
    const Eigen::RowVector3d p = Eigen::Map<const Eigen::RowVector3d>(parameters.data() + 3 * i);
    if (p.allFinite())
    {
      mesh.Vertices.row(copies[i]) = p;
    }
  }
  // A copy whose hexes lost in their minimum or gained an inverted hex goes back; that can cost a
  // neighbour's hexes, so again until none does (each copy goes back at most once).
  std::vector<bool> moved(copies.size());
  for (size_t i = 0; i < copies.size(); ++i)
  {
    moved[i] = mesh.Vertices.row(copies[i]) != start.row(copies[i]);
  }
  for (bool changed = true; changed;)
  {
    changed = false;
    for (size_t i = 0; i < copies.size(); ++i)
    {
      if (!moved[i])
      {
        continue;
      }
      const std::pair<double, int> now = floorAt(copies[i]);
      if (now.first < floorBefore[i].first || now.second > floorBefore[i].second)
      {
        mesh.Vertices.row(copies[i]) = start.row(copies[i]);
        moved[i] = false;
        changed = true;
      }
    }
  }
  if (!(HexQuality(mesh, hexes).second > meanBefore))
  {
    mesh.Vertices = start; // the energy is a proxy for the mean: keep what is sure
    return 0;
  }
  return static_cast<int>(std::count(moved.begin(), moved.end(), true));
}
} // namespace

Status placePaddingCopies(HexMesh& mesh,
  int paddingHexCount,
  const HexPaddingPlacementParameters& params,
  HexPaddingPlacementResult& result)
{
  result = HexPaddingPlacementResult();
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  if (paddingHexCount < 0 || paddingHexCount > hexCount)
  {
    return Status::Failure("placePaddingCopies: the padding hex count is out of range");
  }
  const int firstPadding = hexCount - paddingHexCount;

  // Each inner copy's boundary vertex, and per boundary vertex the inward normal (sum of its
  // boundary quads' area vectors; face 0-1-2-3 of a positive hex faces its top) and the mean
  // length of its boundary edges.
  std::vector<int> outerOf(static_cast<size_t>(vertexCount), -1);
  Points inward = Points::Zero(vertexCount, 3);
  std::vector<double> edgeSum(static_cast<size_t>(vertexCount), 0.0);
  std::vector<int> edgeCount(static_cast<size_t>(vertexCount), 0);
  for (int h = firstPadding; h < hexCount; ++h)
  {
    Eigen::Matrix<double, 4, 3> quad;
    for (int k = 0; k < 4; ++k)
    {
      const int outer = mesh.Cells(h, k);
      const int inner = mesh.Cells(h, k + 4);
      if (outer < 0 || outer >= vertexCount || inner < 0 || inner >= vertexCount ||
        (outerOf[static_cast<size_t>(inner)] >= 0 && outerOf[static_cast<size_t>(inner)] != outer))
      {
        return Status::Failure("placePaddingCopies: hex " + std::to_string(h) +
          " is not a padding hex (boundary quad, then its inner copies)");
      }
      outerOf[static_cast<size_t>(inner)] = outer;
      quad.row(k) = mesh.Vertices.row(outer);
    }
    const Eigen::RowVector3d area =
      0.5 * (quad.row(2) - quad.row(0)).cross(quad.row(3) - quad.row(1));
    for (int k = 0; k < 4; ++k)
    {
      const int outer = mesh.Cells(h, k);
      inward.row(outer) += area;
      edgeSum[static_cast<size_t>(outer)] +=
        (quad.row(k) - quad.row((k + 1) % 4)).norm() + (quad.row(k) - quad.row((k + 3) % 4)).norm();
      edgeCount[static_cast<size_t>(outer)] += 2;
    }
  }

  // The hexes at each inner copy.
  std::vector<std::vector<int>> hexesAt(static_cast<size_t>(vertexCount));
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      const int v = mesh.Cells(h, k);
      if (v >= 0 && v < vertexCount && outerOf[static_cast<size_t>(v)] >= 0)
      {
        hexesAt[static_cast<size_t>(v)].push_back(h);
      }
    }
  }

  std::vector<int> copies;
  for (int v = 0; v < vertexCount; ++v)
  {
    if (outerOf[static_cast<size_t>(v)] >= 0)
    {
      copies.push_back(v);
    }
  }
  const Points mapped = mesh.Vertices;
  Points pushed = mapped;
  for (int v : copies)
  {
    const int outer = outerOf[static_cast<size_t>(v)];
    const double norm = inward.row(outer).norm();
    if (norm > 0.0 && edgeCount[static_cast<size_t>(outer)] > 0)
    {
      const double edge =
        edgeSum[static_cast<size_t>(outer)] / edgeCount[static_cast<size_t>(outer)];
      pushed.row(v) =
        mesh.Vertices.row(outer) + (params.Thickness * edge / norm) * inward.row(outer);
    }
  }

  auto paddingMean = [&]()
  {
    double sum = 0.0;
    for (int h = firstPadding; h < hexCount; ++h)
    {
      sum += HexScaledJacobian(mesh, h);
    }
    return paddingHexCount > 0 ? sum / paddingHexCount : 0.0;
  };
  auto copiesMin = [&]()
  {
    double minimum = std::numeric_limits<double>::max();
    for (int v : copies)
    {
      minimum = std::min(minimum, HexQuality(mesh, hexesAt[static_cast<size_t>(v)]).first);
    }
    return copies.empty() ? 0.0 : minimum;
  };
  result.MeanBefore = paddingMean();
  result.MinBefore = copiesMin();

  // Gauss-Seidel in vertex order: a copy moves only to a strictly better candidate.
  std::vector<double> blend(static_cast<size_t>(vertexCount), 0.0);
  for (int sweep = 0; sweep < params.Sweeps; ++sweep)
  {
    bool moved = false;
    for (int v : copies)
    {
      const std::vector<int>& hexes = hexesAt[static_cast<size_t>(v)];
      double best = blend[static_cast<size_t>(v)];
      std::pair<double, double> bestQuality = HexQuality(mesh, hexes);
      for (double b : params.Blends)
      {
        if (b == blend[static_cast<size_t>(v)])
        {
          continue;
        }
        mesh.Vertices.row(v) = (1.0 - b) * mapped.row(v) + b * pushed.row(v);
        const std::pair<double, double> quality = HexQuality(mesh, hexes);
        if (quality > bestQuality)
        {
          bestQuality = quality;
          best = b;
        }
      }
      mesh.Vertices.row(v) = (1.0 - best) * mapped.row(v) + best * pushed.row(v);
      moved = moved || best != blend[static_cast<size_t>(v)];
      blend[static_cast<size_t>(v)] = best;
    }
    if (!moved)
    {
      break;
    }
  }
  // Then each copy whose hexes are still poor walks in space (compass search: the six axis
  // directions, the step halved when none helps), again only to strictly better places. Where the
  // surface is nearly flat at a polycube corner or edge, the hexes inside need the copy deeper
  // than the push or off the normal, which no blend reaches.
  for (int sweep = 0; sweep < params.SearchSweeps; ++sweep)
  {
    bool moved = false;
    for (int v : copies)
    {
      const std::vector<int>& hexes = hexesAt[static_cast<size_t>(v)];
      // The smallest scaled Jacobian counts up to SearchBelow, the mean beyond it, so that the
      // walk does not trade good hexes for a minimum that is already fine.
      auto capped = [&]()
      {
        std::pair<double, double> quality = HexQuality(mesh, hexes);
        quality.first = std::min(quality.first, params.SearchBelow);
        return quality;
      };
      std::pair<double, double> bestQuality = capped();
      const int outer = outerOf[static_cast<size_t>(v)];
      if (bestQuality.first >= params.SearchBelow || edgeCount[static_cast<size_t>(outer)] == 0)
      {
        continue;
      }
      double step = params.SearchStep * edgeSum[static_cast<size_t>(outer)] /
        edgeCount[static_cast<size_t>(outer)];
      for (int level = 0; level < params.SearchLevels; ++level, step *= 0.5)
      {
        bool improved = true;
        while (improved)
        {
          improved = false;
          for (int direction = 0; direction < 6; ++direction)
          {
            const Eigen::RowVector3d start = mesh.Vertices.row(v);
            mesh.Vertices(v, direction / 2) += direction % 2 == 0 ? step : -step;
            const std::pair<double, double> quality = capped();
            if (quality > bestQuality)
            {
              bestQuality = quality;
              improved = true;
              moved = true;
            }
            else
            {
              mesh.Vertices.row(v) = start;
            }
          }
        }
      }
    }
    if (!moved)
    {
      break;
    }
  }
  result.OptimizedCount =
    OptimizeCopies(mesh, copies, hexesAt, params, result.OptimizationIterations);
  for (int v : copies)
  {
    result.MovedCount += mesh.Vertices.row(v) != mapped.row(v) ? 1 : 0;
  }
  result.MeanAfter = paddingMean();
  result.MinAfter = copiesMin();
  return Status::Success();
}

} // namespace polycubehex
