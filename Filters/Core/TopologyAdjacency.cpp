// SPDX-License-Identifier: BSD-3-Clause
#include "TopologyAdjacency.h"

#include "TetGeometry.h"

#include <algorithm>
#include <sstream>

namespace polycubehex
{

namespace
{
struct SortedFace
{
  std::array<int, 3> Key;
  int Tet;
  int Local;
};

struct SortedEdge
{
  std::array<int, 2> Key;
  int Tet;
  int Local;
};

/// The other local face at the edge of `tet` entered through `entry`: the face opposite the
/// vertex of `entry` that is not on the edge (a, b).
int OtherFaceAtEdge(const Tets& cells, int tet, int entry, int a, int b)
{
  for (int c = 0; c < 3; ++c)
  {
    const int local = TetFaceTable[entry][c];
    const int vertex = cells(tet, local);
    if (vertex != a && vertex != b)
    {
      return TetOppositeFace[local];
    }
  }
  return -1;
}
} // namespace

Status BuildTetAdjacency(int vertexCount, const Tets& cells, TetAdjacency& adjacency)
{
  const int tetCount = static_cast<int>(cells.rows());
  adjacency = TetAdjacency();
  adjacency.VertexCount = vertexCount;
  adjacency.TetCount = tetCount;
  for (int t = 0; t < tetCount; ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      if (cells(t, i) < 0 || cells(t, i) >= vertexCount)
      {
        return Status::Failure("tet " + std::to_string(t) + " refers to vertex " +
          std::to_string(cells(t, i)) + ", outside [0, " + std::to_string(vertexCount) + ")");
      }
      for (int j = 0; j < i; ++j)
      {
        if (cells(t, i) == cells(t, j))
        {
          return Status::Failure(
            "tet " + std::to_string(t) + " repeats vertex " + std::to_string(cells(t, i)));
        }
      }
    }
  }

  // Faces: sort the 4T keys, equal neighbours are the two sides of an interior face.
  std::vector<SortedFace> faces;
  faces.reserve(4 * static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      SortedFace face{ { cells(t, TetFaceTable[k][0]),
                         cells(t, TetFaceTable[k][1]),
                         cells(t, TetFaceTable[k][2]) },
        t,
        k };
      std::sort(face.Key.begin(), face.Key.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(),
    faces.end(),
    [](const SortedFace& a, const SortedFace& b)
    {
      if (a.Key[0] != b.Key[0])
      {
        return a.Key[0] < b.Key[0];
      }
      if (a.Key[1] != b.Key[1])
      {
        return a.Key[1] < b.Key[1];
      }
      if (a.Key[2] != b.Key[2])
      {
        return a.Key[2] < b.Key[2];
      }
      return a.Tet != b.Tet ? a.Tet < b.Tet : a.Local < b.Local;
    });
  adjacency.Neighbor.setConstant(tetCount, 4, -1);
  adjacency.NeighborFace.setConstant(tetCount, 4, -1);
  adjacency.InteriorFaceId.setConstant(tetCount, 4, -1);
  adjacency.VertexOnBoundary.assign(vertexCount, 0);
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].Key == faces[i].Key)
    {
      ++j;
    }
    if (j - i > 2)
    {
      std::ostringstream message;
      message << "face (" << faces[i].Key[0] << ", " << faces[i].Key[1] << ", " << faces[i].Key[2]
              << ") is shared by " << (j - i) << " tets";
      return Status::Failure(message.str());
    }
    if (j - i == 2)
    {
      const SortedFace& a = faces[i];
      const SortedFace& b = faces[i + 1];
      adjacency.Neighbor(a.Tet, a.Local) = b.Tet;
      adjacency.NeighborFace(a.Tet, a.Local) = b.Local;
      adjacency.Neighbor(b.Tet, b.Local) = a.Tet;
      adjacency.NeighborFace(b.Tet, b.Local) = a.Local;
      const int id = static_cast<int>(adjacency.InteriorFaces.size());
      adjacency.InteriorFaceId(a.Tet, a.Local) = id;
      adjacency.InteriorFaceId(b.Tet, b.Local) = id;
      adjacency.InteriorFaces.push_back({ a.Tet, a.Local });
    }
    else
    {
      ++adjacency.BoundaryFaceCount;
      for (int c = 0; c < 3; ++c)
      {
        adjacency.VertexOnBoundary[faces[i].Key[c]] = 1;
      }
    }
    i = j;
  }
  faces.clear();
  faces.shrink_to_fit();

  // Edges.
  std::vector<SortedEdge> edges;
  edges.reserve(6 * static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (int e = 0; e < 6; ++e)
    {
      const int a = cells(t, TetEdgeTable[e][0]);
      const int b = cells(t, TetEdgeTable[e][1]);
      edges.push_back({ { std::min(a, b), std::max(a, b) }, t, e });
    }
  }
  std::sort(edges.begin(),
    edges.end(),
    [](const SortedEdge& a, const SortedEdge& b)
    {
      if (a.Key[0] != b.Key[0])
      {
        return a.Key[0] < b.Key[0];
      }
      if (a.Key[1] != b.Key[1])
      {
        return a.Key[1] < b.Key[1];
      }
      return a.Tet != b.Tet ? a.Tet < b.Tet : a.Local < b.Local;
    });
  adjacency.TetEdge.resize(tetCount, 6);
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    const int id = static_cast<int>(adjacency.EdgeVertices.size());
    adjacency.EdgeVertices.push_back(edges[i].Key);
    adjacency.EdgeTet.push_back({ edges[i].Tet, edges[i].Local });
    while (j < edges.size() && edges[j].Key == edges[i].Key)
    {
      adjacency.TetEdge(edges[j].Tet, edges[j].Local) = id;
      ++j;
    }
    i = j;
  }
  adjacency.EdgeOnBoundary.assign(adjacency.EdgeVertices.size(), 0);
  for (int t = 0; t < tetCount; ++t)
  {
    for (int e = 0; e < 6; ++e)
    {
      const std::array<int, 2> atEdge = FacesOfLocalEdge(e);
      if (adjacency.Neighbor(t, atEdge[0]) < 0 || adjacency.Neighbor(t, atEdge[1]) < 0)
      {
        adjacency.EdgeOnBoundary[adjacency.TetEdge(t, e)] = 1;
      }
    }
  }

  // Tets around each vertex.
  adjacency.VertexTetOffsets.assign(static_cast<size_t>(vertexCount) + 1, 0);
  for (int t = 0; t < tetCount; ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      ++adjacency.VertexTetOffsets[cells(t, i) + 1];
    }
  }
  for (int v = 0; v < vertexCount; ++v)
  {
    adjacency.VertexTetOffsets[v + 1] += adjacency.VertexTetOffsets[v];
  }
  adjacency.VertexTets.resize(4 * static_cast<size_t>(tetCount));
  std::vector<int> fill(adjacency.VertexTetOffsets.begin(), adjacency.VertexTetOffsets.end() - 1);
  for (int t = 0; t < tetCount; ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      adjacency.VertexTets[fill[cells(t, i)]++] = t;
    }
  }
  return Status::Success();
}

