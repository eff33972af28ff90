// SPDX-License-Identifier: BSD-3-Clause
// The Boykov-Kolmogorov maximum flow (Y. Boykov and V. Kolmogorov, "An experimental comparison
// of min-cut/max-flow algorithms for energy minimization in vision", PAMI 26(9), 2004), written
// from the paper's description: a search tree S grows from the source and T from the sink
// through residual arcs; when they touch, the path is augmented; nodes whose tree arc saturates
// become orphans and look for a new parent in their tree (using timestamps and distances to the
// terminal to prefer short, known-valid origins) or are freed. The terminals are implicit:
// TerminalResidual holds each node's residual capacity from the source (> 0) or to the sink (< 0).
#include "MaxFlow.h"

#include <algorithm>
#include <deque>
#include <limits>

namespace polycubehex
{

namespace
{
constexpr int Free = 0;
constexpr int SourceTree = 1;
constexpr int SinkTree = 2;
// Parent markers besides arc indices (>= 0).
constexpr int ParentTerminal = -1;
constexpr int ParentOrphan = -2;
constexpr int ParentNone = -3;
constexpr int InfiniteDistance = std::numeric_limits<int>::max();
} // namespace

std::int64_t MaxFlowGraph::SolveBoykovKolmogorov()
{
  this->BuildArcLists();
  const int n = this->NodeCount;
  std::vector<std::int64_t>& residual = this->Capacity;
  std::vector<std::int64_t>& terminal = this->TerminalResidual;
  const std::vector<int>& to = this->To;

  std::vector<char> tree(n, Free);
  std::vector<int> parent(n, ParentNone); // the arc from a node to its parent
  std::vector<int> stamp(n, 0);
  std::vector<int> distance(n, 0);
  std::vector<char> queued(n, 0);
  std::deque<int> active;
  std::deque<int> orphans;
  int time = 0;

  auto activate = [&](int u)
  {
    if (!queued[u])
    {
      queued[u] = 1;
      active.push_back(u);
    }
  };
  for (int u = 0; u < n; ++u)
  {
    if (terminal[u] != 0)
    {
      tree[u] = terminal[u] > 0 ? SourceTree : SinkTree;
      parent[u] = ParentTerminal;
      distance[u] = 1;
      activate(u);
    }
  }
  auto makeOrphan = [&](int u)
  {
    parent[u] = ParentOrphan;
    orphans.push_back(u);
  };

  std::int64_t flow = 0;
  int current = -1;
  while (true)
  {
    // The node to grow from: the last one if it found a path, else the next active one.
    int p = current;
    current = -1;
    if (p < 0 || tree[p] == Free)
    {
      p = -1;
      while (!active.empty())
      {
        const int u = active.front();
        active.pop_front();
        queued[u] = 0;
        if (tree[u] != Free)
        {
          p = u;
          break;
        }
      }
      if (p < 0)
      {
        break;
      }
    }

    // Growth.
    int meet = -1; // an arc from the source tree to the sink tree with residual capacity
    for (int i = this->Offsets[p]; i < this->Offsets[p + 1]; ++i)
    {
      const int arc = this->Arcs[i];
      const int q = to[arc];
      if (tree[p] == SourceTree)
      {
        if (residual[arc] <= 0)
        {
          continue;
        }
        if (tree[q] == Free)
        {
          tree[q] = SourceTree;
          parent[q] = arc ^ 1;
          stamp[q] = stamp[p];
          distance[q] = distance[p] + 1;
          activate(q);
        }
        else if (tree[q] == SinkTree)
        {
          meet = arc;
          break;
        }
        else if (stamp[q] <= stamp[p] && distance[q] > distance[p])
        {
          parent[q] = arc ^ 1;
          stamp[q] = stamp[p];
          distance[q] = distance[p] + 1;
        }
      }
      else
      {
        if (residual[arc ^ 1] <= 0)
        {
          continue;
        }
        if (tree[q] == Free)
        {
          tree[q] = SinkTree;
          parent[q] = arc ^ 1;
          stamp[q] = stamp[p];
          distance[q] = distance[p] + 1;
          activate(q);
        }
        else if (tree[q] == SourceTree)
        {
          meet = arc ^ 1;
          break;
        }
        else if (stamp[q] <= stamp[p] && distance[q] > distance[p])
        {
          parent[q] = arc ^ 1;
          stamp[q] = stamp[p];
          distance[q] = distance[p] + 1;
        }
      }
    }
    ++time;
    if (meet < 0)
    {
      continue;
    }
    current = p;

    // Augmentation along source ... from(meet) -> to(meet) ... sink.
    const int sourceEnd = to[meet ^ 1];
    const int sinkEnd = to[meet];
    std::int64_t bottleneck = residual[meet];
    int u = sourceEnd;
    while (parent[u] != ParentTerminal)
    {
      const int arc = parent[u]; // u -> parent; flow runs parent -> u on arc ^ 1
      bottleneck = std::min(bottleneck, residual[arc ^ 1]);
      u = to[arc];
    }
    bottleneck = std::min(bottleneck, terminal[u]);
    u = sinkEnd;
    while (parent[u] != ParentTerminal)
    {
      const int arc = parent[u]; // flow runs u -> parent on arc
      bottleneck = std::min(bottleneck, residual[arc]);
      u = to[arc];
    }
    bottleneck = std::min(bottleneck, -terminal[u]);

    residual[meet] -= bottleneck;
    residual[meet ^ 1] += bottleneck;
    u = sourceEnd;
    while (true)
    {
      const int arc = parent[u];
      if (arc == ParentTerminal)
      {
        terminal[u] -= bottleneck;
        if (terminal[u] == 0)
        {
          makeOrphan(u);
        }
        break;
      }
      residual[arc ^ 1] -= bottleneck;
      residual[arc] += bottleneck;
      const int up = to[arc];
      if (residual[arc ^ 1] == 0)
      {
        makeOrphan(u);
      }
      u = up;
    }
    u = sinkEnd;
    while (true)
    {
      const int arc = parent[u];
      if (arc == ParentTerminal)
      {
        terminal[u] += bottleneck;
        if (terminal[u] == 0)
        {
          makeOrphan(u);
        }
        break;
      }
      residual[arc] -= bottleneck;
      residual[arc ^ 1] += bottleneck;
      const int up = to[arc];
      if (residual[arc] == 0)
      {
        makeOrphan(u);
      }
      u = up;
    }
    flow += bottleneck;

    // Adoption.
    ++time;
    while (!orphans.empty())
    {
      const int o = orphans.front();
      orphans.pop_front();
      const int side = tree[o];
      int bestArc = -1;
      int bestDistance = InfiniteDistance;
      for (int i = this->Offsets[o]; i < this->Offsets[o + 1]; ++i)
      {
        const int arc = this->Arcs[i]; // o -> q
        const int q = to[arc];
        if (tree[q] != side)
        {
          continue;
        }
        // A parent q must reach o through a residual arc in the tree's direction.
        const std::int64_t capacity = side == SourceTree ? residual[arc ^ 1] : residual[arc];
        if (capacity <= 0)
        {
          continue;
        }
        // Does q's chain of parents end at the terminal?
        int d = 0;
        int x = q;
        while (true)
        {
          if (stamp[x] == time)
          {
            d += distance[x];
            break;
          }
          const int up = parent[x];
          ++d;
          if (up == ParentTerminal)
          {
            stamp[x] = time;
            distance[x] = 1;
            break;
          }
          if (up == ParentOrphan || up == ParentNone)
          {
            d = InfiniteDistance;
            break;
          }
          x = to[up];
        }
        if (d == InfiniteDistance)
        {
          continue;
        }
        if (d < bestDistance)
        {
          bestDistance = d;
          bestArc = arc;
        }
        // Stamp the chain with its distances, for the next orphans.
        for (x = q; stamp[x] != time; x = to[parent[x]])
        {
          stamp[x] = time;
          distance[x] = d--;
        }
      }
      if (bestArc >= 0)
      {
        parent[o] = bestArc;
        stamp[o] = time;
        distance[o] = bestDistance + 1;
        continue;
      }
      // No parent: o leaves its tree; its children become orphans, its tree neighbours that
      // could reach it become active again.
      for (int i = this->Offsets[o]; i < this->Offsets[o + 1]; ++i)
      {
        const int arc = this->Arcs[i];
        const int q = to[arc];
        if (tree[q] != side)
        {
          continue;
        }
        const std::int64_t capacity = side == SourceTree ? residual[arc ^ 1] : residual[arc];
        if (capacity > 0)
        {
          activate(q);
        }
        if (parent[q] >= 0 && to[parent[q]] == o)
        {
          makeOrphan(q);
        }
      }
      tree[o] = Free;
      parent[o] = ParentNone;
    }
  }

  const int total = n + 2;
  this->Reached.assign(total, 0);
  this->Reached[this->Source] = 1;
  for (int v = 0; v < n; ++v)
  {
    this->Reached[v] = tree[v] == SourceTree ? 1 : 0;
  }
  return flow;
}

} // namespace polycubehex
