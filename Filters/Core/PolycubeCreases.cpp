// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeCreases.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace polycubehex
{

namespace
{
/// Net length and turn-back of the Axis coordinate along the crease's vertices.
void MeasureCrease(const Points& x, PolycubeCrease& crease)
{
  double variation = 0.0;
  for (size_t i = 1; i < crease.Vertices.size(); ++i)
  {
    variation +=
      std::abs(x(crease.Vertices[i], crease.Axis) - x(crease.Vertices[i - 1], crease.Axis));
  }
  crease.NetLength =
    std::abs(x(crease.Vertices.back(), crease.Axis) - x(crease.Vertices.front(), crease.Axis));
  crease.TurnBack = 0.5 * std::max(0.0, variation - crease.NetLength);
}

double PathLength(const Points& x, const std::vector<int>& path)
{
  double length = 0.0;
  for (size_t i = 1; i < path.size(); ++i)
  {
    length += (x.row(path[i]) - x.row(path[i - 1])).norm();
  }
  return length;
}
} // namespace

std::vector<PolycubeCrease> ComputePolycubeCreases(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const PolycubeCharts& charts)
{
  // Edges between each pair of charts (each edge once: from the face with the smaller index).
  std::map<std::pair<int, int>, std::vector<std::array<int, 2>>> pairEdges;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    const int chart = charts.FaceChart[static_cast<size_t>(f)];
    for (int e = 0; e < 3; ++e)
    {
      const Eigen::Index g = adjacency(f, e);
      if (g <= f)
      {
        continue;
      }
      const int other = charts.FaceChart[static_cast<size_t>(g)];
      if (other == chart ||
        charts.ChartLabel[static_cast<size_t>(chart)] / 2 ==
          charts.ChartLabel[static_cast<size_t>(other)] / 2)
      {
        continue;
      }
      pairEdges[{ std::min(chart, other), std::max(chart, other) }].push_back(
        { faces(f, e), faces(f, (e + 1) % 3) });
    }
  }

  std::vector<PolycubeCrease> creases;
  for (const auto& entry : pairEdges)
  {
    const auto& edges = entry.second;
    // vertex -> the indices of its edges in `edges`
    std::map<int, std::vector<int>> incident;
    for (size_t i = 0; i < edges.size(); ++i)
    {
      incident[edges[i][0]].push_back(static_cast<int>(i));
      incident[edges[i][1]].push_back(static_cast<int>(i));
    }
    std::vector<bool> used(edges.size(), false);
    auto walk = [&](int start, int firstEdge)
    {
      PolycubeCrease crease;
      crease.ChartA = entry.first.first;
      crease.ChartB = entry.first.second;
      crease.Axis = 3 - charts.ChartLabel[static_cast<size_t>(crease.ChartA)] / 2 -
        charts.ChartLabel[static_cast<size_t>(crease.ChartB)] / 2;
      crease.Vertices.push_back(start);
      int vertex = start;
      int edge = firstEdge;
      while (edge >= 0)
      {
        used[static_cast<size_t>(edge)] = true;
        const auto& e = edges[static_cast<size_t>(edge)];
        vertex = e[0] == vertex ? e[1] : e[0];
        crease.Vertices.push_back(vertex);
        const auto& around = incident[vertex];
        edge = -1;
        if (around.size() == 2) // pass through; anything else ends the path
        {
          for (int candidate : around)
          {
            if (!used[static_cast<size_t>(candidate)])
            {
              edge = candidate;
            }
          }
        }
      }
      MeasureCrease(x, crease);
      creases.push_back(std::move(crease));
    };
    // Open paths start at their ends (vertices not of degree 2) ...
    for (const auto& around : incident)
    {
      if (around.second.size() == 2)
      {
        continue;
      }
      for (int edge : around.second)
      {
        if (!used[static_cast<size_t>(edge)])
        {
          walk(around.first, edge);
        }
      }
    }
    // ... and what is left are closed loops.
    for (size_t i = 0; i < edges.size(); ++i)
    {
      if (!used[i])
      {
        walk(edges[i][0], static_cast<int>(i));
      }
    }
  }
  return creases;
}