void WalkAroundEdge(const Tets& cells,
  const TetAdjacency& adjacency,
  int edge,
  std::vector<EdgeRingStep>& ring,
  bool& closed)
{
  ring.clear();
  const int a = adjacency.EdgeVertices[edge][0];
  const int b = adjacency.EdgeVertices[edge][1];
  const int start = adjacency.EdgeTet[edge][0];
  const std::array<int, 2> atEdge = FacesOfLocalEdge(adjacency.EdgeTet[edge][1]);

  // Forward from `start` through its first face at the edge.
  int tet = start;
  int exit = atEdge[0];
  closed = false;
  while (true)
  {
    ring.push_back({ tet, exit });
    const int next = adjacency.Neighbor(tet, exit);
    if (next < 0)
    {
      break;
    }
    if (next == start)
    {
      closed = true;
      return;
    }
    const int entry = adjacency.NeighborFace(tet, exit);
    exit = OtherFaceAtEdge(cells, next, entry, a, b);
    tet = next;
  }

  // A boundary edge: prepend the tets met backward from `start` through its second face.
  std::vector<EdgeRingStep> backward;
  tet = start;
  exit = atEdge[1];
  while (true)
  {
    const int next = adjacency.Neighbor(tet, exit);
    if (next < 0)
    {
      break;
    }
    const int entry = adjacency.NeighborFace(tet, exit);
    backward.push_back({ next, entry }); // `next` steps through `entry` into `tet`
    exit = OtherFaceAtEdge(cells, next, entry, a, b);
    tet = next;
  }
  std::reverse(backward.begin(), backward.end());
  backward.insert(backward.end(), ring.begin(), ring.end());
  ring.swap(backward);
}

int CountSolidComponents(const TetAdjacency& adjacency,
  const std::vector<char>& blocked,
  std::vector<int>* component)
{
  std::vector<int> label(adjacency.TetCount, -1);
  std::vector<int> stack;
  int count = 0;
  for (int seed = 0; seed < adjacency.TetCount; ++seed)
  {
    if (label[seed] >= 0)
    {
      continue;
    }
    label[seed] = count;
    stack.push_back(seed);
    while (!stack.empty())
    {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 4; ++k)
      {
        const int n = adjacency.Neighbor(t, k);
        if (n < 0 || label[n] >= 0)
        {
          continue;
        }
        if (!blocked.empty() && blocked[adjacency.InteriorFaceId(t, k)])
        {
          continue;
        }
        label[n] = count;
        stack.push_back(n);
      }
    }
    ++count;
  }
  if (component)
  {
    component->swap(label);
  }
  return count;
}

} // namespace polycubehex
