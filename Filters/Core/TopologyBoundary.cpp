// SPDX-License-Identifier: BSD-3-Clause
#include "TopologyBoundary.h"

#include "DisjointSets.h"
#include "TetGeometry.h"

#include <numeric>
#include <sstream>

namespace polycubehex
{


Status ComputeBoundaryTopology(const Tets& cells,
  const TetAdjacency& adjacency,
  BoundaryTopology& topology)
{
  topology = BoundaryTopology();
  const int tetCount = adjacency.TetCount;
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (adjacency.Neighbor(t, k) < 0)
      {
        topology.Faces.push_back({ t, k });
      }
    }
  }
  const int faceCount = static_cast<int>(topology.Faces.size());
  const int edgeCount = static_cast<int>(adjacency.EdgeVertices.size());

  // Edge ids of each boundary face, and the faces at every boundary edge.
  std::vector<std::array<int, 3>> faceEdges(faceCount);
  std::vector<int> edgeFaceCount(edgeCount, 0);
  std::vector<int> edgeFirstFace(edgeCount, -1);
  std::vector<int> parent(faceCount);
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < faceCount; ++f)
  {
    const int t = topology.Faces[f][0];
    const int k = topology.Faces[f][1];
    for (int c = 0; c < 3; ++c)
    {
      const int edge =
        adjacency.TetEdge(t, TetLocalEdge(TetFaceTable[k][c], TetFaceTable[k][(c + 1) % 3]));
      faceEdges[f][c] = edge;
      ++edgeFaceCount[edge];
      if (edgeFirstFace[edge] < 0)
      {
        edgeFirstFace[edge] = f;
      }
      else
      {
        parent[FindRoot(parent, f)] = FindRoot(parent, edgeFirstFace[edge]);
      }
    }
  }
  for (int e = 0; e < edgeCount; ++e)
  {
    if (edgeFaceCount[e] != 0 && edgeFaceCount[e] != 2)
    {
      std::ostringstream message;
      message << "the boundary is not a closed 2-manifold: boundary edge ("
              << adjacency.EdgeVertices[e][0] << ", " << adjacency.EdgeVertices[e][1]
              << ") lies on " << edgeFaceCount[e] << " boundary faces";
      return Status::Failure(message.str());
    }
  }

  // Every boundary vertex: its boundary faces must form one fan.
  const int vertexCount = adjacency.VertexCount;
  std::vector<int> offsets(static_cast<size_t>(vertexCount) + 1, 0);
  for (int f = 0; f < faceCount; ++f)
  {
    for (int c = 0; c < 3; ++c)
    {
      ++offsets[cells(topology.Faces[f][0], TetFaceTable[topology.Faces[f][1]][c]) + 1];
    }
  }
  for (int v = 0; v < vertexCount; ++v)
  {
    offsets[v + 1] += offsets[v];
  }
  std::vector<int> vertexFaces(offsets.back());
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int f = 0; f < faceCount; ++f)
    {
      for (int c = 0; c < 3; ++c)
      {
        vertexFaces[fill[cells(topology.Faces[f][0], TetFaceTable[topology.Faces[f][1]][c])]++] = f;
      }
    }
  }
  std::vector<int> localParent;
  std::vector<std::pair<int, int>> edgeToLocal; // (edge, local face index) around one vertex
  for (int v = 0; v < vertexCount; ++v)
  {
    const int begin = offsets[v];
    const int count = offsets[v + 1] - begin;
    if (count == 0)
    {
      continue;
    }
    localParent.resize(count);
    std::iota(localParent.begin(), localParent.end(), 0);
    edgeToLocal.clear();
    for (int i = 0; i < count; ++i)
    {
      const int f = vertexFaces[begin + i];
      const int t = topology.Faces[f][0];
      const int k = topology.Faces[f][1];
      for (int c = 0; c < 3; ++c)
      {
        const int a = cells(t, TetFaceTable[k][c]);
        const int b = cells(t, TetFaceTable[k][(c + 1) % 3]);
        if (a != v && b != v)
        {
          continue;
        }
        const int edge = faceEdges[f][c];
        bool found = false;
        for (const auto& entry : edgeToLocal)
        {
          if (entry.first == edge)
          {
            localParent[FindRoot(localParent, i)] = FindRoot(localParent, entry.second);
            found = true;
            break;
          }
        }
        if (!found)
        {
          edgeToLocal.emplace_back(edge, i);
        }
      }
    }
    int fans = 0;
    for (int i = 0; i < count; ++i)
    {
      fans += FindRoot(localParent, i) == i ? 1 : 0;
    }
    if (fans != 1)
    {
      std::ostringstream message;
      message << "the boundary is not a closed 2-manifold: the boundary faces around vertex " << v
              << " form " << fans << " separate fans (a pinched vertex)";
      return Status::Failure(message.str());
    }
  }

  // Components and their Euler characteristics.
  std::vector<int> rootToComponent(faceCount, -1);
  topology.FaceComponent.resize(faceCount);
  int componentCount = 0;
  for (int f = 0; f < faceCount; ++f)
  {
    const int root = FindRoot(parent, f);
    if (rootToComponent[root] < 0)
    {
      rootToComponent[root] = componentCount++;
    }
    topology.FaceComponent[f] = rootToComponent[root];
  }
  std::vector<long long> euler(componentCount, 0);
  for (int f = 0; f < faceCount; ++f)
  {
    ++euler[topology.FaceComponent[f]];
  }
  for (int e = 0; e < edgeCount; ++e)
  {
    if (edgeFaceCount[e] == 2)
    {
      --euler[topology.FaceComponent[edgeFirstFace[e]]];
    }
  }
  for (int v = 0; v < vertexCount; ++v)
  {
    if (offsets[v + 1] > offsets[v])
    {
      ++euler[topology.FaceComponent[vertexFaces[offsets[v]]]];
    }
  }
  topology.ComponentEuler.resize(componentCount);
  topology.ComponentGenus.resize(componentCount);
  for (int c = 0; c < componentCount; ++c)
  {
    const long long chi = euler[c];
    if (chi > 2 || (chi % 2) != 0)
    {
      std::ostringstream message;
      message << "boundary component " << c << " has Euler characteristic " << chi
              << ": not a closed orientable surface";
      return Status::Failure(message.str());
    }
    topology.ComponentEuler[c] = static_cast<int>(chi);
    topology.ComponentGenus[c] = static_cast<int>((2 - chi) / 2);
    topology.Beta1 += topology.ComponentGenus[c];
  }
  topology.SolidComponentCount = CountSolidComponents(adjacency, {});
  topology.Beta2 = componentCount - topology.SolidComponentCount;
  return Status::Success();
}

} // namespace polycubehex
