// SPDX-License-Identifier: BSD-3-Clause
#include "CutSubdivision.h"

#include "TetEdgeSplit.h"

namespace polycubehex
{

std::vector<std::array<int, 2>> BoundaryChordEdges(const TetAdjacency& adjacency,
  const std::vector<char>& near)
{
  std::vector<std::array<int, 2>> edges;
  for (size_t e = 0; e < adjacency.EdgeVertices.size(); ++e)
  {
    const auto& ends = adjacency.EdgeVertices[e];
    if (adjacency.EdgeOnBoundary[e] || !adjacency.VertexOnBoundary[ends[0]] ||
      !adjacency.VertexOnBoundary[ends[1]])
    {
      continue;
    }
    if (!near.empty() && !near[ends[0]] && !near[ends[1]])
    {
      continue;
    }
    edges.push_back({ ends[0], ends[1] });
  }
  return edges;
}

int SubdivideEdges(TetMesh& mesh,
  const std::vector<std::array<int, 2>>& edges,
  std::vector<int>& originalCell,
  std::vector<std::array<int, 2>>& midpointParents)
{
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  std::vector<int> parent;
  std::vector<std::array<int, 2>> midpoints;
  SplitTetEdges(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, edges, parent, midpoints);
  AppendSplitMidpoints(mesh.Vertices, midpoints);
  midpointParents.insert(midpointParents.end(), midpoints.begin(), midpoints.end());
  // parent refers to this round's tets; compose with the earlier rounds.
  std::vector<char> split(tetCount, 0);
  std::vector<int> composed(parent.size());
  for (size_t t = 0; t < parent.size(); ++t)
  {
    composed[t] = originalCell[parent[t]];
    if (static_cast<int>(t) >= tetCount)
    {
      split[parent[t]] = 1;
    }
  }
  originalCell.swap(composed);
  int count = 0;
  for (char s : split)
  {
    count += s;
  }
  return count;
}

} // namespace polycubehex
