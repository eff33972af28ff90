// SPDX-License-Identifier: BSD-3-Clause
// Union-find over indices 0..n-1, as a parent vector (parent[i] == i at a root). Components of
// meshes (charts, boundary components, cut sheets, spanning trees) are all grouped with it.
#pragma once

#include <vector>

namespace polycubehex
{

/// The root of i's set, halving the path on the way (the root does not depend on how paths are
/// compressed, only on the order of the unions).
inline int FindRoot(std::vector<int>& parent, int i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

} // namespace polycubehex
