// SPDX-License-Identifier: BSD-3-Clause
#include "CutMesh.h"

#include "DisjointSets.h"
#include "TetGeometry.h"

#include <numeric>

namespace polycubehex
{


int SplitAlongFaces(int vertexCount,
  const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<char>& cut,
  Tets& cutCells,
  std::vector<int>& splitToOld)
{
  const int tetCount = static_cast<int>(cells.rows());
  // Corners (tet, local vertex) glued across every uncut interior face.
  std::vector<int> parent(4 * static_cast<size_t>(tetCount));
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t face = 0; face < adjacency.InteriorFaces.size(); ++face)
  {
    if (cut[face])
    {
      continue;
    }
    const int t = adjacency.InteriorFaces[face][0];
    const int k = adjacency.InteriorFaces[face][1];
    const int n = adjacency.Neighbor(t, k);
    for (int c = 0; c < 3; ++c)
    {
      const int local = TetFaceTable[k][c];
      const int other = LocalVertexIndex(cells, n, cells(t, local));
      parent[FindRoot(parent, 4 * t + local)] = FindRoot(parent, 4 * n + other);
    }
  }
  // Number the groups: a vertex's first group keeps its id.
  std::vector<int> rootId(parent.size(), -1);
  std::vector<char> firstTaken(vertexCount, 0);
  splitToOld.resize(vertexCount);
  std::iota(splitToOld.begin(), splitToOld.end(), 0);
  cutCells.resize(tetCount, 4);
  for (int t = 0; t < tetCount; ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      const int root = FindRoot(parent, 4 * t + i);
      if (rootId[root] < 0)
      {
        const int old = cells(t, i);
        if (!firstTaken[old])
        {
          firstTaken[old] = 1;
          rootId[root] = old;
        }
        else
        {
          rootId[root] = static_cast<int>(splitToOld.size());
          splitToOld.push_back(old);
        }
      }
      cutCells(t, i) = rootId[root];
    }
  }
  return static_cast<int>(splitToOld.size());
}

} // namespace polycubehex
