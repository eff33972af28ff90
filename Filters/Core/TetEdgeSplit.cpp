// SPDX-License-Identifier: BSD-3-Clause
#include "TetEdgeSplit.h"

#include <algorithm>

namespace polycubehex
{

void SplitTetEdges(int vertexCount,
  Tets& cells,
  const std::vector<std::array<int, 2>>& edges,
  std::vector<int>& parentTet,
  std::vector<std::array<int, 2>>& newVertexParents)
{
  std::vector<std::array<int, 4>> tets(static_cast<size_t>(cells.rows()));
  for (Eigen::Index t = 0; t < cells.rows(); ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      tets[static_cast<size_t>(t)][static_cast<size_t>(c)] = cells(t, c);
    }
  }
  parentTet.resize(tets.size());
  for (size_t t = 0; t < tets.size(); ++t)
  {
    parentTet[t] = static_cast<int>(t);
  }
  newVertexParents.clear();

  // Vertex -> incident tets, kept up to date while splitting.
  std::vector<std::vector<int>> incident(static_cast<size_t>(vertexCount));
  for (size_t t = 0; t < tets.size(); ++t)
  {
    for (int v : tets[t])
    {
      incident[static_cast<size_t>(v)].push_back(static_cast<int>(t));
    }
  }

  std::vector<int> around;
  for (const auto& edge : edges)
  {
    const int a = edge[0];
    const int b = edge[1];
    if (a == b || a < 0 || b < 0 || a >= static_cast<int>(incident.size()) ||
      b >= static_cast<int>(incident.size()))
    {
      continue;
    }
    around.clear();
    for (int t : incident[static_cast<size_t>(a)])
    {
      const auto& tet = tets[static_cast<size_t>(t)];
      if (std::find(tet.begin(), tet.end(), b) != tet.end())
      {
        around.push_back(t);
      }
    }
    if (around.empty())
    {
      continue;
    }
    const int m = static_cast<int>(incident.size());
    incident.emplace_back();
    newVertexParents.push_back({ a, b });
    for (int t : around)
    {
      std::array<int, 4> first = tets[static_cast<size_t>(t)];
      std::array<int, 4> second = first;
      std::replace(first.begin(), first.end(), b, m);
      std::replace(second.begin(), second.end(), a, m);
      tets[static_cast<size_t>(t)] = first;
      const int child = static_cast<int>(tets.size());
      tets.push_back(second);
      parentTet.push_back(parentTet[static_cast<size_t>(t)]);
      // t lost b and gained m; the child holds b, m and the two other vertices.
      auto& atB = incident[static_cast<size_t>(b)];
      atB.erase(std::remove(atB.begin(), atB.end(), t), atB.end());
      for (int v : second)
      {
        incident[static_cast<size_t>(v)].push_back(child);
      }
      incident[static_cast<size_t>(m)].push_back(t);
    }
  }

  cells.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      cells(static_cast<Eigen::Index>(t), c) = tets[t][static_cast<size_t>(c)];
    }
  }
}

void AppendSplitMidpoints(Points& points, const std::vector<std::array<int, 2>>& newVertexParents)
{
  const Eigen::Index first = points.rows();
  points.conservativeResize(first + static_cast<Eigen::Index>(newVertexParents.size()), 3);
  for (size_t i = 0; i < newVertexParents.size(); ++i)
  {
    points.row(first + static_cast<Eigen::Index>(i)) =
      0.5 * (points.row(newVertexParents[i][0]) + points.row(newVertexParents[i][1]));
  }
}

void SplitTetsAtCentroid(int vertexCount,
  Tets& cells,
  const std::vector<int>& tetsToSplit,
  std::vector<int>& parentTet,
  std::vector<std::array<int, 4>>& newVertexCorners)
{
  newVertexCorners.clear();
  const Eigen::Index first = cells.rows();
  cells.conservativeResize(first + 3 * static_cast<Eigen::Index>(tetsToSplit.size()), 4);
  Eigen::Index next = first;
  for (size_t i = 0; i < tetsToSplit.size(); ++i)
  {
    const int t = tetsToSplit[i];
    const int m = vertexCount + static_cast<int>(i);
    const std::array<int, 4> corners = { cells(t, 0), cells(t, 1), cells(t, 2), cells(t, 3) };
    newVertexCorners.push_back(corners);
    // Child c replaces corner c by the centroid: the same orientation as the parent.
    for (int c = 0; c < 4; ++c)
    {
      const Eigen::Index child = c == 0 ? t : next++;
      for (int k = 0; k < 4; ++k)
      {
        cells(child, k) = k == c ? m : corners[static_cast<size_t>(k)];
      }
      if (c > 0)
      {
        parentTet.push_back(parentTet[static_cast<size_t>(t)]);
      }
    }
  }
}

void AppendSplitCentroids(Points& points, const std::vector<std::array<int, 4>>& newVertexCorners)
{
  const Eigen::Index first = points.rows();
  points.conservativeResize(first + static_cast<Eigen::Index>(newVertexCorners.size()), 3);
  for (size_t i = 0; i < newVertexCorners.size(); ++i)
  {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (int c : newVertexCorners[i])
    {
      sum += points.row(c);
    }
    points.row(first + static_cast<Eigen::Index>(i)) = 0.25 * sum;
  }
}

} // namespace polycubehex
