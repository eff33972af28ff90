// SPDX-License-Identifier: BSD-3-Clause
#include "CutSurface.h"

#include "DisjointSets.h"
#include "TetGeometry.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace polycubehex
{

namespace
{

std::string EdgeName(const TetAdjacency& adjacency, int edge)
{
  return "(" + std::to_string(adjacency.EdgeVertices[edge][0]) + ", " +
    std::to_string(adjacency.EdgeVertices[edge][1]) + ")";
}
} // namespace

std::array<int, 3> OrientedCutFace(const Tets& cells,
  const TetAdjacency& adjacency,
  const CutFaceEntry& entry)
{
  int t = adjacency.InteriorFaces[entry.Face][0];
  int k = adjacency.InteriorFaces[entry.Face][1];
  if (entry.Side < 0)
  {
    const int n = adjacency.Neighbor(t, k);
    k = adjacency.NeighborFace(t, k);
    t = n;
  }
  return {
    cells(t, TetFaceTable[k][0]), cells(t, TetFaceTable[k][1]), cells(t, TetFaceTable[k][2])
  };
}

int CountMismatchedCutEdges(const TetAdjacency& input,
  const std::vector<std::vector<int>>& loops,
  const std::vector<int>& toOriginal)
{
  std::map<std::pair<int, int>, int> uses;
  for (const std::vector<int>& loop : loops)
  {
    for (size_t i = 0; i < loop.size(); ++i)
    {
      const int a = toOriginal[loop[i]];
      const int b = toOriginal[loop[(i + 1) % loop.size()]];
      ++uses[std::minmax(a, b)];
    }
  }
  int mismatched = 0;
  for (const auto& entry : uses)
  {
    const std::array<int, 2> key{ entry.first.first, entry.first.second };
    const auto found = std::lower_bound(input.EdgeVertices.begin(), input.EdgeVertices.end(), key);
    const bool interior = found != input.EdgeVertices.end() && *found == key &&
      !input.EdgeOnBoundary[found - input.EdgeVertices.begin()];
    mismatched += interior && entry.second % 2 != 0 ? 1 : 0;
  }
  return mismatched;
}

double InteriorFaceArea(const Tets& cells,
  const TetAdjacency& adjacency,
  const Points& points,
  int face)
{
  const int t = adjacency.InteriorFaces[face][0];
  const int k = adjacency.InteriorFaces[face][1];
  const Eigen::Vector3d a = points.row(cells(t, TetFaceTable[k][0])).transpose();
  const Eigen::Vector3d b = points.row(cells(t, TetFaceTable[k][1])).transpose();
  const Eigen::Vector3d c = points.row(cells(t, TetFaceTable[k][2])).transpose();
  return 0.5 * (b - a).cross(c - a).norm();
}

void AnalyzeCutSurface(const Tets& cells,
  const TetAdjacency& adjacency,
  const Points& points,
  const std::vector<CutFaceEntry>& faces,
  CutSurfaceReport& report)
{
  report = CutSurfaceReport();
  const int count = static_cast<int>(faces.size());
  if (count == 0)
  {
    report.Problem = "the cut is empty";
    return;
  }
  std::ostringstream problem;

  // Edges of the cut faces.
  std::unordered_map<int, std::vector<int>> edgeFaces; // edge -> cut faces (indices into faces)
  std::vector<std::array<int, 3>> faceEdges(count);
  std::unordered_map<int, int> sideOfFace; // interior face id -> index into faces
  for (int i = 0; i < count; ++i)
  {
    const int face = faces[i].Face;
    if (!sideOfFace.emplace(face, i).second)
    {
      report.Problem = "face " + std::to_string(face) + " is listed twice";
      return;
    }
    report.Area += InteriorFaceArea(cells, adjacency, points, face);
    const int t = adjacency.InteriorFaces[face][0];
    const int k = adjacency.InteriorFaces[face][1];
    for (int c = 0; c < 3; ++c)
    {
      const int edge =
        adjacency.TetEdge(t, TetLocalEdge(TetFaceTable[k][c], TetFaceTable[k][(c + 1) % 3]));
      faceEdges[i][c] = edge;
      edgeFaces[edge].push_back(i);
    }
  }

  // Connectivity through cut edges.
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& entry : edgeFaces)
  {
    for (size_t j = 1; j < entry.second.size(); ++j)
    {
      parent[FindRoot(parent, entry.second[j])] = FindRoot(parent, entry.second[0]);
    }
  }
  int components = 0;
  for (int i = 0; i < count; ++i)
  {
    components += FindRoot(parent, i) == i ? 1 : 0;
  }
  report.Connected = components == 1;
  if (!report.Connected)
  {
    problem << "the cut has " << components << " components; ";
  }

  // Edges: 2 cut faces inside the solid, 1 on its boundary; sides agree inside.
  bool manifold = true;
  bool twoSided = true;
  std::vector<int> sortedEdges;
  for (const auto& entry : edgeFaces)
  {
    sortedEdges.push_back(entry.first);
  }
  std::sort(sortedEdges.begin(), sortedEdges.end()); // deterministic messages
  std::vector<EdgeRingStep> ring;
  bool closed = false;
  int boundaryEdgeCount = 0;
  for (int edge : sortedEdges)
  {
    const std::vector<int>& at = edgeFaces[edge];
    const bool onBoundary = adjacency.EdgeOnBoundary[edge] != 0;
    const size_t wanted = onBoundary ? 1 : 2;
    if (at.size() != wanted)
    {
      if (manifold)
      {
        problem << "edge " << EdgeName(adjacency, edge)
                << (onBoundary ? " on the boundary" : " inside") << " holds " << at.size()
                << " cut faces; ";
      }
      manifold = false;
      continue;
    }
    if (onBoundary)
    {
      ++boundaryEdgeCount;
      continue;
    }
    // The two cut faces split the ring around the edge into two arcs: both minus tets must lie
    // in the same arc (this needs no tet orientation).
    WalkAroundEdge(cells, adjacency, edge, ring, closed);
    const int n = static_cast<int>(ring.size());
    int minusAfter[2] = { 0, 0 }; // 1 when the minus tet is ring[i + 1], 0 when ring[i]
    int found = 0;
    for (int i = 0; i < n && found < 2; ++i)
    {
      const int face = adjacency.InteriorFaceId(ring[i].Tet, ring[i].Exit);
      const auto it = sideOfFace.find(face);
      if (it == sideOfFace.end())
      {
        continue;
      }
      const CutFaceEntry& entry = faces[it->second];
      const int minusTet = entry.Side > 0
        ? adjacency.InteriorFaces[face][0]
        : adjacency.Neighbor(adjacency.InteriorFaces[face][0], adjacency.InteriorFaces[face][1]);
      minusAfter[found] = minusTet == ring[i].Tet ? 0 : 1;
      ++found;
    }
    // With the two cut faces at ring positions i0 < i1, arc A = ring[i0 + 1 .. i1]: the minus
    // tet of face 0 is in A when it is ring[i0 + 1]; that of face 1 when it is ring[i1].
    const bool firstInA = minusAfter[0] == 1;
    const bool secondInA = minusAfter[1] == 0;
    if (found != 2 || firstInA != secondInA)
    {
      if (twoSided)
      {
        problem << "the sides of the cut disagree across edge " << EdgeName(adjacency, edge)
                << "; ";
      }
      twoSided = false;
    }
  }

  // Vertex fans: the cut faces around a cut vertex form one fan; at a boundary vertex it must
  // end on the boundary (a cut touching the boundary at an isolated vertex is not proper).
  std::unordered_map<int, std::vector<int>> vertexFaces;
  for (int i = 0; i < count; ++i)
  {
    const std::array<int, 3> tri = OrientedCutFace(cells, adjacency, faces[i]);
    for (int v : tri)
    {
      vertexFaces[v].push_back(i);
    }
  }
  std::vector<int> sortedVertices;
  for (const auto& entry : vertexFaces)
  {
    sortedVertices.push_back(entry.first);
  }
  std::sort(sortedVertices.begin(), sortedVertices.end());
  std::vector<int> localParent;
  std::vector<std::pair<int, int>> edgeToLocal;
  for (int v : sortedVertices)
  {
    const std::vector<int>& around = vertexFaces[v];
    localParent.resize(around.size());
    std::iota(localParent.begin(), localParent.end(), 0);
    edgeToLocal.clear();
    bool endsOnBoundary = false;
    for (size_t j = 0; j < around.size(); ++j)
    {
      for (int edge : faceEdges[around[j]])
      {
        if (adjacency.EdgeVertices[edge][0] != v && adjacency.EdgeVertices[edge][1] != v)
        {
          continue;
        }
        endsOnBoundary = endsOnBoundary || adjacency.EdgeOnBoundary[edge];
        bool seen = false;
        for (const auto& entry : edgeToLocal)
        {
          if (entry.first == edge)
          {
            localParent[FindRoot(localParent, static_cast<int>(j))] =
              FindRoot(localParent, entry.second);
            seen = true;
          }
        }
        if (!seen)
        {
          edgeToLocal.emplace_back(edge, static_cast<int>(j));
        }
      }
    }
    int fans = 0;
    for (size_t j = 0; j < around.size(); ++j)
    {
      fans += FindRoot(localParent, static_cast<int>(j)) == static_cast<int>(j) ? 1 : 0;
    }
    if (fans != 1)
    {
      if (manifold)
      {
        problem << "the cut faces around vertex " << v << " form " << fans << " fans; ";
      }
      manifold = false;
    }
    else if (adjacency.VertexOnBoundary[v] && !endsOnBoundary)
    {
      if (manifold)
      {
        problem << "the cut touches the boundary at vertex " << v << " inside the cut; ";
      }
      manifold = false;
    }
  }
  report.Manifold = manifold;
  report.TwoSided = twoSided;
  report.EulerCharacteristic =
    static_cast<int>(vertexFaces.size()) - static_cast<int>(edgeFaces.size()) + count;

  // Boundary loops, oriented as the boundary of the cut faces seen from their minus side.
  if (manifold)
  {
    std::unordered_map<int, std::vector<std::array<int, 2>>> outgoing; // vertex -> (to, edge)
    for (int i = 0; i < count; ++i)
    {
      const std::array<int, 3> tri = OrientedCutFace(cells, adjacency, faces[i]);
      for (int c = 0; c < 3; ++c)
      {
        const int a = tri[c];
        const int b = tri[(c + 1) % 3];
        for (int e : faceEdges[i])
        {
          const auto& ev = adjacency.EdgeVertices[e];
          if (adjacency.EdgeOnBoundary[e] &&
            ((ev[0] == a && ev[1] == b) || (ev[0] == b && ev[1] == a)))
          {
            outgoing[a].push_back({ b, e });
          }
        }
      }
    }
    std::unordered_map<int, char> used;
    std::vector<int> starts;
    for (const auto& entry : outgoing)
    {
      starts.push_back(entry.first);
    }
    std::sort(starts.begin(), starts.end());
    for (int start : starts)
    {
      for (const auto& first : outgoing[start])
      {
        if (used[first[1]])
        {
          continue;
        }
        std::vector<int> loop{ start };
        used[first[1]] = 1;
        int current = first[0];
        int guard = 0;
        while (current != start && guard++ <= boundaryEdgeCount)
        {
          loop.push_back(current);
          bool advanced = false;
          for (const auto& next : outgoing[current])
          {
            if (!used[next[1]])
            {
              used[next[1]] = 1;
              current = next[0];
              advanced = true;
              break;
            }
          }
          if (!advanced)
          {
            break;
          }
        }
        report.Loops.push_back(std::move(loop));
      }
    }
  }
  report.Problem = problem.str();
  if (report.Problem.size() >= 2)
  {
    report.Problem.resize(report.Problem.size() - 2);
  }
}

} // namespace polycubehex
