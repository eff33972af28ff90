// SPDX-License-Identifier: BSD-3-Clause
// How many threads the core may use: the hardware's count, or POLYCUBEHEX_THREADS when it is set
// to a positive number (for the determinism tests and for users who share a machine). Every
// parallel loop writes only its own outputs and reduces in a fixed order, so the results do not
// depend on it.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace polycubehex
{

inline unsigned ThreadCount()
{
  if (const char* value = std::getenv("POLYCUBEHEX_THREADS"))
  {
    const int requested = std::atoi(value);
    if (requested > 0)
    {
      return static_cast<unsigned>(requested);
    }
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

} // namespace polycubehex
