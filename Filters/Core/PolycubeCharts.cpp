// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeCharts.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace polycubehex
{

int PolycubeLabelOfNormal(const Eigen::Vector3d& normal)
{
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  return 2 * axis + (normal(axis) < 0.0 ? 1 : 0);
}

std::vector<int> PolycubeFaceLabels(const Points& x, const Triangles& faces)
{
  std::vector<int> labels(static_cast<size_t>(faces.rows()));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    const Eigen::Vector3d p0 = x.row(faces(f, 0)).transpose();
    const Eigen::Vector3d n =
      (x.row(faces(f, 1)).transpose() - p0).cross(x.row(faces(f, 2)).transpose() - p0);
    labels[static_cast<size_t>(f)] = PolycubeLabelOfNormal(n);
  }
  return labels;
}

namespace
{
double FaceArea(const Points& x, const Triangles& faces, Eigen::Index f)
{
  const Eigen::Vector3d p0 = x.row(faces(f, 0)).transpose();
  return 0.5 *
    (x.row(faces(f, 1)).transpose() - p0).cross(x.row(faces(f, 2)).transpose() - p0).norm();
}
} // namespace

PolycubeCharts ComputePolycubeCharts(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<int>& labels)
{
  PolycubeCharts charts;
  const int faceCount = static_cast<int>(faces.rows());
  charts.FaceChart.assign(static_cast<size_t>(faceCount), -1);
  std::vector<int> stack;
  for (int seed = 0; seed < faceCount; ++seed)
  {
    if (charts.FaceChart[static_cast<size_t>(seed)] >= 0)
    {
      continue;
    }
    const int chart = charts.Count();
    const int label = labels[static_cast<size_t>(seed)];
    charts.ChartLabel.push_back(label);
    charts.ChartArea.push_back(0.0);
    charts.FaceChart[static_cast<size_t>(seed)] = chart;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      charts.ChartArea.back() += FaceArea(x, faces, f);
      for (int e = 0; e < 3; ++e)
      {
        const int g = adjacency(f, e);
        if (g >= 0 && charts.FaceChart[static_cast<size_t>(g)] < 0 &&
          labels[static_cast<size_t>(g)] == label)
        {
          charts.FaceChart[static_cast<size_t>(g)] = chart;
          stack.push_back(g);
        }
      }
    }
  }
  return charts;
}

std::vector<int> ChartBoundaryTurns(const Triangles& faces,
  const Triangles& adjacency,
  const PolycubeCharts& charts)
{
  const int chartCount = charts.Count();
  std::vector<int> turns(static_cast<size_t>(chartCount), std::numeric_limits<int>::max());
  // Boundary half-edges of each chart, chart on the left: start vertex -> (end vertex, the
  // neighbouring chart's label).
  std::vector<std::multimap<int, std::pair<int, int>>> halfEdges(static_cast<size_t>(chartCount));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    const int chart = charts.FaceChart[static_cast<size_t>(f)];
    for (int e = 0; e < 3; ++e)
    {
      const int g = adjacency(f, e);
      if (g < 0 || charts.FaceChart[static_cast<size_t>(g)] == chart)
      {
        continue;
      }
      const int other = charts.ChartLabel[static_cast<size_t>(charts.FaceChart[static_cast<size_t>(g)])];
      halfEdges[static_cast<size_t>(chart)].emplace(
        faces(f, e), std::make_pair(faces(f, (e + 1) % 3), other));
    }
  }
  for (int c = 0; c < chartCount; ++c)
  {
    auto& edges = halfEdges[static_cast<size_t>(c)];
    while (!edges.empty())
    {
      // Walk one loop, recording the axis of the neighbour along it.
      std::vector<int> axes;
      auto it = edges.begin();
      const int start = it->first;
      for (size_t guard = 0; it != edges.end() && guard < faces.size(); ++guard)
      {
        const int next = it->second.first;
        axes.push_back(it->second.second / 2);
        edges.erase(it);
        if (next == start)
        {
          break;
        }
        it = edges.find(next);
      }
      int count = 0;
      for (size_t i = 0; i < axes.size(); ++i)
      {
        count += axes[i] != axes[(i + 1) % axes.size()] ? 1 : 0;
      }
      turns[static_cast<size_t>(c)] = std::min(turns[static_cast<size_t>(c)], count);
    }
  }
  return turns;
}