int ShaveTurnedBackCreases(const Points& x,
  const Triangles& faces,
  const PolycubeCharts& charts,
  const std::vector<PolycubeCrease>& creases,
  double tolerance,
  std::vector<int>& labels)
{
  // vertex -> its faces
  std::vector<std::vector<int>> vertexFaces(static_cast<size_t>(x.rows()));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      vertexFaces[static_cast<size_t>(faces(f, k))].push_back(static_cast<int>(f));
    }
  }
  const std::vector<int> original = labels;
  int relabelled = 0;
  for (const PolycubeCrease& crease : creases)
  {
    if (crease.TurnBack <= tolerance || crease.Vertices.front() == crease.Vertices.back())
    {
      continue;
    }
    const double direction =
      x(crease.Vertices.back(), crease.Axis) >= x(crease.Vertices.front(), crease.Axis) ? 1.0
                                                                                        : -1.0;
    double farthest = -std::numeric_limits<double>::infinity();
    std::vector<int> around; // faces of the two charts at the vertices behind
    for (int v : crease.Vertices)
    {
      const double position = direction * x(v, crease.Axis);
      farthest = std::max(farthest, position);
      if (position >= farthest - tolerance)
      {
        continue;
      }
      for (int f : vertexFaces[static_cast<size_t>(v)])
      {
        const int chart = charts.FaceChart[static_cast<size_t>(f)];
        if (chart == crease.ChartA || chart == crease.ChartB)
        {
          around.push_back(f);
        }
      }
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    int inA = 0;
    for (int f : around)
    {
      inA += charts.FaceChart[static_cast<size_t>(f)] == crease.ChartA ? 1 : 0;
    }
    const int winner = 2 * inA >= static_cast<int>(around.size()) ? crease.ChartA : crease.ChartB;
    const int label = charts.ChartLabel[static_cast<size_t>(winner)];
    for (int f : around)
    {
      if (labels[static_cast<size_t>(f)] != label)
      {
        relabelled += original[static_cast<size_t>(f)] == labels[static_cast<size_t>(f)] ? 1 : 0;
        labels[static_cast<size_t>(f)] = label;
      }
    }
  }
  return relabelled;
}

double CreaseStretch(const Points& rest, const PolycubeCrease& crease)
{
  if (crease.Vertices.size() < 2 || crease.Vertices.front() == crease.Vertices.back())
  {
    return 0.0;
  }
  const double length = PathLength(rest, crease.Vertices);
  return length > 0.0 ? crease.NetLength / length : 0.0;
}

bool IsSquashedCrease(const Points& rest,
  const PolycubeCrease& crease,
  double maxStretch,
  double minRestLength,
  double* stretch)
{
  if (crease.Vertices.size() < 2 || crease.Vertices.front() == crease.Vertices.back())
  {
    return false; // a closed loop has no net length to compare
  }
  const double length = PathLength(rest, crease.Vertices);
  if (!(length >= minRestLength) || !(length > 0.0))
  {
    return false;
  }
  const double ratio = crease.NetLength / length;
  if (stretch)
  {
    *stretch = ratio;
  }
  return ratio < maxStretch;
}

int CountSquashedCreases(const Points& rest,
  const std::vector<PolycubeCrease>& creases,
  double maxStretch,
  double minRestLength,
  double* smallest)
{
  int count = 0;
  double least = 1.0;
  for (const PolycubeCrease& crease : creases)
  {
    double stretch = 1.0;
    count += IsSquashedCrease(rest, crease, maxStretch, minRestLength, &stretch) ? 1 : 0;
    least = std::min(least, stretch);
  }
  if (smallest)
  {
    *smallest = least;
  }
  return count;
}

double MaxCreaseTurnBack(const std::vector<PolycubeCrease>& creases,
  double tolerance,
  int* countAbove)
{
  double largest = 0.0;
  int count = 0;
  for (const PolycubeCrease& crease : creases)
  {
    largest = std::max(largest, crease.TurnBack);
    count += crease.TurnBack > tolerance ? 1 : 0;
  }
  if (countAbove)
  {
    *countAbove = count;
  }
  return largest;
}

} // namespace polycubehex
