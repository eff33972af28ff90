// SPDX-License-Identifier: BSD-3-Clause
#include "HexMeshValidity.h"

#include "DisjointSets.h"
#include <algorithm>
#include <numeric>
#include <sstream>
#include <tuple>
#include <vector>

namespace polycubehex
{
namespace
{
/// One hex face, keyed by its sorted vertex indices so that both sides of a quad meet.
struct FaceUse
{
  std::array<int, 4> Key;
  int Hex;
  int Face;
};

/// One directed edge of a boundary quad, keyed by its unordered end points.
struct EdgeUse
{
  int Low;
  int High;
  int Quad;
  bool Forward; ///< the quad walks the edge from Low to High
};

std::array<int, 4> OrientedQuad(const HexMesh& mesh, int hex, int face)
{
  std::array<int, 4> quad;
  for (int k = 0; k < 4; ++k)
  {
    quad[k] = mesh.Cells(hex, HexFaces[face][k]);
  }
  return quad;
}

bool HasRepeats(std::array<int, 4> key)
{
  return key[0] == key[1] || key[1] == key[2] || key[2] == key[3];
}

/// True when b walks the same 4 vertices as a in the opposite cyclic direction, which is how
/// the two hexes on either side of an interior quad see it.
bool IsReversed(const std::array<int, 4>& a, const std::array<int, 4>& b)
{
  const auto start = std::find(b.begin(), b.end(), a[0]);
  const int p = static_cast<int>(start - b.begin());
  return p < 4 && b[(p + 3) % 4] == a[1] && b[(p + 2) % 4] == a[2] && b[(p + 1) % 4] == a[3];
}


/// Degenerate hexes: a repeated index makes at least one face or edge collapse.
void CheckDistinctVertices(const HexMesh& mesh, HexMeshValidity& result, std::ostream& report)
{
  for (int h = 0; h < mesh.Cells.rows(); ++h)
  {
    std::array<int, 8> sorted;
    for (int k = 0; k < 8; ++k)
    {
      sorted[k] = mesh.Cells(h, k);
    }
    std::sort(sorted.begin(), sorted.end());
    const auto repeat = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeat == sorted.end())
    {
      continue;
    }
    if (result.DegenerateHexCount++ == 0)
    {
      report << "degenerate hexes (repeated vertex): first is hex " << h << ", vertex " << *repeat
             << " appears twice\n";
    }
  }
}

/// Matches the 6 faces of every hex with each other; returns the boundary faces as
/// (hex, face) pairs in hex order.
std::vector<std::pair<int, int>> MatchFaces(const HexMesh& mesh,
  HexMeshValidity& result,
  std::ostream& report)
{
  std::vector<FaceUse> uses;
  uses.reserve(6 * static_cast<size_t>(mesh.Cells.rows()));
  for (int h = 0; h < mesh.Cells.rows(); ++h)
  {
    for (int f = 0; f < 6; ++f)
    {
      FaceUse use{ OrientedQuad(mesh, h, f), h, f };
      std::sort(use.Key.begin(), use.Key.end());
      uses.push_back(use);
    }
  }
  // Sorting (rather than hashing) keeps the order, and so the first offender, deterministic.
  std::sort(uses.begin(),
    uses.end(),
    [](const FaceUse& a, const FaceUse& b)
    { return std::tie(a.Key, a.Hex, a.Face) < std::tie(b.Key, b.Hex, b.Face); });

  std::vector<std::pair<int, int>> boundary;
  for (size_t begin = 0, end = 0; begin < uses.size(); begin = end)
  {
    end = begin + 1;
    while (end < uses.size() && uses[end].Key == uses[begin].Key)
    {
      ++end;
    }
    const size_t count = end - begin;
    const FaceUse& first = uses[begin];
    if (count == 1)
    {
      boundary.emplace_back(first.Hex, first.Face);
    }
    else if (count == 2)
    {
      const FaceUse& second = uses[begin + 1];
      // A quad with a repeated vertex has no orientation; its hex is already reported.
      if (!HasRepeats(first.Key) &&
        !IsReversed(
          OrientedQuad(mesh, first.Hex, first.Face), OrientedQuad(mesh, second.Hex, second.Face)))
      {
        if (result.MisorientedQuadCount++ == 0)
        {
          const auto quad = OrientedQuad(mesh, first.Hex, first.Face);
          report << "quads whose two hexes lie on the same side (overlap or inversion): first "
                 << "is quad " << quad[0] << " " << quad[1] << " " << quad[2] << " " << quad[3]
                 << " of hexes " << first.Hex << " and " << second.Hex << "\n";
        }
      }
    }
    else
    {
      if (result.OverSharedQuadCount++ == 0)
      {
        const auto quad = OrientedQuad(mesh, first.Hex, first.Face);
        report << "quads shared by more than two hexes: first is quad " << quad[0] << " " << quad[1]
               << " " << quad[2] << " " << quad[3] << ", used by " << count << " hexes:";
        for (size_t i = begin; i < end; ++i)
        {
          report << " " << uses[i].Hex;
        }
        report << "\n";
      }
    }
  }
  std::sort(boundary.begin(), boundary.end());
  return boundary;
}

/// A closed oriented 2-manifold walks each edge exactly twice, once in each direction.
void CheckBoundaryEdges(const Quads& quads, HexMeshValidity& result, std::ostream& report)
{
  std::vector<EdgeUse> edges;
  edges.reserve(4 * static_cast<size_t>(quads.rows()));
  for (int q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int u = quads(q, k);
      const int v = quads(q, (k + 1) % 4);
      if (u != v)
      {
        edges.push_back({ std::min(u, v), std::max(u, v), q, u < v });
      }
    }
  }
  std::sort(edges.begin(),
    edges.end(),
    [](const EdgeUse& a, const EdgeUse& b)
    {
      return std::tie(a.Low, a.High, a.Quad, a.Forward) <
        std::tie(b.Low, b.High, b.Quad, b.Forward);
    });
  for (size_t begin = 0, end = 0; begin < edges.size(); begin = end)
  {
    end = begin + 1;
    while (end < edges.size() && edges[end].Low == edges[begin].Low &&
      edges[end].High == edges[begin].High)
    {
      ++end;
    }
    const size_t count = end - begin;
    const bool manifold = count == 2 && edges[begin].Forward != edges[begin + 1].Forward;
    if (manifold)
    {
      continue;
    }
    if (result.NonManifoldBoundaryEdgeCount++ == 0)
    {
      report << "boundary edges not shared by exactly two oppositely oriented boundary quads "
             << "(open, touching or flipped boundary): first is edge " << edges[begin].Low << "-"
             << edges[begin].High << ", in " << count << " boundary quad(s)\n";
    }
  }
}

