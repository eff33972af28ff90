// SPDX-License-Identifier: BSD-3-Clause
// Maximum flow: Boykov-Kolmogorov and Dinic agree with each other and with brute force over all
// cuts on small random graphs, the reported source side is a minimum cut, and a grid graph gives
// the expected value.
#include "MaxFlow.h"
#include "TestAssert.h"

#include <cstdint>
#include <iostream>
#include <random>
#include <vector>

using polycubehex::MaxFlowAlgorithm;
using polycubehex::MaxFlowGraph;

namespace
{
struct Edge
{
  int U, V;
  std::int64_t Forward, Backward;
};
struct Problem
{
  int Nodes;
  std::vector<Edge> Edges;
  std::vector<std::int64_t> FromSource, ToSink;
};

Problem RandomProblem(std::mt19937& random, int nodes, int edges, int maxCapacity)
{
  std::uniform_int_distribution<int> node(0, nodes - 1);
  std::uniform_int_distribution<int> capacity(0, maxCapacity);
  Problem problem{
    nodes, {}, std::vector<std::int64_t>(nodes, 0), std::vector<std::int64_t>(nodes, 0)
  };
  for (int e = 0; e < edges; ++e)
  {
    const int u = node(random);
    int v = node(random);
    if (u == v)
    {
      v = (v + 1) % nodes;
    }
    problem.Edges.push_back({ u, v, capacity(random), random() % 3 == 0 ? 0 : capacity(random) });
  }
  for (int u = 0; u < nodes; ++u)
  {
    if (random() % 3 == 0)
    {
      problem.FromSource[u] = capacity(random);
    }
    if (random() % 3 == 0)
    {
      problem.ToSink[u] = capacity(random);
    }
  }
  return problem;
}

/// Capacity of the cut whose source side is `side` (bit u set = node u on the source side).
std::int64_t CutCapacity(const Problem& problem, unsigned side)
{
  std::int64_t capacity = 0;
  for (int u = 0; u < problem.Nodes; ++u)
  {
    const bool inSource = (side >> u) & 1u;
    capacity += inSource ? problem.ToSink[u] : problem.FromSource[u];
  }
  for (const Edge& edge : problem.Edges)
  {
    const bool u = (side >> edge.U) & 1u;
    const bool v = (side >> edge.V) & 1u;
    if (u && !v)
    {
      capacity += edge.Forward;
    }
    if (v && !u)
    {
      capacity += edge.Backward;
    }
  }
  return capacity;
}

std::int64_t Solve(const Problem& problem, MaxFlowAlgorithm algorithm, unsigned& side)
{
  MaxFlowGraph graph(problem.Nodes);
  for (const Edge& edge : problem.Edges)
  {
    graph.AddEdge(edge.U, edge.V, edge.Forward, edge.Backward);
  }
  for (int u = 0; u < problem.Nodes; ++u)
  {
    graph.AddTerminal(u, problem.FromSource[u], problem.ToSink[u]);
  }
  const std::int64_t flow = graph.Solve(algorithm);
  side = 0;
  for (int u = 0; u < problem.Nodes; ++u)
  {
    side |= graph.OnSourceSide(u) ? (1u << u) : 0u;
  }
  return flow;
}
} // namespace

int main(int, char*[])
{
  std::mt19937 random(12345);
  int disagreements = 0;
  for (int trial = 0; trial < 400; ++trial)
  {
    const int nodes = 2 + trial % 11;
    const Problem problem = RandomProblem(random, nodes, 3 * nodes, trial % 2 ? 9 : 1000);
    std::int64_t best = -1;
    for (unsigned side = 0; side < (1u << nodes); ++side)
    {
      const std::int64_t capacity = CutCapacity(problem, side);
      best = best < 0 ? capacity : std::min(best, capacity);
    }
    unsigned bkSide = 0;
    unsigned dinicSide = 0;
    const std::int64_t bk = Solve(problem, MaxFlowAlgorithm::BoykovKolmogorov, bkSide);
    const std::int64_t dinic = Solve(problem, MaxFlowAlgorithm::Dinic, dinicSide);
    const bool ok = bk == best && dinic == best && CutCapacity(problem, bkSide) == best &&
      CutCapacity(problem, dinicSide) == best && bkSide == dinicSide;
    if (!ok)
    {
      std::cerr << "trial " << trial << ": brute force " << best << ", BK " << bk << " (cut "
                << CutCapacity(problem, bkSide) << "), Dinic " << dinic << " (cut "
                << CutCapacity(problem, dinicSide) << ")" << std::endl;
      ++disagreements;
    }
  }
  PCH_CHECK(disagreements == 0);

  // A 200 x 200 grid, unit capacities, source on the left column, sink on the right: flow 200.
  const int n = 200;
  for (MaxFlowAlgorithm algorithm : { MaxFlowAlgorithm::BoykovKolmogorov, MaxFlowAlgorithm::Dinic })
  {
    MaxFlowGraph graph(n * n);
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        if (j + 1 < n)
        {
          graph.AddEdge(i * n + j, i * n + j + 1, 1, 1);
        }
        if (i + 1 < n)
        {
          graph.AddEdge(i * n + j, (i + 1) * n + j, 1, 1);
        }
      }
      graph.AddTerminal(i * n, 5, 0);
      graph.AddTerminal(i * n + n - 1, 0, 5);
    }
    PCH_CHECK(graph.Solve(algorithm) == n);
    PCH_CHECK(graph.OnSourceSide(0) && !graph.OnSourceSide(n - 1));
  }
  return PCH_TEST_RESULT();
}
