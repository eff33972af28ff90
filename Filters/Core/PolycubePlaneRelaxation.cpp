// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubePlaneRelaxation.h"

#include "PolycubeEnergy.h"
#include "PolycubeNewton.h"
#include "TetGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace polycubehex
{

namespace
{
Eigen::VectorXd Flat(const Points& x)
{
  return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}

/// Smallest volume of x over the reference volume, per tet.
double MinRatio(const Eigen::VectorXd& x, const Tets& cells, const Eigen::VectorXd& referenceVolume)
{
  const Points points = Eigen::Map<const Points>(x.data(), x.size() / 3, 3);
  double ratio = std::numeric_limits<double>::infinity();
  for (int t = 0; t < static_cast<int>(cells.rows()); ++t)
  {
    ratio = std::min(ratio, TetSignedVolume(points, cells, t) / referenceVolume(t));
  }
  return ratio;
}
} // namespace

Status RelaxPolycubeToPlanes(const Points& rest,
  const Points& reference,
  const Tets& cells,
  const ChartPlanes& charts,
  const Eigen::VectorXd& targets,
  const PlaneRelaxationParameters& params,
  Points& positions,
  PlaneRelaxationResult& result,
  const Progress& progress)
{
  result = PlaneRelaxationResult();
  const int vertexCount = static_cast<int>(reference.rows());
  const int tetCount = static_cast<int>(cells.rows());
  const int planeCount = static_cast<int>(targets.size());
  if (rest.rows() != vertexCount || charts.VertexPlane.rows() != vertexCount ||
    static_cast<int>(charts.PlaneAxis.size()) != planeCount)
  {
    return Status::Failure("plane relaxation: the sizes of the inputs disagree");
  }

  // The input, scaled to the polycube's volume, is ARAP's rest shape.
  Eigen::VectorXd referenceVolume(tetCount);
  double restVolume = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    referenceVolume(t) = TetSignedVolume(reference, cells, t);
    const double volume = TetSignedVolume(rest, cells, t);
    if (!(referenceVolume(t) > 0.0) || !(volume > 0.0))
    {
      return Status::Failure("plane relaxation: tet " + std::to_string(t) + " is not positive");
    }
    restVolume += volume;
  }
  const Points restScaled = rest * std::cbrt(referenceVolume.sum() / restVolume);
  TetTopology topology;
  ComputeTetTopology(vertexCount, cells, topology);
  PolycubeEnergy energy(restScaled, cells, topology.BoundaryFaces);

  // One variable per plane; one anchored representative coordinate per plane.
  std::vector<int> group(static_cast<size_t>(3 * vertexCount), -1);
  std::vector<int> representative(static_cast<size_t>(planeCount), -1);
  std::vector<double> planeSum(static_cast<size_t>(planeCount), 0.0);
  std::vector<int> planeCountOf(static_cast<size_t>(planeCount), 0);
  for (int v = 0; v < vertexCount; ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int p = charts.VertexPlane(v, a);
      if (p >= 0)
      {
        group[static_cast<size_t>(3 * v + a)] = p;
        representative[static_cast<size_t>(p)] = 3 * v + a;
        planeSum[static_cast<size_t>(p)] += reference(v, a);
        ++planeCountOf[static_cast<size_t>(p)];
      }
    }
  }
  // Start on the reference with every plane exactly flat (its mean), the planes shared
  // variables pulled by one representative coordinate each. When that inverts a tet (a few
  // vertices the deformation could not put on their planes), every plane coordinate is its own
  // variable, pulled to its target, instead.
  Eigen::VectorXd x = Flat(reference);
  for (size_t i = 0; i < group.size(); ++i)
  {
    if (group[i] >= 0)
    {
      x(static_cast<Eigen::Index>(i)) =
        planeSum[static_cast<size_t>(group[i])] / planeCountOf[static_cast<size_t>(group[i])];
    }
  }
  result.SharedPlanes = MinRatio(x, cells, referenceVolume) > 0.0;
  std::vector<int> anchorIndex;
  std::vector<double> anchorTarget;
  if (result.SharedPlanes)
  {
    for (int p = 0; p < planeCount; ++p)
    {
      if (representative[static_cast<size_t>(p)] >= 0)
      {
        anchorIndex.push_back(representative[static_cast<size_t>(p)]);
        anchorTarget.push_back(targets(p));
      }
    }
  }
  else
  {
    x = Flat(reference);
    for (size_t i = 0; i < group.size(); ++i)
    {
      if (group[i] >= 0)
      {
        anchorIndex.push_back(static_cast<int>(i));
        anchorTarget.push_back(targets(group[i]));
      }
    }
  }

  PolycubeEnergyWeights weights;
  weights.Barrier = 1.0;
  weights.BarrierThreshold = params.BarrierThreshold;
  energy.SetAnchors(anchorIndex, anchorTarget);
  NewtonSettings settings;
  settings.MaxIterations = params.IterationsPerRound;
  settings.StepTolerance = 1e-12;
  {
    const VariableReduction reduction = result.SharedPlanes
      ? VariableReduction::ShareCoordinates(vertexCount, group, planeCount)
      : VariableReduction::Identity(vertexCount);
    PolycubeNewtonSolver solver(energy, reduction);
    double weight = params.InitialWeight;
    for (int round = 0; round < params.Rounds; ++round, weight *= 10.0)
    {
      weights.Anchor = weight;
      energy.SetWeights(weights);
      NewtonStats stats;
      Status status = solver.Minimize(x,
        settings,
        stats,
        [&](double f) { return ReportProgress(progress, 0.9 * (round + f) / params.Rounds); });
      if (!status)
      {
        return Status::Failure("plane relaxation: " + status.Message());
      }
      result.Iterations += stats.Iterations;
      result.Rounds = round + 1;
      result.MaxPlaneDeviation = stats.Terms.MaxAnchorDeviation;
      if (result.MaxPlaneDeviation < params.Tolerance)
      {
        break;
      }
    }
  }

  // Snap the planes and relax the free coordinates with the planes fixed.
  std::vector<int> fixedIndex;
  std::vector<double> fixedValue;
  for (size_t i = 0; i < group.size(); ++i)
  {
    if (group[i] >= 0)
    {
      x(static_cast<Eigen::Index>(i)) = targets(group[i]);
      fixedIndex.push_back(static_cast<int>(i));
      fixedValue.push_back(targets(group[i]));
    }
  }
  if (!energy.IsFeasible(x.data()))
  {
    std::ostringstream message;
    message << "plane relaxation: the planes stayed " << result.MaxPlaneDeviation
            << " lattice units from their targets, and snapping them inverts a tet";
    return Status::Failure(message.str());
  }
  {
    energy.SetAnchors({}, {});
    weights.Anchor = 0.0;
    energy.SetWeights(weights);
    const VariableReduction reduction =
      VariableReduction::FixCoordinates(vertexCount, fixedIndex, fixedValue);
    PolycubeNewtonSolver solver(energy, reduction);
    NewtonStats stats;
    Status status = solver.Minimize(x, settings, stats);
    if (!status)
    {
      return Status::Failure("plane relaxation: " + status.Message());
    }
    result.Iterations += stats.Iterations;
  }
  positions = Eigen::Map<const Points>(x.data(), vertexCount, 3);
  result.MinVolumeRatio = MinRatio(x, cells, referenceVolume);
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