/// Around a manifold boundary vertex the boundary quads form one fan; two cubes touching at a
/// vertex give two fans. Also counts irregular vertices (boundary valence other than 4).
void CheckBoundaryVertices(const Quads& quads,
  int vertexCount,
  HexMeshValidity& result,
  std::ostream& report)
{
  // Corners of boundary quads grouped by vertex (compressed rows).
  std::vector<int> offsets(vertexCount + 1, 0);
  for (int q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      ++offsets[quads(q, k) + 1];
    }
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<int> corners(offsets.back());
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (int q = 0; q < quads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      corners[fill[quads(q, k)]++] = 4 * q + k;
    }
  }

  std::vector<std::pair<int, int>> neighbours; // (vertex across a boundary edge, local corner)
  std::vector<int> parent;
  for (int v = 0; v < vertexCount; ++v)
  {
    const int valence = offsets[v + 1] - offsets[v];
    if (valence == 0)
    {
      continue;
    }
    if (valence != 4)
    {
      ++result.IrregularBoundaryVertexCount;
    }
    neighbours.clear();
    parent.resize(valence);
    std::iota(parent.begin(), parent.end(), 0);
    for (int i = 0; i < valence; ++i)
    {
      const int q = corners[offsets[v] + i] / 4;
      const int k = corners[offsets[v] + i] % 4;
      neighbours.emplace_back(quads(q, (k + 1) % 4), i);
      neighbours.emplace_back(quads(q, (k + 3) % 4), i);
    }
    // Two corners are in one fan when their quads share an edge at v.
    std::sort(neighbours.begin(), neighbours.end());
    for (size_t j = 1; j < neighbours.size(); ++j)
    {
      if (neighbours[j].first == neighbours[j - 1].first && neighbours[j].first != v)
      {
        parent[FindRoot(parent, neighbours[j].second)] = FindRoot(parent, neighbours[j - 1].second);
      }
    }
    int fans = 0;
    for (int i = 0; i < valence; ++i)
    {
      fans += FindRoot(parent, i) == i ? 1 : 0;
    }
    if (fans > 1 && result.NonManifoldBoundaryVertexCount++ == 0)
    {
      report << "non-manifold boundary vertices (several boundary fans meet): first is vertex " << v
             << ", with " << fans << " fans\n";
    }
  }
}
} // namespace

Status checkHexMeshValidity(const HexMesh& mesh, HexMeshValidity& result)
{
  result = HexMeshValidity();
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  if (mesh.Cells.rows() == 0)
  {
    return Status::Failure("the hex mesh has no hexahedra");
  }
  if (mesh.Cells.minCoeff() < 0 || mesh.Cells.maxCoeff() >= vertexCount)
  {
    std::ostringstream message;
    message << "a hex refers to a vertex index outside [0, " << vertexCount << ")";
    return Status::Failure(message.str());
  }
  result.HexCount = static_cast<int>(mesh.Cells.rows());

  std::ostringstream report;
  CheckDistinctVertices(mesh, result, report);
  const auto boundary = MatchFaces(mesh, result, report);
  result.BoundaryQuadCount = static_cast<int>(boundary.size());
  result.BoundaryQuads.resize(result.BoundaryQuadCount, 4);
  for (int b = 0; b < result.BoundaryQuadCount; ++b)
  {
    const auto quad = OrientedQuad(mesh, boundary[b].first, boundary[b].second);
    for (int k = 0; k < 4; ++k)
    {
      result.BoundaryQuads(b, k) = quad[k];
    }
  }
  CheckBoundaryEdges(result.BoundaryQuads, result, report);
  CheckBoundaryVertices(result.BoundaryQuads, vertexCount, result, report);

  std::ostringstream summary;
  summary << (result.IsValid() ? "combinatorially valid" : "combinatorially INVALID") << ": "
          << result.HexCount << " hexes, " << result.BoundaryQuadCount << " boundary quads, "
          << result.IrregularBoundaryVertexCount << " irregular boundary vertices\n";
  result.Report = summary.str() + report.str();
  return Status::Success();
}

} // namespace polycubehex
