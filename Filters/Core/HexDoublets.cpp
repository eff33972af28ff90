// SPDX-License-Identifier: BSD-3-Clause
#include "HexDoublets.h"

#include "HexMeshValidity.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace polycubehex
{
namespace
{
/// Every hex face as its sorted vertices and its hex, sorted, so that equal faces are adjacent.
std::vector<std::array<int, 5>> SortedFaces(const HexMesh& mesh)
{
  std::vector<std::array<int, 5>> faces;
  faces.reserve(static_cast<size_t>(6 * mesh.Cells.rows()));
  for (int h = 0; h < mesh.Cells.rows(); ++h)
  {
    for (const auto& face : HexFaces)
    {
      std::array<int, 5> key = { mesh.Cells(h, face[0]),
        mesh.Cells(h, face[1]),
        mesh.Cells(h, face[2]),
        mesh.Cells(h, face[3]),
        h };
      std::sort(key.begin(), key.begin() + 4);
      faces.push_back(key);
    }
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

bool SameQuad(const std::array<int, 5>& a, const std::array<int, 5>& b)
{
  return std::equal(a.begin(), a.begin() + 4, b.begin());
}

/// How many hexes use each vertex.
std::vector<int> VertexUses(const HexMesh& mesh)
{
  std::vector<int> uses(static_cast<size_t>(mesh.Vertices.rows()), 0);
  for (Eigen::Index h = 0; h < mesh.Cells.rows(); ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      ++uses[static_cast<size_t>(mesh.Cells(h, k))];
    }
  }
  return uses;
}

/// The mesh without the hexes marked in `remove` (vertices unchanged).
HexMesh WithoutHexes(const HexMesh& mesh, const std::vector<char>& remove)
{
  HexMesh kept;
  kept.Vertices = mesh.Vertices;
  kept.Cells.resize(mesh.Cells.rows() - std::count(remove.begin(), remove.end(), 1), 8);
  for (Eigen::Index h = 0, row = 0; h < mesh.Cells.rows(); ++h)
  {
    if (!remove[static_cast<size_t>(h)])
    {
      kept.Cells.row(row++) = mesh.Cells.row(h);
    }
  }
  return kept;
}
} // namespace

Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> FindHexDoublets(const HexMesh& mesh)
{
  const std::vector<std::array<int, 5>> faces = SortedFaces(mesh);
  // The hex pairs across every interior face; a pair seen twice shares two faces.
  std::vector<std::array<int, 2>> pairs;
  for (size_t i = 0; i + 1 < faces.size(); ++i)
  {
    if (SameQuad(faces[i], faces[i + 1]) && (i + 2 >= faces.size() || !SameQuad(faces[i], faces[i + 2])))
    {
      pairs.push_back({ faces[i][4], faces[i + 1][4] });
      ++i;
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<std::array<int, 2>> doublets;
  for (size_t i = 0; i + 1 < pairs.size(); ++i)
  {
    if (pairs[i] == pairs[i + 1] && (doublets.empty() || doublets.back() != pairs[i]))
    {
      doublets.push_back(pairs[i]);
    }
  }
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> result(
    static_cast<Eigen::Index>(doublets.size()), 2);
  for (size_t d = 0; d < doublets.size(); ++d)
  {
    result.row(static_cast<Eigen::Index>(d)) << doublets[d][0], doublets[d][1];
  }
  return result;
}

int RemoveBoundaryDoublets(HexMesh& mesh, const Eigen::VectorXd& quality, std::vector<int>* removed)
{
  if (removed)
  {
    removed->clear();
  }
  const auto doublets = FindHexDoublets(mesh);
  if (doublets.rows() == 0)
  {
    return 0;
  }
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  std::vector<char> onBoundary(static_cast<size_t>(hexCount), 0);
  {
    const std::vector<std::array<int, 5>> faces = SortedFaces(mesh);
    for (size_t i = 0; i < faces.size(); ++i)
    {
      const bool shared = (i > 0 && SameQuad(faces[i], faces[i - 1])) ||
        (i + 1 < faces.size() && SameQuad(faces[i], faces[i + 1]));
      if (!shared)
      {
        onBoundary[static_cast<size_t>(faces[i][4])] = 1;
      }
    }
  }
  std::vector<int> uses = VertexUses(mesh);
  // The mesh without the hexes marked in `remove`.
  std::vector<char> remove(static_cast<size_t>(hexCount), 0);
  auto without = [&]() { return WithoutHexes(mesh, remove); };
  // A dent must not pinch the boundary (two fans at a vertex, or an edge of four quads where
  // two removed hexes touch along it): each removal is kept only if the boundary stays as
  // manifold as it was, trying the other hex of the pair when the worse one fails.
  HexMeshValidity before;
  if (!checkHexMeshValidity(mesh, before))
  {
    return 0;
  }
  auto pinches = [&](const HexMesh& candidate)
  {
    HexMeshValidity after;
    return !checkHexMeshValidity(candidate, after) ||
      after.NonManifoldBoundaryEdgeCount > before.NonManifoldBoundaryEdgeCount ||
      after.NonManifoldBoundaryVertexCount > before.NonManifoldBoundaryVertexCount ||
      after.OverSharedQuadCount > before.OverSharedQuadCount ||
      after.MisorientedQuadCount > before.MisorientedQuadCount;
  };
  for (Eigen::Index d = 0; d < doublets.rows(); ++d)
  {
    const int a = doublets(d, 0);
    const int b = doublets(d, 1);
    if (!onBoundary[static_cast<size_t>(a)] || !onBoundary[static_cast<size_t>(b)] ||
      remove[static_cast<size_t>(a)] || remove[static_cast<size_t>(b)])
    {
      continue;
    }
    const int worse = quality[a] < quality[b] ? a : b;
    for (const int victim : { worse, worse == a ? b : a })
    {
      bool orphans = false;
      for (int k = 0; k < 8; ++k)
      {
        orphans = orphans || uses[static_cast<size_t>(mesh.Cells(victim, k))] <= 1;
      }
      if (orphans)
      {
        continue;
      }
      remove[static_cast<size_t>(victim)] = 1;
      if (pinches(without()))
      {
        remove[static_cast<size_t>(victim)] = 0;
        continue;
      }
      for (int k = 0; k < 8; ++k)
      {
        --uses[static_cast<size_t>(mesh.Cells(victim, k))];
      }
      break;
    }
  }
  const int count = static_cast<int>(std::count(remove.begin(), remove.end(), 1));
  if (count == 0)
  {
    return 0;
  }
  HexMesh kept = without();
  std::vector<int> gone;
  for (int h = 0; h < hexCount; ++h)
  {
    if (remove[static_cast<size_t>(h)])
    {
      gone.push_back(h);
    }
  }
  mesh.Cells = std::move(kept.Cells);
  if (removed)
  {
    *removed = std::move(gone);
  }
  return count;
}

int RemoveOverlappingHexes(HexMesh& mesh, const Eigen::VectorXd& quality)
{
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  // Candidates: the hexes of quads used three times or twice with the same orientation (the
  // orientation of a face: whether its vertex after the smallest is smaller than the one before).
  std::vector<std::array<int, 6>> faces;
  faces.reserve(static_cast<size_t>(6 * hexCount));
  for (int h = 0; h < hexCount; ++h)
  {
    for (const auto& face : HexFaces)
    {
      std::array<int, 4> q = { mesh.Cells(h, face[0]),
        mesh.Cells(h, face[1]),
        mesh.Cells(h, face[2]),
        mesh.Cells(h, face[3]) };
      const int first = static_cast<int>(std::min_element(q.begin(), q.end()) - q.begin());
      const int turn = q[static_cast<size_t>((first + 1) % 4)] < q[static_cast<size_t>((first + 3) % 4)];
      std::sort(q.begin(), q.end());
      faces.push_back({ q[0], q[1], q[2], q[3], turn, h });
    }
  }
  std::sort(faces.begin(), faces.end(),
    [](const std::array<int, 6>& a, const std::array<int, 6>& b)
    { return std::lexicographical_compare(a.begin(), a.begin() + 4, b.begin(), b.begin() + 4) ||
        (std::equal(a.begin(), a.begin() + 4, b.begin()) && a[5] < b[5]); });
  std::vector<int> candidates;
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i + 1;
    while (j < faces.size() && std::equal(faces[i].begin(), faces[i].begin() + 4, faces[j].begin()))
    {
      ++j;
    }
    if (j - i >= 3 || (j - i == 2 && faces[i][4] == faces[i + 1][4]))
    {
      for (size_t k = i; k < j; ++k)
      {
        candidates.push_back(faces[k][5]);
      }
    }
    i = j;
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  if (candidates.empty() || candidates.size() > 64)
  {
    return 0; // none, or a fold too large to mend hex by hex
  }
  std::stable_sort(candidates.begin(), candidates.end(),
    [&quality](int a, int b) { return quality[a] < quality[b]; });

  auto defects = [](const HexMesh& candidate)
  {
    HexMeshValidity validity;
    if (!checkHexMeshValidity(candidate, validity))
    {
      return std::numeric_limits<int>::max();
    }
    return validity.OverSharedQuadCount + validity.MisorientedQuadCount +
      validity.NonManifoldBoundaryEdgeCount + validity.NonManifoldBoundaryVertexCount;
  };
  int current = defects(mesh);
  std::vector<int> uses = VertexUses(mesh);
  std::vector<char> remove(static_cast<size_t>(hexCount), 0);
  auto without = [&]() { return WithoutHexes(mesh, remove); };
  for (const int h : candidates)
  {
    if (current == 0)
    {
      break;
    }
    bool orphans = false;
    for (int k = 0; k < 8; ++k)
    {
      orphans = orphans || uses[static_cast<size_t>(mesh.Cells(h, k))] <= 1;
    }
    if (orphans)
    {
      continue;
    }
    remove[static_cast<size_t>(h)] = 1;
    const int after = defects(without());
    if (after >= current)
    {
      remove[static_cast<size_t>(h)] = 0;
      continue;
    }
    current = after;
    for (int k = 0; k < 8; ++k)
    {
      --uses[static_cast<size_t>(mesh.Cells(h, k))];
    }
  }
  const int count = static_cast<int>(std::count(remove.begin(), remove.end(), 1));
  if (count > 0)
  {
    mesh.Cells = without().Cells;
  }
  return count;
}

namespace
{
/// Combinatorial defects of `mesh` (INT_MAX when it cannot be checked), and its validity.
int CountDefects(const HexMesh& mesh, HexMeshValidity& validity)
{
  if (!checkHexMeshValidity(mesh, validity))
  {
    return std::numeric_limits<int>::max();
  }
  return validity.OverSharedQuadCount + validity.MisorientedQuadCount +
    validity.NonManifoldBoundaryEdgeCount + validity.NonManifoldBoundaryVertexCount;
}

/// The vertices of boundary edges not used by exactly two boundary quads, and of boundary
/// vertices whose quads form more than one fan (connected through edges at the vertex).
std::vector<int> PinchVertices(int vertexCount, const Quads& boundary)
{
  std::map<std::pair<int, int>, int> edgeUses;
  for (Eigen::Index q = 0; q < boundary.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int a = boundary(q, k);
      const int b = boundary(q, (k + 1) % 4);
      ++edgeUses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::vector<char> pinched(static_cast<size_t>(vertexCount), 0);
  for (const auto& entry : edgeUses)
  {
    if (entry.second != 2)
    {
      pinched[static_cast<size_t>(entry.first.first)] = 1;
      pinched[static_cast<size_t>(entry.first.second)] = 1;
    }
  }
  // Fans: at each vertex, its quads joined when they share one of the vertex's edges.
  std::vector<std::vector<int>> vertexQuads(static_cast<size_t>(vertexCount));
  for (Eigen::Index q = 0; q < boundary.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      vertexQuads[static_cast<size_t>(boundary(q, k))].push_back(static_cast<int>(q));
    }
  }
  for (int v = 0; v < vertexCount; ++v)
  {
    const auto& quads = vertexQuads[static_cast<size_t>(v)];
    if (quads.size() < 2 || pinched[static_cast<size_t>(v)])
    {
      continue;
    }
    // The other end of each quad's two edges at v.
    auto neighbours = [&](int q)
    {
      int k = 0;
      while (boundary(q, k) != v)
      {
        ++k;
      }
      return std::array<int, 2>{ boundary(q, (k + 1) % 4), boundary(q, (k + 3) % 4) };
    };
    std::vector<int> fan(quads.size());
    std::iota(fan.begin(), fan.end(), 0);
    auto root = [&fan](int i)
    {
      while (fan[static_cast<size_t>(i)] != i)
      {
        i = fan[static_cast<size_t>(i)] = fan[static_cast<size_t>(fan[static_cast<size_t>(i)])];
      }
      return i;
    };
    for (size_t i = 0; i < quads.size(); ++i)
    {
      for (size_t j = i + 1; j < quads.size(); ++j)
      {
        const auto a = neighbours(quads[i]);
        const auto b = neighbours(quads[j]);
        if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1])
        {
          fan[static_cast<size_t>(root(static_cast<int>(i)))] = root(static_cast<int>(j));
        }
      }
    }
    int fans = 0;
    for (size_t i = 0; i < quads.size(); ++i)
    {
      fans += root(static_cast<int>(i)) == static_cast<int>(i) ? 1 : 0;
    }
    pinched[static_cast<size_t>(v)] = fans > 1 ? 1 : 0;
  }
  std::vector<int> vertices;
  for (int v = 0; v < vertexCount; ++v)
  {
    if (pinched[static_cast<size_t>(v)])
    {
      vertices.push_back(v);
    }
  }
  return vertices;
}
} // namespace

int RemovePinchingHexes(HexMesh& mesh, const Eigen::VectorXd& quality, std::vector<int>* removed)
{
  if (removed)
  {
    removed->clear();
  }
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  std::vector<char> remove(static_cast<size_t>(hexCount), 0);
  HexMeshValidity validity;
  int current = CountDefects(mesh, validity);
  if (current == 0 || current == std::numeric_limits<int>::max())
  {
    return 0;
  }
  std::vector<int> uses = VertexUses(mesh);
  // The hexes left that touch a pinch of `state`, worst first; empty when there are none or
  // too many to mend hex by hex.
  auto candidatesOf = [&](const HexMeshValidity& state)
  {
    std::vector<int> candidates;
    const std::vector<int> pinched = PinchVertices(vertexCount, state.BoundaryQuads);
    if (pinched.size() > 64)
    {
      return candidates;
    }
    std::vector<char> isPinched(static_cast<size_t>(vertexCount), 0);
    for (int v : pinched)
    {
      isPinched[static_cast<size_t>(v)] = 1;
    }
    for (int h = 0; h < hexCount; ++h)
    {
      for (int k = 0; k < 8 && !remove[static_cast<size_t>(h)]; ++k)
      {
        if (isPinched[static_cast<size_t>(mesh.Cells(h, k))])
        {
          candidates.push_back(h);
          break;
        }
      }
    }
    std::stable_sort(candidates.begin(), candidates.end(),
      [&quality](int a, int b) { return quality[a] < quality[b]; });
    return candidates;
  };
  // Removes h (false when that would leave a vertex unused), or puts it back.
  auto take = [&](int h)
  {
    for (int k = 0; k < 8; ++k)
    {
      if (uses[static_cast<size_t>(mesh.Cells(h, k))] <= 1)
      {
        return false;
      }
    }
    remove[static_cast<size_t>(h)] = 1;
    for (int k = 0; k < 8; ++k)
    {
      --uses[static_cast<size_t>(mesh.Cells(h, k))];
    }
    return true;
  };
  auto putBack = [&](int h)
  {
    remove[static_cast<size_t>(h)] = 0;
    for (int k = 0; k < 8; ++k)
    {
      ++uses[static_cast<size_t>(mesh.Cells(h, k))];
    }
  };
  // Keeps the current removals when they leave fewer defects.
  auto acceptIfFewer = [&](int defects, HexMeshValidity& after)
  {
    if (defects >= current)
    {
      return false;
    }
    current = defects;
    validity = std::move(after);
    return true;
  };
  // One removal that lowers the defects, else a pair (a removal often moves a pinch to the
  // next cube of a diagonal chain: the second one then mends it).
  for (int round = 0; round < 16 && current > 0; ++round)
  {
    bool mended = false;
    const std::vector<int> candidates = candidatesOf(validity);
    for (size_t i = 0; i < candidates.size() && !mended; ++i)
    {
      const int h = candidates[i];
      if (!take(h))
      {
        continue;
      }
      HexMeshValidity after;
      const int defects = CountDefects(WithoutHexes(mesh, remove), after);
      const std::vector<int> seconds = defects == current ? candidatesOf(after) : std::vector<int>();
      mended = acceptIfFewer(defects, after);
      for (size_t j = 0; j < seconds.size() && !mended; ++j)
      {
        if (!take(seconds[j]))
        {
          continue;
        }
        HexMeshValidity pair;
        mended = acceptIfFewer(CountDefects(WithoutHexes(mesh, remove), pair), pair);
        if (!mended)
        {
          putBack(seconds[j]);
        }
      }
      if (!mended)
      {
        putBack(h);
      }
    }
    if (!mended)
    {
      break;
    }
  }
  const int count = static_cast<int>(std::count(remove.begin(), remove.end(), 1));
  if (count == 0)
  {
    return 0;
  }
  if (removed)
  {
    for (int h = 0; h < hexCount; ++h)
    {
      if (remove[static_cast<size_t>(h)])
      {
        removed->push_back(h);
      }
    }
  }
  mesh.Cells = WithoutHexes(mesh, remove).Cells;
  return count;
}

} // namespace polycubehex
