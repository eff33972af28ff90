// SPDX-License-Identifier: BSD-3-Clause
#include "MemoryBudget.h"

#include <cstdio>
#include <unistd.h>

namespace polycubehex
{

double PhysicalMemoryBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize)
                                   : 0.0;
}

Status CheckMemoryEstimate(const std::string& what, double bytes, const std::string& advice)
{
  const double physical = PhysicalMemoryBytes();
  if (physical <= 0.0 || !(bytes > 0.8 * physical))
  {
    return Status::Success();
  }
  char text[160];
  std::snprintf(text,
    sizeof(text),
    " needs about %.3g GB, more than this machine's %.3g GB of memory; ",
    bytes / 1e9,
    physical / 1e9);
  return Status::Failure(what + text + advice);
}

} // namespace polycubehex
