// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeCutMesh.h"

#include "CubeSymmetry.h"
#include "CutMesh.h"
#include "TopologyAdjacency.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

namespace polycubehex
{

Status BuildPolycubeCutMesh(const TetMesh& input, const PolycubeCuts& cuts, PolycubeCutMesh& out)
{
  const int tetCount = static_cast<int>(input.Cells.rows());
  const int vertexCount = static_cast<int>(input.Vertices.rows());
  if (cuts.FaceCut.rows() != tetCount || cuts.FaceSide.rows() != tetCount)
  {
    return Status::Failure("the cut arrays have " + std::to_string(cuts.FaceCut.rows()) +
      " rows for " + std::to_string(tetCount) + " tets");
  }
  for (int c = 0; c < cuts.Count(); ++c)
  {
    if (CubeRotationIndex(cuts.Transitions[static_cast<size_t>(c)]) < 0)
    {
      return Status::Failure("the transition of cut " + std::to_string(c) +
        " is not one of the 24 cube rotations");
    }
  }
  TetAdjacency adjacency;
  Status status = BuildTetAdjacency(vertexCount, input.Cells, adjacency);
  if (!status)
  {
    return status;
  }
  std::vector<char> cut(adjacency.InteriorFaces.size(), 0);
  for (size_t f = 0; f < adjacency.InteriorFaces.size(); ++f)
  {
    const int t = adjacency.InteriorFaces[f][0];
    const int k = adjacency.InteriorFaces[f][1];
    const int n = adjacency.Neighbor(t, k);
    const int nk = adjacency.NeighborFace(t, k);
    const int id = cuts.FaceCut(t, k);
    if (id != cuts.FaceCut(n, nk) || id >= cuts.Count() ||
      (id >= 0 && cuts.FaceSide(t, k) * cuts.FaceSide(n, nk) != -1))
    {
      std::ostringstream message;
      message << "face " << k << " of tet " << t
              << " is not marked as one cut face with two opposite sides on its two tets (cut ids "
              << id << " and " << cuts.FaceCut(n, nk) << ", " << cuts.Count() << " cuts)";
      return Status::Failure(message.str());
    }
    cut[f] = id >= 0 ? 1 : 0;
  }
  SplitAlongFaces(vertexCount, input.Cells, adjacency, cut, out.Cells, out.CopiedVertex);

  // Each vertex of a cut face: its copy in the minus tet and in the plus tet.
  std::set<std::array<int, 3>> seen;
  out.Copies.clear();
  for (size_t f = 0; f < adjacency.InteriorFaces.size(); ++f)
  {
    if (!cut[f])
    {
      continue;
    }
    int t = adjacency.InteriorFaces[f][0];
    int k = adjacency.InteriorFaces[f][1];
    int n = adjacency.Neighbor(t, k);
    if (cuts.FaceSide(t, k) > 0)
    {
      std::swap(t, n);
      k = adjacency.NeighborFace(n, k);
    }
    for (int i = 0; i < 3; ++i)
    {
      const int local = TetFaceTable[k][i];
      const int original = input.Cells(t, local);
      int plusLocal = 0;
      while (input.Cells(n, plusLocal) != original)
      {
        ++plusLocal;
      }
      const std::array<int, 3> key = { out.Cells(t, local), out.Cells(n, plusLocal),
        cuts.FaceCut(t, k) };
      if (seen.insert(key).second)
      {
        out.Copies.push_back({ key[0], key[1], key[2] });
      }
    }
  }
  return Status::Success();
}

std::vector<std::array<int, 2>> MirrorEdgesAcrossCuts(const std::vector<std::array<int, 2>>& edges,
  const std::vector<CopyRelation>& copies,
  int vertexCount,
  std::vector<std::array<int, 3>>& partnerEdges)
{
  partnerEdges.clear();
  std::vector<std::array<int, 2>> result = edges;
  if (copies.empty())
  {
    return result;
  }
  // Per vertex: (other copy, cut, +1 if this one is the minus copy).
  std::vector<std::vector<std::array<int, 3>>> partners(static_cast<size_t>(vertexCount));
  for (const CopyRelation& r : copies)
  {
    partners[static_cast<size_t>(r.Minus)].push_back({ r.Plus, r.Cut, 1 });
    partners[static_cast<size_t>(r.Plus)].push_back({ r.Minus, r.Cut, -1 });
  }
  std::map<std::array<int, 2>, int> index;
  for (size_t e = 0; e < result.size(); ++e)
  {
    index.emplace(std::array<int, 2>{ std::min(result[e][0], result[e][1]),
                    std::max(result[e][0], result[e][1]) },
      static_cast<int>(e));
  }
  for (size_t e = 0; e < result.size(); ++e) // grows while mirrored edges are appended
  {
    const std::array<int, 2> edge = result[e];
    for (const auto& pa : partners[static_cast<size_t>(edge[0])])
    {
      for (const auto& pb : partners[static_cast<size_t>(edge[1])])
      {
        if (pa[1] != pb[1] || pa[2] != pb[2])
        {
          continue; // both ends must cross the same cut in the same direction
        }
        const std::array<int, 2> mirrored = { std::min(pa[0], pb[0]), std::max(pa[0], pb[0]) };
        auto found = index.find(mirrored);
        int other = 0;
        if (found == index.end())
        {
          other = static_cast<int>(result.size());
          index.emplace(mirrored, other);
          result.push_back({ pa[0], pb[0] });
        }
        else
        {
          other = found->second;
        }
        const int minusEdge = pa[2] > 0 ? static_cast<int>(e) : other;
        const int plusEdge = pa[2] > 0 ? other : static_cast<int>(e);
        partnerEdges.push_back({ minusEdge, plusEdge, pa[1] });
      }
    }
  }
  std::sort(partnerEdges.begin(), partnerEdges.end());
  partnerEdges.erase(std::unique(partnerEdges.begin(), partnerEdges.end()), partnerEdges.end());
  return result;
}

void SortCopiesAlike(std::vector<std::array<int, 2>>& edges,
  std::vector<std::array<int, 3>>& partnerEdges,
  const std::vector<int>& identity)
{
  std::vector<std::array<int, 3>> keys(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
  {
    const int a = identity[static_cast<size_t>(edges[e][0])];
    const int b = identity[static_cast<size_t>(edges[e][1])];
    keys[e] = { std::min(a, b), std::max(a, b), static_cast<int>(e) };
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::array<int, 2>> sorted(edges.size());
  std::vector<int> position(edges.size());
  for (size_t i = 0; i < keys.size(); ++i)
  {
    const int e = keys[i][2];
    sorted[i] = edges[static_cast<size_t>(e)];
    position[static_cast<size_t>(e)] = static_cast<int>(i);
  }
  edges = sorted;
  for (auto& pair : partnerEdges)
  {
    pair[0] = position[static_cast<size_t>(pair[0])];
    pair[1] = position[static_cast<size_t>(pair[1])];
  }
}

void AddMidpointCopies(const std::vector<std::array<int, 2>>& edges,
  const std::vector<std::array<int, 3>>& partnerEdges,
  const std::vector<std::array<int, 2>>& midpointParents,
  int firstNew,
  std::vector<CopyRelation>& copies,
  std::vector<int>& identity)
{
  // The midpoint of each split edge, found by its parents (SplitTetEdges skips missing edges).
  std::map<std::array<int, 2>, int> midpoint;
  for (size_t i = 0; i < midpointParents.size(); ++i)
  {
    const auto& p = midpointParents[i];
    midpoint[{ std::min(p[0], p[1]), std::max(p[0], p[1]) }] = firstNew + static_cast<int>(i);
  }
  const int oldSize = static_cast<int>(identity.size());
  identity.resize(static_cast<size_t>(firstNew + static_cast<int>(midpointParents.size())));
  for (int v = oldSize; v < static_cast<int>(identity.size()); ++v)
  {
    identity[static_cast<size_t>(v)] = v;
  }
  auto find = [&](int e)
  {
    const auto& edge = edges[static_cast<size_t>(e)];
    const auto it = midpoint.find({ std::min(edge[0], edge[1]), std::max(edge[0], edge[1]) });
    return it == midpoint.end() ? -1 : it->second;
  };
  // Identities: all midpoints mirrored into each other share the smallest identity (passes
  // until stable: a chain of cuts links more than two).
  for (bool changed = true; changed;)
  {
    changed = false;
    for (const auto& pair : partnerEdges)
    {
      const int a = find(pair[0]);
      const int b = find(pair[1]);
      if (a < 0 || b < 0)
      {
        continue;
      }
      const int id = std::min(identity[static_cast<size_t>(a)], identity[static_cast<size_t>(b)]);
      if (identity[static_cast<size_t>(a)] != id || identity[static_cast<size_t>(b)] != id)
      {
        identity[static_cast<size_t>(a)] = identity[static_cast<size_t>(b)] = id;
        changed = true;
      }
    }
  }
  for (const auto& pair : partnerEdges)
  {
    const int a = find(pair[0]);
    const int b = find(pair[1]);
    if (a >= 0 && b >= 0)
    {
      copies.push_back({ a, b, pair[2] });
    }
  }
}

void KeepInputBoundary(TetTopology& topology, const std::vector<int>& identity)
{
  const Triangles glued = IdentityFaces(topology.BoundaryFaces, identity);
  std::map<std::array<int, 3>, int> count;
  std::vector<std::array<int, 3>> keys(static_cast<size_t>(glued.rows()));
  for (Eigen::Index f = 0; f < glued.rows(); ++f)
  {
    std::array<int, 3> key = { glued(f, 0), glued(f, 1), glued(f, 2) };
    std::sort(key.begin(), key.end());
    keys[static_cast<size_t>(f)] = key;
    ++count[key];
  }
  Triangles faces(glued.rows(), 3);
  std::vector<int> faceTet;
  std::vector<int> faceLocal;
  topology.TetFaceToBoundaryFace.setConstant(-1);
  std::fill(topology.IsBoundaryVertex.begin(), topology.IsBoundaryVertex.end(), false);
  int kept = 0;
  for (Eigen::Index f = 0; f < glued.rows(); ++f)
  {
    if (count[keys[static_cast<size_t>(f)]] > 1)
    {
      continue;
    }
    faces.row(kept) = topology.BoundaryFaces.row(f);
    faceTet.push_back(topology.BoundaryFaceTet[static_cast<size_t>(f)]);
    faceLocal.push_back(topology.BoundaryFaceLocal[static_cast<size_t>(f)]);
    topology.TetFaceToBoundaryFace(faceTet.back(), faceLocal.back()) = kept;
    for (int c = 0; c < 3; ++c)
    {
      topology.IsBoundaryVertex[static_cast<size_t>(faces(kept, c))] = true;
    }
    ++kept;
  }
  faces.conservativeResize(kept, 3);
  topology.BoundaryFaces = faces;
  topology.BoundaryFaceTet = faceTet;
  topology.BoundaryFaceLocal = faceLocal;
}

Triangles IdentityFaces(const Triangles& faces, const std::vector<int>& identity)
{
  Triangles glued(faces.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    for (int c = 0; c < 3; ++c)
    {
      glued(f, c) = identity[static_cast<size_t>(faces(f, c))];
    }
  }
  return glued;
}

int TransformLabel(const Eigen::Matrix3i& pi, int label)
{
  const int axis = label / 2;
  const int sign = label % 2 == 0 ? 1 : -1;
  for (int r = 0; r < 3; ++r)
  {
    if (pi(r, axis) != 0)
    {
      return 2 * r + (sign * pi(r, axis) < 0 ? 1 : 0);
    }
  }
  return label;
}

std::vector<std::array<int, 3>> FacesAcrossCuts(const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<CopyRelation>& copies)
{
  std::map<std::array<int, 2>, int> cutOf; // (minus copy, plus copy) -> cut
  for (const CopyRelation& r : copies)
  {
    cutOf[{ r.Minus, r.Plus }] = r.Cut;
  }
  std::vector<std::array<int, 3>> across;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    for (int e = 0; e < 3; ++e)
    {
      const Eigen::Index g = adjacency(f, e);
      if (g < 0)
      {
        continue;
      }
      // The shared edge as seen from g: the corner of g that is a copy of f's corner e.
      const int a = faces(f, e);
      for (int k = 0; k < 3; ++k)
      {
        const int b = faces(g, k);
        if (b == a)
        {
          break; // the same vertex: not across a cut
        }
        const auto it = cutOf.find({ a, b });
        if (it != cutOf.end())
        {
          across.push_back({ static_cast<int>(f), static_cast<int>(g), it->second });
          break;
        }
      }
    }
  }
  std::sort(across.begin(), across.end());
  across.erase(std::unique(across.begin(), across.end()), across.end());
  return across;
}

int MatchLabelsAcrossCuts(const std::vector<std::array<int, 3>>& across,
  const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<Eigen::Matrix3i>& transitions,
  std::vector<int>& labels)
{
  // Which side gives way: first the face whose normal still points along its new label (no
  // face folds over), then the one whose other neighbours already carry the new label (no
  // one-face tooth is left behind). A face may give way only if it keeps a neighbour of the new
  // label on its side or its normal is within 60 degrees of the label; -1 otherwise.
  auto score = [&](int face, int label, int other)
  {
    const Eigen::Vector3d p0 = x.row(faces(face, 0)).transpose();
    const Eigen::Vector3d normal = (x.row(faces(face, 1)).transpose() - p0)
                                     .cross(x.row(faces(face, 2)).transpose() - p0);
    const double length = normal.norm();
    const double along =
      length > 0.0 ? (label % 2 == 0 ? 1.0 : -1.0) * normal(label / 2) / length : 0.0;
    int count = 0;
    for (int e = 0; e < 3; ++e)
    {
      const int n = adjacency(face, e);
      count += n >= 0 && n != other && labels[static_cast<size_t>(n)] == label ? 1 : 0;
    }
    if (count == 0 && !(along > 0.5))
    {
      return -1;
    }
    return (along > 0.0 ? 10 : 0) + count;
  };
  int changed = 0;
  for (const auto& pair : across)
  {
    const Eigen::Matrix3i& pi = transitions[static_cast<size_t>(pair[2])];
    const int minus = pair[0];
    const int plus = pair[1];
    const int plusLabel = TransformLabel(pi, labels[static_cast<size_t>(minus)]);
    if (labels[static_cast<size_t>(plus)] == plusLabel)
    {
      continue;
    }
    const int minusLabel = TransformLabel(pi.transpose(), labels[static_cast<size_t>(plus)]);
    const int plusScore = score(plus, plusLabel, minus);
    const int minusScore = score(minus, minusLabel, plus);
    if (plusScore < 0 && minusScore < 0)
    {
      continue; // a crease along the loop
    }
    if (plusScore >= minusScore)
    {
      labels[static_cast<size_t>(plus)] = plusLabel;
    }
    else
    {
      labels[static_cast<size_t>(minus)] = minusLabel;
    }
    ++changed;
  }
  return changed;
}

int CleanUpCutMeshLabels(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<CopyRelation>& copies,
  const std::vector<Eigen::Matrix3i>& transitions,
  const PolycubeChartCleanup& settings,
  std::vector<int>& labels)
{
  if (copies.empty())
  {
    return CleanUpPolycubeCharts(x, faces, adjacency, settings, labels);
  }
  const std::vector<std::array<int, 3>> across = FacesAcrossCuts(faces, adjacency, copies);
  // The clean-up compares labels as they are, so it sees across a cut's loop only where the
  // transition is the identity. Across a twisted cut, +Y beside +Y is a mismatch (Pi turns one
  // of them) that it would take for one chart: after a collapse relabelling on fertility's
  // 90-degree cut it turned such a chart into the -Y beside it and folded 373 faces.
  Triangles untwisted = adjacency;
  for (const auto& pair : across)
  {
    if (transitions[static_cast<size_t>(pair[2])] == Eigen::Matrix3i::Identity())
    {
      continue;
    }
    for (int e = 0; e < 3; ++e)
    {
      if (untwisted(pair[0], e) == pair[1])
      {
        untwisted(pair[0], e) = -1;
      }
      if (untwisted(pair[1], e) == pair[0])
      {
        untwisted(pair[1], e) = -1;
      }
    }
  }
  int changed = CleanUpPolycubeCharts(x, faces, untwisted, settings, labels);
  // No second clean-up: it compares labels across a cut without the transition, and would undo
  // matches across a twisted cut. The matching itself leaves no face across its normal.
  changed += MatchLabelsAcrossCuts(across, x, faces, adjacency, transitions, labels);
  return changed;
}

std::vector<int> ChartsAcrossCuts(const std::vector<std::array<int, 3>>& across,
  const std::vector<Eigen::Matrix3i>& transitions,
  const std::vector<int>& labels,
  const std::vector<int>& faceChart,
  int chartCount)
{
  std::vector<int> parent(static_cast<size_t>(chartCount));
  for (int c = 0; c < chartCount; ++c)
  {
    parent[static_cast<size_t>(c)] = c;
  }
  auto root = [&parent](int c)
  {
    while (parent[static_cast<size_t>(c)] != c)
    {
      c = parent[static_cast<size_t>(c)] = parent[static_cast<size_t>(parent[static_cast<size_t>(c)])];
    }
    return c;
  };
  for (const auto& pair : across)
  {
    if (TransformLabel(transitions[static_cast<size_t>(pair[2])],
          labels[static_cast<size_t>(pair[0])]) == labels[static_cast<size_t>(pair[1])])
    {
      const int a = root(faceChart[static_cast<size_t>(pair[0])]);
      const int b = root(faceChart[static_cast<size_t>(pair[1])]);
      parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
    }
  }
  std::vector<int> linked(faceChart.size());
  for (size_t f = 0; f < faceChart.size(); ++f)
  {
    linked[f] = root(faceChart[f]);
  }
  return linked;
}

void AddCopyRelations(const std::vector<CopyRelation>& copies,
  const std::vector<Eigen::Matrix3i>& transitions,
  CoordinateRelations& relations)
{
  for (const CopyRelation& r : copies)
  {
    const Eigen::Matrix3i& pi = transitions[static_cast<size_t>(r.Cut)];
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        if (pi(a, b) != 0)
        {
          relations.Relate(3 * r.Plus + a, 3 * r.Minus + b, pi(a, b), { { 3 * r.Cut + a, 1.0 } });
        }
      }
    }
  }
}

} // namespace polycubehex
