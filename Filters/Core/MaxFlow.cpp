// SPDX-License-Identifier: BSD-3-Clause
#include "MaxFlow.h"

#include <algorithm>
#include <limits>

namespace polycubehex
{

MaxFlowGraph::MaxFlowGraph(int nodeCount)
  : NodeCount(nodeCount)
  , Source(nodeCount)
  , Sink(nodeCount + 1)
  , SourceCapacity(nodeCount, 0)
  , SinkCapacity(nodeCount, 0)
{
}

void MaxFlowGraph::AddEdge(int u, int v, std::int64_t forward, std::int64_t backward)
{
  this->From.push_back(u);
  this->To.push_back(v);
  this->Capacity.push_back(forward);
  this->From.push_back(v);
  this->To.push_back(u);
  this->Capacity.push_back(backward);
}

void MaxFlowGraph::AddTerminal(int u, std::int64_t fromSource, std::int64_t toSink)
{
  this->SourceCapacity[u] += fromSource;
  this->SinkCapacity[u] += toSink;
}

bool MaxFlowGraph::BuildLevels()
{
  const int total = this->NodeCount + 2;
  this->Level.assign(total, -1);
  std::vector<int> queue;
  queue.reserve(total);
  this->Level[this->Source] = 0;
  queue.push_back(this->Source);
  for (size_t head = 0; head < queue.size(); ++head)
  {
    const int u = queue[head];
    for (int i = this->Offsets[u]; i < this->Offsets[u + 1]; ++i)
    {
      const int arc = this->Arcs[i];
      const int v = this->To[arc];
      if (this->Capacity[arc] > 0 && this->Level[v] < 0)
      {
        this->Level[v] = this->Level[u] + 1;
        queue.push_back(v);
      }
    }
  }
  return this->Level[this->Sink] >= 0;
}

std::int64_t MaxFlowGraph::Augment()
{
  // Blocking flow on the level graph with an explicit path stack.
  std::int64_t total = 0;
  std::vector<int> path; // arcs
  int u = this->Source;
  while (true)
  {
    if (u == this->Sink)
    {
      std::int64_t bottleneck = std::numeric_limits<std::int64_t>::max();
      for (int arc : path)
      {
        bottleneck = std::min(bottleneck, this->Capacity[arc]);
      }
      size_t firstSaturated = path.size();
      for (size_t i = 0; i < path.size(); ++i)
      {
        this->Capacity[path[i]] -= bottleneck;
        this->Capacity[path[i] ^ 1] += bottleneck;
        if (this->Capacity[path[i]] == 0 && firstSaturated == path.size())
        {
          firstSaturated = i;
        }
      }
      total += bottleneck;
      path.resize(firstSaturated);
      u = path.empty() ? this->Source : this->To[path.back()];
      continue;
    }
    bool advanced = false;
    for (int& i = this->Current[u]; i < this->Offsets[u + 1]; ++i)
    {
      const int arc = this->Arcs[i];
      const int v = this->To[arc];
      if (this->Capacity[arc] > 0 && this->Level[v] == this->Level[u] + 1)
      {
        path.push_back(arc);
        u = v;
        advanced = true;
        break;
      }
    }
    if (advanced)
    {
      continue;
    }
    // Dead end: retreat.
    this->Level[u] = -1;
    if (path.empty())
    {
      break;
    }
    const int arc = path.back();
    path.pop_back();
    u = this->From[arc];
    ++this->Current[u];
  }
  return total;
}

void MaxFlowGraph::BuildArcLists()
{
  const int total = this->NodeCount + 2;
  this->Offsets.assign(static_cast<size_t>(total) + 1, 0);
  for (int from : this->From)
  {
    ++this->Offsets[from + 1];
  }
  for (int u = 0; u < total; ++u)
  {
    this->Offsets[u + 1] += this->Offsets[u];
  }
  this->Arcs.resize(this->From.size());
  std::vector<int> fill(this->Offsets.begin(), this->Offsets.end() - 1);
  for (size_t arc = 0; arc < this->From.size(); ++arc)
  {
    this->Arcs[fill[this->From[arc]]++] = static_cast<int>(arc);
  }
}

std::int64_t MaxFlowGraph::Solve(MaxFlowAlgorithm algorithm)
{
  // Flow straight from source to sink through one node needs no search.
  std::int64_t flow = 0;
  this->TerminalResidual.assign(this->NodeCount, 0);
  for (int u = 0; u < this->NodeCount; ++u)
  {
    const std::int64_t direct = std::min(this->SourceCapacity[u], this->SinkCapacity[u]);
    flow += direct;
    this->TerminalResidual[u] = this->SourceCapacity[u] - this->SinkCapacity[u];
  }
  flow += algorithm == MaxFlowAlgorithm::Dinic ? this->SolveDinic() : this->SolveBoykovKolmogorov();
  return flow;
}

std::int64_t MaxFlowGraph::SolveDinic()
{
  // Terminal capacities become arcs from the source and to the sink.
  for (int u = 0; u < this->NodeCount; ++u)
  {
    if (this->TerminalResidual[u] > 0)
    {
      this->AddEdge(this->Source, u, this->TerminalResidual[u], 0);
    }
    else if (this->TerminalResidual[u] < 0)
    {
      this->AddEdge(u, this->Sink, -this->TerminalResidual[u], 0);
    }
  }
  this->BuildArcLists();
  std::int64_t flow = 0;
  while (this->BuildLevels())
  {
    this->Current.assign(this->Offsets.begin(), this->Offsets.end() - 1);
    flow += this->Augment();
  }
  // Residual reachability from the source.
  const int total = this->NodeCount + 2;
  this->Reached.assign(total, 0);
  std::vector<int> stack{ this->Source };
  this->Reached[this->Source] = 1;
  while (!stack.empty())
  {
    const int u = stack.back();
    stack.pop_back();
    for (int i = this->Offsets[u]; i < this->Offsets[u + 1]; ++i)
    {
      const int arc = this->Arcs[i];
      const int v = this->To[arc];
      if (this->Capacity[arc] > 0 && !this->Reached[v])
      {
        this->Reached[v] = 1;
        stack.push_back(v);
      }
    }
  }
  return flow;
}

} // namespace polycubehex
