// SPDX-License-Identifier: BSD-3-Clause
#include "CutRepair.h"

#include "TetGeometry.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace polycubehex
{

namespace
{
/// Level sets of the cocycle in the star of one vertex.
struct Star
{
  std::vector<int> Tets;      // the star
  std::vector<int> Level;     // per star tet
  std::vector<int> Component; // per star tet: its level set component
  std::vector<int> ComponentLevel;
  std::vector<char> ComponentTouchesBoundary;
  /// Pairs of adjacent components (across a face at the vertex), each pair once per face.
  std::vector<std::pair<int, int>> Adjacent;
};

class StarBuilder
{
public:
  StarBuilder(const Tets& cells, const TetAdjacency& adjacency)
    : Cells(cells)
    , Adjacency(adjacency)
    , LocalIndex(adjacency.TetCount, -1)
  {
  }

  void Build(const std::vector<int>& cocycle, int vertex, Star& star)
  {
    const TetAdjacency& adj = this->Adjacency;
    star.Tets.assign(adj.VertexTets.begin() + adj.VertexTetOffsets[vertex],
      adj.VertexTets.begin() + adj.VertexTetOffsets[vertex + 1]);
    const int n = static_cast<int>(star.Tets.size());
    for (int i = 0; i < n; ++i)
    {
      this->LocalIndex[star.Tets[i]] = i;
    }
    star.Level.assign(n, std::numeric_limits<int>::min());
    star.Component.assign(n, -1);
    star.ComponentLevel.clear();
    star.ComponentTouchesBoundary.clear();
    star.Adjacent.clear();
    // Levels: breadth first through the interior faces at the vertex.
    std::vector<int>& queue = this->Queue;
    for (int seed = 0; seed < n; ++seed)
    {
      if (star.Level[seed] != std::numeric_limits<int>::min())
      {
        continue;
      }
      star.Level[seed] = 0;
      queue.assign(1, seed);
      for (size_t head = 0; head < queue.size(); ++head)
      {
        const int i = queue[head];
        const int t = star.Tets[i];
        const int opposite = TetOppositeFace[LocalVertexIndex(this->Cells, t, vertex)];
        for (int k = 0; k < 4; ++k)
        {
          const int m = adj.Neighbor(t, k);
          if (k == opposite || m < 0)
          {
            continue;
          }
          const int j = this->LocalIndex[m];
          if (star.Level[j] == std::numeric_limits<int>::min())
          {
            star.Level[j] =
              star.Level[i] + InteriorFaceSign(adj, t, k) * cocycle[adj.InteriorFaceId(t, k)];
            queue.push_back(j);
          }
        }
      }
    }
    // Components: connected through faces at the vertex carrying 0.
    for (int seed = 0; seed < n; ++seed)
    {
      if (star.Component[seed] >= 0)
      {
        continue;
      }
      const int component = static_cast<int>(star.ComponentLevel.size());
      star.ComponentLevel.push_back(star.Level[seed]);
      star.ComponentTouchesBoundary.push_back(0);
      star.Component[seed] = component;
      queue.assign(1, seed);
      for (size_t head = 0; head < queue.size(); ++head)
      {
        const int i = queue[head];
        const int t = star.Tets[i];
        const int opposite = TetOppositeFace[LocalVertexIndex(this->Cells, t, vertex)];
        for (int k = 0; k < 4; ++k)
        {
          if (k == opposite)
          {
            continue;
          }
          const int m = adj.Neighbor(t, k);
          if (m < 0)
          {
            star.ComponentTouchesBoundary[component] = 1;
            continue;
          }
          if (cocycle[adj.InteriorFaceId(t, k)] != 0)
          {
            continue;
          }
          const int j = this->LocalIndex[m];
          if (star.Component[j] < 0)
          {
            star.Component[j] = component;
            queue.push_back(j);
          }
        }
      }
    }
    for (int i = 0; i < n; ++i)
    {
      const int t = star.Tets[i];
      const int opposite = TetOppositeFace[LocalVertexIndex(this->Cells, t, vertex)];
      for (int k = 0; k < 4; ++k)
      {
        const int m = adj.Neighbor(t, k);
        if (k == opposite || m < 0)
        {
          continue;
        }
        const int j = this->LocalIndex[m];
        if (star.Component[i] != star.Component[j])
        {
          star.Adjacent.emplace_back(star.Component[i], star.Component[j]);
        }
      }
    }
    for (int t : star.Tets)
    {
      this->LocalIndex[t] = -1;
    }
  }

  /// Star index of tet t while a star is being examined (-1 outside): valid only inside Build.
  const Tets& Cells;
  const TetAdjacency& Adjacency;
  std::vector<int> LocalIndex;
  std::vector<int> Queue;
};

bool StarIsProper(const Star& star, bool onBoundary)
{
  const size_t components = star.ComponentLevel.size();
  if (components <= 1)
  {
    return true;
  }
  if (components != 2 || std::abs(star.ComponentLevel[0] - star.ComponentLevel[1]) != 1)
  {
    return false;
  }
  return !onBoundary || (star.ComponentTouchesBoundary[0] && star.ComponentTouchesBoundary[1]);
}
} // namespace

bool IsCocycleProperAtVertex(const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<int>& cocycle,
  int vertex)
{
  StarBuilder builder(cells, adjacency);
  Star star;
  builder.Build(cocycle, vertex, star);
  return StarIsProper(star, adjacency.VertexOnBoundary[vertex] != 0);
}

bool RepairCocycleSurface(const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<double>& faceArea,
  std::vector<int>& cocycle,
  int maxMoves,
  int* moves)
{
  StarBuilder builder(cells, adjacency);
  Star star;
  std::vector<char> queued(adjacency.VertexCount, 0);
  std::vector<int> work;
  for (size_t f = 0; f < cocycle.size(); ++f)
  {
    if (cocycle[f] == 0)
    {
      continue;
    }
    const int t = adjacency.InteriorFaces[f][0];
    const int k = adjacency.InteriorFaces[f][1];
    for (int c = 0; c < 3; ++c)
    {
      const int v = cells(t, TetFaceTable[k][c]);
      if (!queued[v])
      {
        queued[v] = 1;
        work.push_back(v);
      }
    }
  }
  // Smallest vertex ids first (the stack pops from the back).
  std::sort(work.rbegin(), work.rend());
  int made = 0;
  std::vector<int> members;
  while (!work.empty())
  {
    const int v = work.back();
    work.pop_back();
    queued[v] = 0;
    builder.Build(cocycle, v, star);
    if (StarIsProper(star, adjacency.VertexOnBoundary[v] != 0))
    {
      continue;
    }
    if (made >= maxMoves)
    {
      if (moves)
      {
        *moves = made;
      }
      return false;
    }
    // The cheapest move: shift one component to the level of an adjacent one.
    const int components = static_cast<int>(star.ComponentLevel.size());
    double bestCost = std::numeric_limits<double>::infinity();
    int bestComponent = -1;
    int bestShift = 0;
    int bestSize = 0;
    for (const auto& pair : star.Adjacent)
    {
      const int component = pair.first;
      const int shift = star.ComponentLevel[pair.second] - star.ComponentLevel[component];
      if (shift == 0)
      {
        continue;
      }
      double cost = 0.0;
      int size = 0;
      for (size_t i = 0; i < star.Tets.size(); ++i)
      {
        if (star.Component[i] != component)
        {
          continue;
        }
        ++size;
        const int t = star.Tets[i];
        for (int k = 0; k < 4; ++k)
        {
          const int m = adjacency.Neighbor(t, k);
          if (m < 0)
          {
            continue;
          }
          // Faces inside the component keep their value.
          const auto found = std::find(star.Tets.begin(), star.Tets.end(), m);
          if (found != star.Tets.end() && star.Component[found - star.Tets.begin()] == component)
          {
            continue;
          }
          const int f = adjacency.InteriorFaceId(t, k);
          const int before = cocycle[f];
          const int after = before - InteriorFaceSign(adjacency, t, k) * shift;
          cost += faceArea[f] * (std::abs(after) - std::abs(before));
        }
      }
      if (cost < bestCost - 1e-15 || (cost <= bestCost + 1e-15 && size < bestSize))
      {
        bestCost = cost;
        bestComponent = component;
        bestShift = shift;
        bestSize = size;
      }
    }
    if (bestComponent < 0 || components < 2)
    {
      // Two components at the same level cannot happen (they would be joined); give up.
      if (moves)
      {
        *moves = made;
      }
      return false;
    }
    members.clear();
    for (size_t i = 0; i < star.Tets.size(); ++i)
    {
      if (star.Component[i] == bestComponent)
      {
        members.push_back(star.Tets[i]);
      }
    }
    for (int t : members)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int m = adjacency.Neighbor(t, k);
        if (m < 0 || std::find(members.begin(), members.end(), m) != members.end())
        {
          continue;
        }
        cocycle[adjacency.InteriorFaceId(t, k)] -= InteriorFaceSign(adjacency, t, k) * bestShift;
      }
    }
    ++made;
    // Recheck v and every vertex of the moved tets.
    for (int t : members)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int u = cells(t, i);
        if (!queued[u])
        {
          queued[u] = 1;
          work.push_back(u);
        }
      }
    }
    if (!queued[v])
    {
      queued[v] = 1;
      work.push_back(v);
    }
  }
  if (moves)
  {
    *moves = made;
  }
  return true;
}

} // namespace polycubehex
