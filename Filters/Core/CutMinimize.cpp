// SPDX-License-Identifier: BSD-3-Clause
#include "CutMinimize.h"

#include "MaxFlow.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace polycubehex
{

double CochainArea(const std::vector<double>& faceArea, const std::vector<int>& cochain)
{
  double area = 0.0;
  for (size_t f = 0; f < cochain.size(); ++f)
  {
    area += faceArea[f] * std::abs(cochain[f]);
  }
  return area;
}

double MinimizeCocycleArea(const TetAdjacency& adjacency,
  const std::vector<double>& faceArea,
  std::vector<int>& cocycle,
  int copies,
  int maxRounds,
  int* rounds)
{
  copies = std::max(copies, 1);
  const int tetCount = adjacency.TetCount;
  const int faceCount = static_cast<int>(adjacency.InteriorFaces.size());
  double maxArea = 0.0;
  for (double area : faceArea)
  {
    maxArea = std::max(maxArea, area);
  }
  // Integer capacities: 2^30 for the largest face keeps the sum far below 2^63.
  std::vector<std::int64_t> capacity(faceCount, 1);
  if (maxArea > 0.0)
  {
    for (int f = 0; f < faceCount; ++f)
    {
      capacity[f] = std::max<std::int64_t>(1, std::llround(faceArea[f] / maxArea * 1073741824.0));
    }
  }

  double area = CochainArea(faceArea, cocycle);
  int done = 0;
  std::vector<int> height(tetCount);
  std::vector<int> next(faceCount);
  for (; done < maxRounds; ++done)
  {
    if (area <= 0.0)
    {
      break;
    }
    MaxFlowGraph graph(copies * tetCount);
    for (int f = 0; f < faceCount; ++f)
    {
      const int a = adjacency.InteriorFaces[f][0];
      const int b = adjacency.Neighbor(a, adjacency.InteriorFaces[f][1]);
      const int p = cocycle[f];
      const std::int64_t cap = capacity[f];
      // Pairs (a, c) -- (b, c + p) with at least one end in the window [0, copies).
      const int lowest = std::min(0, -p);
      const int highest = std::max(copies, copies - p);
      for (int c = lowest; c < highest; ++c)
      {
        const bool aIn = c >= 0 && c < copies;
        const bool bIn = c + p >= 0 && c + p < copies;
        if (aIn && bIn)
        {
          graph.AddEdge(c * tetCount + a, (c + p) * tetCount + b, cap, cap);
        }
        else if (aIn)
        {
          graph.AddTerminal(c * tetCount + a, c + p < 0 ? cap : 0, c + p < 0 ? 0 : cap);
        }
        else if (bIn)
        {
          graph.AddTerminal((c + p) * tetCount + b, c < 0 ? cap : 0, c < 0 ? 0 : cap);
        }
      }
    }
    graph.Solve();
    for (int t = 0; t < tetCount; ++t)
    {
      height[t] = 0;
      for (int c = 0; c < copies; ++c)
      {
        height[t] += graph.OnSourceSide(c * tetCount + t) ? 1 : 0;
      }
    }
    for (int f = 0; f < faceCount; ++f)
    {
      const int a = adjacency.InteriorFaces[f][0];
      const int b = adjacency.Neighbor(a, adjacency.InteriorFaces[f][1]);
      next[f] = cocycle[f] + height[a] - height[b];
    }
    const double nextArea = CochainArea(faceArea, next);
    if (!(nextArea < area * (1.0 - 1e-12)))
    {
      ++done;
      break;
    }
    cocycle.swap(next);
    area = nextArea;
  }
  if (rounds)
  {
    *rounds = done;
  }
  return area;
}

} // namespace polycubehex
