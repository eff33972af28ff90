// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeHomotopy.h"

#include <algorithm>
#include <cmath>

namespace polycubehex
{

namespace
{
/// Largest |x_i - target_i| over the anchors, and over those not frozen.
void Deviations(const Eigen::VectorXd& x,
  const std::vector<int>& anchorIndex,
  const std::vector<double>& anchorTarget,
  const std::vector<char>& frozen,
  double& all,
  double& moving)
{
  all = 0.0;
  moving = 0.0;
  for (size_t i = 0; i < anchorIndex.size(); ++i)
  {
    const double deviation = std::abs(x(anchorIndex[i]) - anchorTarget[i]);
    all = std::max(all, deviation);
    if (!frozen[i])
    {
      moving = std::max(moving, deviation);
    }
  }
}
} // namespace

Status FollowAnchors(const PolycubeEnergy& energy,
  const std::vector<int>& anchorIndex,
  const std::vector<double>& anchorTarget,
  const HomotopySettings& settings,
  Eigen::VectorXd& x,
  HomotopyStats& stats)
{
  stats = HomotopyStats();
  const int vertexCount = static_cast<int>(x.size() / 3);
  // The anchors' values in the reduction do not matter: x carries them.
  const VariableReduction reduction = VariableReduction::FixCoordinates(
    vertexCount, anchorIndex, std::vector<double>(anchorIndex.size(), 0.0));
  PolycubeNewtonSolver solver(energy, reduction);
  NewtonSettings newton;
  newton.LinearSolver = settings.LinearSolver;
  newton.MaxIterations = settings.RelaxIterations;
  newton.StepTolerance = 1e-12;
  std::vector<std::vector<int>> vertexAnchors(static_cast<size_t>(vertexCount));
  for (size_t i = 0; i < anchorIndex.size(); ++i)
  {
    vertexAnchors[static_cast<size_t>(anchorIndex[i] / 3)].push_back(static_cast<int>(i));
  }
  std::vector<char> frozen(anchorIndex.size(), 0);
  const double volumeFloor =
    std::min(settings.MinVolumeRatio, 0.5 * energy.MinVolumeRatio(x.data()));
  Eigen::VectorXd jump = Eigen::VectorXd::Zero(x.size());
  double moving = 0.0;
  Deviations(x, anchorIndex, anchorTarget, frozen, stats.Deviation, moving);
  for (int step = 0; step < settings.MaxSteps && moving > settings.Tolerance; ++step)
  {
    for (size_t i = 0; i < anchorIndex.size(); ++i)
    {
      jump(anchorIndex[i]) = frozen[i] ? 0.0 : anchorTarget[i] - x(anchorIndex[i]);
    }
    NewtonStats followed;
    double fraction = 0.0;
    std::vector<int> blocking;
    Status status = solver.Follow(x, jump, newton, followed, fraction, &blocking, volumeFloor);
    if (!status)
    {
      return status;
    }
    ++stats.Steps;
    stats.Halvings += followed.InfeasibleTrials;
    stats.SmallestFraction = std::min(stats.SmallestFraction, fraction);
    if (fraction == 1.0)
    {
      // Exactly on target (x + jump is rounded, so set the values themselves).
      Eigen::VectorXd exact = x;
      for (size_t i = 0; i < anchorIndex.size(); ++i)
      {
        if (!frozen[i])
        {
          exact(anchorIndex[i]) = anchorTarget[i];
        }
      }
      if (energy.IsFeasible(exact.data()) && energy.MinVolumeRatio(exact.data()) > volumeFloor)
      {
        x.swap(exact);
      }
    }
    // One fold must not hold back every other chart: the anchors of the vertices that blocked
    // a larger fraction keep their values from now on.
    bool froze = false;
    if (fraction < settings.FreezeBelow)
    {
      for (int v : blocking)
      {
        for (int i : vertexAnchors[static_cast<size_t>(v)])
        {
          if (!frozen[static_cast<size_t>(i)] && jump(anchorIndex[static_cast<size_t>(i)]) != 0.0)
          {
            frozen[static_cast<size_t>(i)] = 1;
            ++stats.FrozenAnchors;
            froze = true;
          }
        }
      }
    }
    if (settings.RelaxIterations > 0)
    {
      NewtonStats relaxed;
      status = solver.Minimize(x, newton, relaxed);
      if (!status)
      {
        return status;
      }
    }
    Deviations(x, anchorIndex, anchorTarget, frozen, stats.Deviation, moving);
    if (fraction == 0.0 && !froze)
    {
      break; // blocked by vertices that have no anchor left to freeze
    }
  }
  return Status::Success();
}

} // namespace polycubehex
