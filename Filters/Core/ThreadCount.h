// SPDX-License-Identifier: BSD-3-Clause
// How many threads the core may use: the hardware's count, or POLYCUBEHEX_THREADS when it is set
// to a positive number (for the determinism tests and for users who share a machine). Every
// parallel loop writes only its own outputs and reduces in a fixed order, so the results do not
// depend on it.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <thread>
#include <vector>

namespace polycubehex
{

/// A cap on ThreadCount() for the calling thread alone (0, the default: none), for work that
/// runs beside other work of its own (the hex extraction's second untangling path).
inline thread_local unsigned ThreadCap = 0;

inline unsigned ThreadCount()
{
  unsigned count = std::max(1u, std::thread::hardware_concurrency());
  if (const char* value = std::getenv("POLYCUBEHEX_THREADS"))
  {
    const int requested = std::atoi(value);
    if (requested > 0)
    {
      count = static_cast<unsigned>(requested);
    }
  }
  return ThreadCap > 0 ? std::min(count, ThreadCap) : count;
}

/// Runs body(begin, end) over [0, count) in contiguous chunks of at least `grain` items, one
/// chunk per thread (ThreadCount()). The body must write only outputs of its own items, so the
/// result does not depend on the thread count.
template<typename Body>
void ParallelChunks(int count, int grain, const Body& body)
{
  const int threads =
    std::max(1, std::min(static_cast<int>(ThreadCount()), count / std::max(1, grain)));
  if (threads == 1)
  {
    body(0, count);
    return;
  }
  std::vector<std::thread> workers;
  const int chunk = (count + threads - 1) / threads;
  for (int i = 1; i < threads; ++i)
  {
    const int begin = std::min(count, i * chunk);
    const int end = std::min(count, begin + chunk);
    workers.emplace_back([&body, begin, end]() { body(begin, end); });
  }
  body(0, std::min(count, chunk));
  for (auto& worker : workers)
  {
    worker.join();
  }
}

} // namespace polycubehex