int CleanUpPolycubeCharts(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const PolycubeChartCleanup& settings,
  std::vector<int>& labels)
{
  const int faceCount = static_cast<int>(faces.rows());
  int relabelled = 0;
  auto removeTeeth = [&]()
  {
    for (int sweep = 0; sweep < 100; ++sweep)
    {
      int changed = 0;
      for (int f = 0; f < faceCount; ++f)
      {
        const int a = adjacency(f, 0) >= 0 ? labels[static_cast<size_t>(adjacency(f, 0))] : -1;
        const int b = adjacency(f, 1) >= 0 ? labels[static_cast<size_t>(adjacency(f, 1))] : -1;
        const int c = adjacency(f, 2) >= 0 ? labels[static_cast<size_t>(adjacency(f, 2))] : -1;
        const int majority = (a >= 0 && (a == b || a == c)) ? a : (b >= 0 && b == c ? b : -1);
        if (majority >= 0 && majority != labels[static_cast<size_t>(f)])
        {
          labels[static_cast<size_t>(f)] = majority;
          ++changed;
        }
      }
      relabelled += changed;
      if (changed == 0)
      {
        break;
      }
    }
  };
  for (int pass = 0; pass < settings.MaxPasses; ++pass)
  {
    if (settings.RemoveTeeth)
    {
      removeTeeth();
    }
    const PolycubeCharts charts = ComputePolycubeCharts(x, faces, adjacency, labels);
    const int chartCount = charts.Count();
    double totalArea = 0.0;
    for (double a : charts.ChartArea)
    {
      totalArea += a;
    }
    std::vector<int> faceTally(static_cast<size_t>(chartCount), 0);
    for (int f = 0; f < faceCount; ++f)
    {
      ++faceTally[static_cast<size_t>(charts.FaceChart[static_cast<size_t>(f)])];
    }
    // Shared boundary length between neighbouring charts.
    std::vector<std::map<int, double>> shared(static_cast<size_t>(chartCount));
    for (int f = 0; f < faceCount; ++f)
    {
      for (int e = 0; e < 3; ++e)
      {
        const int g = adjacency(f, e);
        const int a = charts.FaceChart[static_cast<size_t>(f)];
        if (g < 0 || charts.FaceChart[static_cast<size_t>(g)] == a)
        {
          continue;
        }
        const double length = (x.row(faces(f, (e + 1) % 3)) - x.row(faces(f, e))).norm();
        shared[static_cast<size_t>(a)][charts.FaceChart[static_cast<size_t>(g)]] += length;
      }
    }

    // Extent of each chart along each axis.
    std::vector<Eigen::Vector3d> lo(static_cast<size_t>(chartCount),
      Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()));
    std::vector<Eigen::Vector3d> hi(static_cast<size_t>(chartCount),
      Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity()));
    for (int f = 0; f < faceCount; ++f)
    {
      const int c = charts.FaceChart[static_cast<size_t>(f)];
      for (int k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d p = x.row(faces(f, k)).transpose();
        lo[static_cast<size_t>(c)] = lo[static_cast<size_t>(c)].cwiseMin(p);
        hi[static_cast<size_t>(c)] = hi[static_cast<size_t>(c)].cwiseMax(p);
      }
    }

    std::vector<bool> small(static_cast<size_t>(chartCount), false);
    std::vector<bool> bad(static_cast<size_t>(chartCount), false);
    const std::vector<int> turns = settings.MinBoundaryTurns > 0
      ? ChartBoundaryTurns(faces, adjacency, charts)
      : std::vector<int>(static_cast<size_t>(chartCount), std::numeric_limits<int>::max());
    for (int c = 0; c < chartCount; ++c)
    {
      if (shared[static_cast<size_t>(c)].empty())
      {
        continue;
      }
      if (turns[static_cast<size_t>(c)] < settings.MinBoundaryTurns)
      {
        bad[static_cast<size_t>(c)] = true;
      }
      if (charts.ChartArea[static_cast<size_t>(c)] < settings.MinAreaFraction * totalArea ||
        faceTally[static_cast<size_t>(c)] < settings.MinFaceCount)
      {
        small[static_cast<size_t>(c)] = true;
      }
      for (const auto& neighbour : shared[static_cast<size_t>(c)])
      {
        // Opposite labels side by side: relabel the smaller chart.
        const int d = neighbour.first;
        if (charts.ChartLabel[static_cast<size_t>(d)] ==
            (charts.ChartLabel[static_cast<size_t>(c)] ^ 1) &&
          (charts.ChartArea[static_cast<size_t>(c)] < charts.ChartArea[static_cast<size_t>(d)] ||
            (charts.ChartArea[static_cast<size_t>(c)] == charts.ChartArea[static_cast<size_t>(d)] &&
              c < d)))
        {
          bad[static_cast<size_t>(c)] = true;
        }
      }
    }
    std::vector<int> order;
    for (int c = 0; c < chartCount; ++c)
    {
      if (bad[static_cast<size_t>(c)] || small[static_cast<size_t>(c)])
      {
        order.push_back(c);
      }
    }
    if (order.empty())
    {
      break;
    }
    std::sort(order.begin(),
      order.end(),
      [&charts](int a, int b)
      {
        return charts.ChartArea[static_cast<size_t>(a)] != charts.ChartArea[static_cast<size_t>(b)]
          ? charts.ChartArea[static_cast<size_t>(a)] < charts.ChartArea[static_cast<size_t>(b)]
          : a < b;
      });
    // Relabel in increasing area; a chart next to one relabelled in this pass waits for the next
    // pass, so that two small neighbours do not swap labels forever.
    std::vector<int> newLabel(charts.ChartLabel);
    std::vector<bool> touched(static_cast<size_t>(chartCount), false);
    for (int c : order)
    {
      bool wait = false;
      for (const auto& neighbour : shared[static_cast<size_t>(c)])
      {
        wait = wait || touched[static_cast<size_t>(neighbour.first)];
      }
      if (wait)
      {
        continue;
      }
      // Candidate labels: thinnest extent along the label's axis first, then longest shared
      // boundary; a label opposite to a neighbour's only when nothing else is possible.
      std::map<int, double> byLabel;
      for (const auto& neighbour : shared[static_cast<size_t>(c)])
      {
        byLabel[newLabel[static_cast<size_t>(neighbour.first)]] += neighbour.second;
      }
      const Eigen::Vector3d extent = hi[static_cast<size_t>(c)] - lo[static_cast<size_t>(c)];
      std::vector<std::array<double, 4>> candidates; // conflict, extent, -length, label
      for (const auto& entry : byLabel)
      {
        const int label = entry.first;
        if (label == newLabel[static_cast<size_t>(c)])
        {
          continue;
        }
        // Flattening c into its neighbours of this label moves c's vertices by about c's
        // extent along the axis, and widens each such neighbour's range by the growth.
        const int axis = label / 2;
        double cost = extent(axis);
        for (const auto& neighbour : shared[static_cast<size_t>(c)])
        {
          const size_t n = static_cast<size_t>(neighbour.first);
          if (newLabel[n] != label)
          {
            continue;
          }
          const double merged = std::max(hi[n](axis), hi[static_cast<size_t>(c)](axis)) -
            std::min(lo[n](axis), lo[static_cast<size_t>(c)](axis));
          cost = std::max(cost, merged - (hi[n](axis) - lo[n](axis)));
        }
        candidates.push_back({ byLabel.count(label ^ 1) ? 1.0 : 0.0,
          cost,
          -entry.second,
          static_cast<double>(label) });
      }
      if (candidates.empty())
      {
        continue;
      }
      std::sort(candidates.begin(), candidates.end());
      const auto& best = candidates.front();
      if (!bad[static_cast<size_t>(c)] && (best[0] > 0.0 || best[1] > settings.MaxMergeExtent))
      {
        continue; // small but tall, or no compatible neighbour: a real feature, keep it
      }
      const int chosen = static_cast<int>(best[3]);
      newLabel[static_cast<size_t>(c)] = chosen;
      touched[static_cast<size_t>(c)] = true;
    }
    int changed = 0;
    for (int f = 0; f < faceCount; ++f)
    {
      const int label = newLabel[static_cast<size_t>(charts.FaceChart[static_cast<size_t>(f)])];
      if (label != labels[static_cast<size_t>(f)])
      {
        labels[static_cast<size_t>(f)] = label;
        ++changed;
      }
    }
    relabelled += changed;
    if (changed == 0)
    {
      break;
    }
  }
  return relabelled;
}

int CountPolycubeCorners(int vertexCount,
  const Triangles& faces,
  const std::vector<int>& faceChart,
  std::vector<bool>* isCorner)
{
  std::vector<std::vector<int>> around(static_cast<size_t>(vertexCount));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    for (int c = 0; c < 3; ++c)
    {
      around[static_cast<size_t>(faces(f, c))].push_back(faceChart[static_cast<size_t>(f)]);
    }
  }
  if (isCorner)
  {
    isCorner->assign(static_cast<size_t>(vertexCount), false);
  }
  int corners = 0;
  for (int v = 0; v < vertexCount; ++v)
  {
    auto& list = around[static_cast<size_t>(v)];
    std::sort(list.begin(), list.end());
    const auto distinct = std::unique(list.begin(), list.end()) - list.begin();
    if (distinct >= 3)
    {
      ++corners;
      if (isCorner)
      {
        (*isCorner)[static_cast<size_t>(v)] = true;
      }
    }
  }
  return corners;
}

} // namespace polycubehex
