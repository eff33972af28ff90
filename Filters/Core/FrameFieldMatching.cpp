// SPDX-License-Identifier: BSD-3-Clause
#include "FrameFieldMatching.h"

#include "DisjointSets.h"
#include "CubeSymmetry.h"

#include <algorithm>
#include <numeric>

namespace polycubehex
{


int MatchFramesAlongSpanningTree(const Tets& neighbors,
  const Tets& faceCut,
  std::vector<Eigen::Matrix3d>& frames)
{
  const int tetCount = static_cast<int>(neighbors.rows());
  const bool hasCuts = faceCut.rows() == neighbors.rows();

  struct DualEdge
  {
    double Weight;
    int A, B;
  };
  std::vector<DualEdge> edges;
  edges.reserve(2 * static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int s = neighbors(t, k);
      if (s <= t || (hasCuts && faceCut(t, k) >= 0))
      {
        continue;
      }
      double error = 0.0;
      BestCubeRotation(frames[t], frames[s], &error);
      edges.push_back({ error, t, s });
    }
  }
  // Kruskal; the stable sort keeps equal weights in face order.
  std::stable_sort(edges.begin(),
    edges.end(),
    [](const DualEdge& x, const DualEdge& y) { return x.Weight < y.Weight; });
  std::vector<int> parent(static_cast<size_t>(tetCount));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::vector<int>> tree(static_cast<size_t>(tetCount));
  for (const DualEdge& e : edges)
  {
    const int ra = FindRoot(parent, e.A);
    const int rb = FindRoot(parent, e.B);
    if (ra == rb)
    {
      continue;
    }
    parent[std::max(ra, rb)] = std::min(ra, rb);
    tree[e.A].push_back(e.B);
    tree[e.B].push_back(e.A);
  }

  // Breadth-first from the lowest tet of each component.
  std::vector<bool> visited(static_cast<size_t>(tetCount), false);
  std::vector<int> queue;
  queue.reserve(static_cast<size_t>(tetCount));
  int components = 0;
  for (int root = 0; root < tetCount; ++root)
  {
    if (visited[root])
    {
      continue;
    }
    ++components;
    visited[root] = true;
    queue.clear();
    queue.push_back(root);
    for (size_t head = 0; head < queue.size(); ++head)
    {
      const int t = queue[head];
      for (int child : tree[t])
      {
        if (visited[child])
        {
          continue;
        }
        visited[child] = true;
        const int g = BestCubeRotation(frames[child], frames[t]);
        frames[child] = CubeRotationMatrix(g) * frames[child];
        queue.push_back(child);
      }
    }
  }
  return components;
}

} // namespace polycubehex
