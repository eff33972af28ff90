// SPDX-License-Identifier: BSD-3-Clause
#include "HexLatticeExtraction.h"

#include "DisjointSets.h"
#include "PolycubeCutMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace polycubehex
{
namespace
{
constexpr int FaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };
/// The local vertex opposite local face k, and the local face opposite local vertex i.
constexpr int OppositeVertex[4] = { 2, 0, 1, 3 };
constexpr int OppositeFace[4] = { 1, 2, 0, 3 };

/// VTK hexahedron corners as offsets from the cube's minimum corner.
constexpr int CubeCorners[8][3] = { { 0, 0, 0 },
  { 1, 0, 0 },
  { 1, 1, 0 },
  { 0, 1, 0 },
  { 0, 0, 1 },
  { 1, 0, 1 },
  { 1, 1, 1 },
  { 0, 1, 1 } };

/// Lattice coordinates packed into one integer; each must lie in (-KeyLimit, KeyLimit).
using Key = std::int64_t;
constexpr std::int64_t KeyLimit = std::int64_t(1) << 20;

Key Pack(std::int64_t x, std::int64_t y, std::int64_t z)
{
  return ((x + KeyLimit) << 42) | ((y + KeyLimit) << 21) | (z + KeyLimit);
}

struct Hit
{
  int Tet;
  std::array<double, 4> Lambda;
};

/// One point of the input: a lattice coordinate and the connected tets that contain it.
struct PointGroup
{
  Key Coordinate;
  std::array<std::int64_t, 3> Cell; ///< the integer part (the cube's minimum corner for centres)
  std::vector<int> Tets;
  int Tet = -1;                      ///< the tet that contains it most deeply
  std::array<double, 4> Lambda = {}; ///< its barycentric coordinates there
  std::vector<int> Charts;
};

/// Barycentric coordinates of q in the tet u, each the signed volume of q and the opposite face
/// over the sum: on a chart plane the face's three corners and q share one coordinate exactly,
/// so the face's normal has one non-zero component and the coordinate is exactly 0.
bool Barycentric(const std::array<Eigen::Vector3d, 4>& u,
  const Eigen::Vector3d& q,
  double tolerance,
  std::array<double, 4>& lambda)
{
  double sum = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    const int* face = FaceTable[OppositeFace[i]];
    const Eigen::Vector3d normal = (u[face[1]] - u[face[0]]).cross(u[face[2]] - u[face[0]]);
    lambda[i] = -(q - u[face[0]]).dot(normal);
    sum += lambda[i];
  }
  if (!(sum > 0.0))
  {
    return false;
  }
  bool inside = true;
  for (int i = 0; i < 4; ++i)
  {
    lambda[i] /= sum;
    inside = inside && lambda[i] >= -tolerance;
  }
  return inside;
}

bool ShareVertex(const Tets& cells, int a, int b)
{
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      if (cells(a, i) == cells(b, j))
      {
        return true;
      }
    }
  }
  return false;
}

/// Splits the hits of each coordinate into groups of tets connected through shared vertices.
void GroupHits(const std::unordered_map<Key, std::vector<Hit>>& hits,
  const Tets& cells,
  const ChartPlanes& charts,
  double tolerance,
  std::vector<PointGroup>& groups,
  std::unordered_map<Key, std::vector<int>>& groupsAt)
{
  std::vector<Key> keys;
  keys.reserve(hits.size());
  for (const auto& entry : hits)
  {
    keys.push_back(entry.first);
  }
  std::sort(keys.begin(), keys.end()); // deterministic numbering
  for (Key key : keys)
  {
    const std::vector<Hit>& list = hits.at(key);
    const int n = static_cast<int>(list.size());
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    for (int i = 0; i < n; ++i)
    {
      for (int j = i + 1; j < n; ++j)
      {
        if (ShareVertex(cells, list[i].Tet, list[j].Tet))
        {
          const int a = FindRoot(parent, i);
          const int b = FindRoot(parent, j);
          parent[std::max(a, b)] = std::min(a, b);
        }
      }
    }
    std::vector<int> groupOfRoot(n, -1);
    for (int i = 0; i < n; ++i)
    {
      const int root = FindRoot(parent, i);
      if (groupOfRoot[root] < 0)
      {
        groupOfRoot[root] = static_cast<int>(groups.size());
        PointGroup group;
        group.Coordinate = key;
        group.Cell = { (key >> 42) - KeyLimit,
          ((key >> 21) & ((std::int64_t(1) << 21) - 1)) - KeyLimit,
          (key & ((std::int64_t(1) << 21) - 1)) - KeyLimit };
        group.Tet = -1;
        groupsAt[key].push_back(groupOfRoot[root]);
        groups.push_back(group);
      }
      PointGroup& group = groups[groupOfRoot[root]];
      const Hit& hit = list[i];
      group.Tets.push_back(hit.Tet);
      const double depth = *std::min_element(hit.Lambda.begin(), hit.Lambda.end());
      if (group.Tet < 0 || depth > *std::min_element(group.Lambda.begin(), group.Lambda.end()))
      {
        group.Tet = hit.Tet;
        group.Lambda = hit.Lambda;
      }
      for (int k = 0; k < 4; ++k)
      {
        const int chart = charts.FaceChart(hit.Tet, k);
        if (chart >= 0 && hit.Lambda[OppositeVertex[k]] <= tolerance)
        {
          group.Charts.push_back(chart);
        }
      }
    }
  }
  for (PointGroup& group : groups)
  {
    std::sort(group.Charts.begin(), group.Charts.end());
    group.Charts.erase(std::unique(group.Charts.begin(), group.Charts.end()), group.Charts.end());
  }
}

/// The image of a point in the original space: its barycentric coordinates, with the ones
/// within the tolerance of 0 snapped to 0 so that a point on a boundary face lands on it.
Eigen::RowVector3d MapToOriginal(const Points& original,
  const Tets& cells,
  int tet,
  std::array<double, 4> lambda,
  double tol)
{
  double sum = 0.0;
  for (double& l : lambda)
  {
    l = l <= tol ? 0.0 : l;
    sum += l;
  }
  Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
  for (int i = 0; i < 4; ++i)
  {
    x += (lambda[i] / sum) * original.row(cells(tet, i));
  }
  return x;
}

bool SameTransform(const LatticeTransform& a, const LatticeTransform& b)
{
  return a.Rotation == b.Rotation && (a.Translation - b.Translation).cwiseAbs().maxCoeff() < 1e-6;
}

/// Union-find over point groups that also carries, per group, the map from its frame to its
/// parent's (the root's after Find): groups united across a seam stand for one point of M seen
/// from two frames. The root of a set is its smallest group, as in FindRoot.
class FrameUnion
{
public:
  explicit FrameUnion(int count)
    : Parent(static_cast<size_t>(count))
    , ToParent(static_cast<size_t>(count))
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }

  /// The root of g; afterwards ToRoot(g) is the map from g's frame to the root's.
  int Find(int g)
  {
    this->Path.clear();
    while (this->Parent[g] != g)
    {
      this->Path.push_back(g);
      g = this->Parent[g];
    }
    const int root = g;
    // Nearest the root first, so that each parent already maps to the root.
    for (auto it = this->Path.rbegin(); it != this->Path.rend(); ++it)
    {
      const int x = *it;
      const int p = this->Parent[x];
      if (p != root)
      {
        this->ToParent[x] = this->ToParent[p].After(this->ToParent[x]);
        this->Parent[x] = root;
      }
    }
    return root;
  }

  const LatticeTransform& ToRoot(int g) const { return this->ToParent[g]; }

  /// Unites a and b, where `aToB` maps a's frame to b's; counts a contradiction with an earlier
  /// union (a cycle of seams whose transitions do not compose to the identity).
  void Unite(int a, int b, const LatticeTransform& aToB)
  {
    const int ra = this->Find(a);
    const int rb = this->Find(b);
    const LatticeTransform ta = this->ToParent[a]; // identity at a root
    const LatticeTransform tb = this->ToParent[b];
    if (ra == rb)
    {
      if (!SameTransform(tb.After(aToB), ta))
      {
        ++this->Inconsistent;
      }
      return;
    }
    if (rb < ra)
    {
      this->Parent[ra] = rb;
      this->ToParent[ra] = tb.After(aToB.After(ta.Inverse()));
    }
    else
    {
      this->Parent[rb] = ra;
      this->ToParent[rb] = ta.After(aToB.Inverse().After(tb.Inverse()));
    }
  }

  int Inconsistent = 0;

private:
  std::vector<int> Parent;
  std::vector<LatticeTransform> ToParent;
  std::vector<int> Path;
};

std::array<Eigen::Vector3d, 4> TetLattice(const Points& lattice, const Tets& cells, int t)
{
  std::array<Eigen::Vector3d, 4> u;
  for (int i = 0; i < 4; ++i)
  {
    u[i] = lattice.row(cells(t, i)).transpose();
  }
  return u;
}

bool OverlapsBox(const Points& lattice,
  const Tets& cells,
  int t,
  const Eigen::Vector3d& low,
  const Eigen::Vector3d& high)
{
  for (int a = 0; a < 3; ++a)
  {
    double lo = lattice(cells(t, 0), a);
    double hi = lo;
    for (int i = 1; i < 4; ++i)
    {
      lo = std::min(lo, lattice(cells(t, i), a));
      hi = std::max(hi, lattice(cells(t, i), a));
    }
    if (hi < low[a] || lo > high[a])
    {
      return false;
    }
  }
  return true;
}

/// The key of a lattice point (offset 0) or cube centre (offset 1/2) given by its position;
/// false when it is out of range.
bool KeyOf(const Eigen::Vector3d& position,
  double offset,
  Key& key,
  std::array<std::int64_t, 3>& cell)
{
  for (int a = 0; a < 3; ++a)
  {
    const double c = std::round(position[a] - offset);
    if (!(std::abs(c) < static_cast<double>(KeyLimit) - 2.0))
    {
      return false;
    }
    cell[a] = static_cast<std::int64_t>(c);
  }
  key = Pack(cell[0], cell[1], cell[2]);
  return true;
}

/// Unites each group with a point on a cut face with the group of the tet across at the
/// transformed coordinate (the same point of M seen from the other side).
void UniteAcrossSeams(const std::vector<PointGroup>& groups,
  const std::unordered_map<Key, std::vector<int>>& groupsAt,
  double offset,
  const Points& lattice,
  const Tets& cells,
  const PolycubeSeams& seams,
  double tolerance,
  FrameUnion& unions,
  int& unmatched)
{
  for (int g = 0; g < static_cast<int>(groups.size()); ++g)
  {
    const PointGroup& group = groups[g];
    const Eigen::Vector3d q(group.Cell[0] + offset, group.Cell[1] + offset, group.Cell[2] + offset);
    for (int t : group.Tets)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int n = seams.Neighbor(t, k);
        if (n < 0)
        {
          continue;
        }
        std::array<double, 4> lambda;
        if (!Barycentric(TetLattice(lattice, cells, t), q, tolerance, lambda) ||
          lambda[OppositeVertex[k]] > tolerance)
        {
          continue;
        }
        const LatticeTransform across = seams.Across(t, k);
        Key key;
        std::array<std::int64_t, 3> cell;
        int partner = -1;
        const auto found =
          KeyOf(across.Apply(q), offset, key, cell) ? groupsAt.find(key) : groupsAt.end();
        if (found != groupsAt.end())
        {
          // The group of the tet across, else one of a tet touching it (the tet across missed
          // the point by a rounding error).
          for (int pass = 0; pass < 2 && partner < 0; ++pass)
          {
            for (int h : found->second)
            {
              for (int s : groups[h].Tets)
              {
                if (partner < 0 && (pass == 0 ? s == n : ShareVertex(cells, s, n)))
                {
                  partner = h;
                }
              }
            }
          }
        }
        if (partner < 0)
        {
          ++unmatched;
          continue;
        }
        unions.Unite(g, partner, across);
      }
    }
  }
}
} // namespace

Status extractLatticeHexes(const Points& original,
  const Points& lattice,
  const Tets& cells,
  const ChartPlanes& charts,
  const LatticeExtractionParameters& params,
  LatticeHexMesh& out,
  const Progress& progress,
  const PolycubeSeams* seams)
{
  const int tetCount = static_cast<int>(cells.rows());
  const double tol = params.BarycentricTolerance;
  out = LatticeHexMesh();
  if (lattice.rows() > 0 && lattice.cwiseAbs().maxCoeff() >= static_cast<double>(KeyLimit) - 2.0)
  {
    return Status::Failure("the lattice is too large (coordinates beyond 2^20); lower the "
                           "resolution");
  }

  // 1. Integer points (offset 0) and cube centres (offset 1/2) of every tet.
  std::unordered_map<Key, std::vector<Hit>> vertexHits;
  std::unordered_map<Key, std::vector<Hit>> centreHits;
  for (int t = 0; t < tetCount; ++t)
  {
    if (t % 4096 == 0 && !ReportProgress(progress, 0.6 * t / std::max(1, tetCount)))
    {
      return Status::Failure("hex extraction aborted");
    }
    std::array<Eigen::Vector3d, 4> u;
    for (int i = 0; i < 4; ++i)
    {
      u[i] = lattice.row(cells(t, i)).transpose();
    }
    const Eigen::Vector3d low = u[0].cwiseMin(u[1]).cwiseMin(u[2]).cwiseMin(u[3]);
    const Eigen::Vector3d high = u[0].cwiseMax(u[1]).cwiseMax(u[2]).cwiseMax(u[3]);
    const double pad = 1e-6;
    for (int pass = 0; pass < 2; ++pass)
    {
      const double offset = pass == 0 ? 0.0 : 0.5;
      std::array<std::int64_t, 3> from;
      std::array<std::int64_t, 3> to;
      for (int a = 0; a < 3; ++a)
      {
        from[a] = static_cast<std::int64_t>(std::ceil(low[a] - offset - pad));
        to[a] = static_cast<std::int64_t>(std::floor(high[a] - offset + pad));
      }
      for (std::int64_t i = from[0]; i <= to[0]; ++i)
      {
        for (std::int64_t j = from[1]; j <= to[1]; ++j)
        {
          for (std::int64_t k = from[2]; k <= to[2]; ++k)
          {
            const Eigen::Vector3d q(i + offset, j + offset, k + offset);
            Hit hit;
            hit.Tet = t;
            if (Barycentric(u, q, tol, hit.Lambda))
            {
              (pass == 0 ? vertexHits : centreHits)[Pack(i, j, k)].push_back(hit);
            }
          }
        }
      }
    }
  }

  // 2. One vertex (one cube) per coordinate and connected group of tets; across a seam, the
  //    groups of one point of M seen from both sides are one vertex (one cube).
  std::vector<PointGroup> vertices;
  std::unordered_map<Key, std::vector<int>> verticesAt;
  GroupHits(vertexHits, cells, charts, tol, vertices, verticesAt);
  std::vector<PointGroup> centres;
  std::unordered_map<Key, std::vector<int>> centresAt;
  GroupHits(centreHits, cells, charts, tol, centres, centresAt);
  const bool cut = seams && !seams->Empty();
  FrameUnion vertexUnion(cut ? static_cast<int>(vertices.size()) : 0);
  FrameUnion centreUnion(cut ? static_cast<int>(centres.size()) : 0);
  if (cut)
  {
    int unmatched = 0;
    UniteAcrossSeams(
      vertices, verticesAt, 0.0, lattice, cells, *seams, tol, vertexUnion, unmatched);
    UniteAcrossSeams(centres, centresAt, 0.5, lattice, cells, *seams, tol, centreUnion, unmatched);
    out.InconsistentSeamCount = vertexUnion.Inconsistent + centreUnion.Inconsistent + unmatched;
  }
  if (!ReportProgress(progress, 0.7))
  {
    return Status::Failure("hex extraction aborted");
  }

  // 3. Hexes: the 8 corners of each cube whose centre is inside. The walk from the centre's tets
  //    through tets overlapping the cube tells which of several groups at a corner's coordinate
  //    is meant; across a seam it carries the map from the centre's frame to the tet's, and the
  //    cube is looked for at its image (frames[visitFrame[t]] for each visited tet t).
  std::vector<int> vertexIndex(vertices.size(), -1);
  std::vector<int> usedVertices; // the root group of each output vertex
  std::vector<std::array<int, 8>> hexes;
  std::vector<std::array<std::int64_t, 3>> hexOrigins;
  std::vector<Eigen::Matrix3i> cornerRotations;
  std::vector<Eigen::RowVector3d> hexCentres;
  std::vector<int> visitStamp(tetCount, -1);
  std::vector<int> visitFrame(cut ? tetCount : 0, 0);
  std::vector<LatticeTransform> frames;
  for (int c = 0; c < static_cast<int>(centres.size()); ++c)
  {
    if (cut && centreUnion.Find(c) != c)
    {
      continue; // the same cube as its root, found from the other side of a seam
    }
    const PointGroup& centre = centres[c];
    std::array<int, 8> corners;
    std::array<Eigen::Matrix3i, 8> rotations;
    bool complete = true;
    bool walked = false;
    auto walk = [&]()
    {
      walked = true;
      frames.assign(1, LatticeTransform());
      std::vector<int> stack(centre.Tets.begin(), centre.Tets.end());
      for (int t : stack)
      {
        visitStamp[t] = c;
        if (cut)
        {
          visitFrame[t] = 0;
        }
      }
      const Eigen::Vector3d cubeLow(static_cast<double>(centre.Cell[0]),
        static_cast<double>(centre.Cell[1]),
        static_cast<double>(centre.Cell[2]));
      const Eigen::Vector3d cubeHigh = cubeLow.array() + 1.0;
      while (!stack.empty())
      {
        const int t = stack.back();
        stack.pop_back();
        const int frame = cut ? visitFrame[t] : 0;
        for (int f = 0; f < 4; ++f)
        {
          int n = charts.Neighbors(t, f);
          int nextFrame = frame;
          if (n < 0 && cut && seams->Neighbor(t, f) >= 0)
          {
            n = seams->Neighbor(t, f);
            const LatticeTransform next = seams->Across(t, f).After(frames[frame]);
            nextFrame = -1;
            for (int i = 0; i < static_cast<int>(frames.size()) && nextFrame < 0; ++i)
            {
              nextFrame = SameTransform(frames[i], next) ? i : -1;
            }
            if (nextFrame < 0)
            {
              nextFrame = static_cast<int>(frames.size());
              frames.push_back(next);
            }
          }
          if (n < 0 || visitStamp[n] == c)
          {
            continue;
          }
          const Eigen::Vector3d a = frames[nextFrame].Apply(cubeLow);
          const Eigen::Vector3d b = frames[nextFrame].Apply(cubeHigh);
          if (OverlapsBox(
                lattice, cells, n, a.cwiseMin(b).array() - 1e-6, a.cwiseMax(b).array() + 1e-6))
          {
            visitStamp[n] = c;
            if (cut)
            {
              visitFrame[n] = nextFrame;
            }
            stack.push_back(n);
          }
        }
      }
    };
    for (int k = 0; k < 8 && complete; ++k)
    {
      const Eigen::Vector3d corner(static_cast<double>(centre.Cell[0] + CubeCorners[k][0]),
        static_cast<double>(centre.Cell[1] + CubeCorners[k][1]),
        static_cast<double>(centre.Cell[2] + CubeCorners[k][2]));
      if (!cut)
      {
        const auto found = verticesAt.find(Pack(centre.Cell[0] + CubeCorners[k][0],
          centre.Cell[1] + CubeCorners[k][1],
          centre.Cell[2] + CubeCorners[k][2]));
        if (found == verticesAt.end())
        {
          complete = false;
          break;
        }
        if (found->second.size() == 1)
        {
          corners[k] = found->second[0];
          continue;
        }
        // Several points of the input share this coordinate: take the one reached from the
        // centre through tets that overlap the cube.
        if (!walked)
        {
          walk();
        }
        int chosen = -1;
        for (int g : found->second)
        {
          for (int t : vertices[g].Tets)
          {
            if (chosen < 0 && visitStamp[t] == c)
            {
              chosen = g;
            }
          }
        }
        ++out.AmbiguousCornerCount;
        if (chosen < 0)
        {
          complete = false;
        }
        corners[k] = chosen;
        continue;
      }
      // With seams every corner is looked up through the walk, in each frame it reached.
      if (!walked)
      {
        walk();
      }
      int chosen = -1;
      int chosenFrame = -1;
      int firstRoot = -1;
      bool ambiguous = false;
      for (int i = 0; i < static_cast<int>(frames.size()); ++i)
      {
        Key key;
        std::array<std::int64_t, 3> cell;
        if (!KeyOf(frames[i].Apply(corner), 0.0, key, cell))
        {
          continue;
        }
        const auto found = verticesAt.find(key);
        if (found == verticesAt.end())
        {
          continue;
        }
        for (int g : found->second)
        {
          const int root = vertexUnion.Find(g);
          firstRoot = firstRoot < 0 ? root : firstRoot;
          ambiguous = ambiguous || root != firstRoot;
          for (int t : vertices[g].Tets)
          {
            if (chosen < 0 && visitStamp[t] == c && visitFrame[t] == i)
            {
              chosen = g;
              chosenFrame = i;
            }
          }
        }
      }
      if (ambiguous)
      {
        ++out.AmbiguousCornerCount;
      }
      if (chosen < 0)
      {
        complete = false;
        break;
      }
      // The vertex is its root group; root frame -> chosen group's frame -> centre's frame.
      const int root = vertexUnion.Find(chosen);
      corners[k] = root;
      rotations[k] =
        frames[chosenFrame].Rotation.transpose() * vertexUnion.ToRoot(chosen).Rotation.transpose();
    }
    if (!complete)
    {
      ++out.IncompleteCubeCount;
      continue;
    }
    std::array<int, 8> hex;
    for (int k = 0; k < 8; ++k)
    {
      int& index = vertexIndex[corners[k]];
      if (index < 0)
      {
        index = static_cast<int>(usedVertices.size());
        usedVertices.push_back(corners[k]);
      }
      hex[k] = index;
      if (cut)
      {
        cornerRotations.push_back(rotations[k]);
      }
    }
    hexes.push_back(hex);
    hexOrigins.push_back(centre.Cell);
    hexCentres.push_back(MapToOriginal(original, cells, centre.Tet, centre.Lambda, tol));
  }

  // 4. Output arrays. A vertex's charts are those of all its groups, their labels seen from its
  //    root group's frame.
  const int vertexCount = static_cast<int>(usedVertices.size());
  std::vector<std::vector<int>> members(static_cast<size_t>(vertexCount));
  for (int g = 0; g < static_cast<int>(vertices.size()); ++g)
  {
    const int root = cut ? vertexUnion.Find(g) : g;
    if (vertexIndex[root] >= 0)
    {
      members[static_cast<size_t>(vertexIndex[root])].push_back(g);
    }
  }
  out.Mesh.Vertices.resize(vertexCount, 3);
  out.LatticeVertices.resize(vertexCount, 3);
  out.VertexCharts.resize(vertexCount);
  out.VertexChartLabels.resize(vertexCount);
  out.VertexTets.resize(vertexCount);
  for (int v = 0; v < vertexCount; ++v)
  {
    const PointGroup& group = vertices[usedVertices[v]];
    out.Mesh.Vertices.row(v) = MapToOriginal(original, cells, group.Tet, group.Lambda, tol);
    for (int a = 0; a < 3; ++a)
    {
      out.LatticeVertices(v, a) = static_cast<double>(group.Cell[a]);
    }
    // (chart, label in the root's frame), sorted by chart; a chart seen from two groups once.
    std::vector<std::pair<int, int>> seen;
    for (int g : members[static_cast<size_t>(v)])
    {
      for (int chart : vertices[g].Charts)
      {
        const int label = charts.ChartLabel[chart];
        seen.emplace_back(
          chart, cut ? TransformLabel(vertexUnion.ToRoot(g).Rotation, label) : label);
      }
    }
    std::sort(seen.begin(), seen.end());
    for (size_t i = 0; i < seen.size(); ++i)
    {
      if (i == 0 || seen[i].first != seen[i - 1].first)
      {
        out.VertexCharts[v].push_back(seen[i].first);
        out.VertexChartLabels[v].push_back(seen[i].second);
      }
    }
    out.VertexTets[v] = group.Tet;
  }
  const int hexCount = static_cast<int>(hexes.size());
  out.Mesh.Cells.resize(hexCount, 8);
  out.HexCenters.resize(hexCount, 3);
  out.HexOrigins.resize(hexCount, 3);
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      out.Mesh.Cells(h, k) = hexes[h][k];
    }
    out.HexCenters.row(h) = hexCentres[h];
    for (int a = 0; a < 3; ++a)
    {
      out.HexOrigins(h, a) = static_cast<double>(hexOrigins[h][a]);
    }
  }
  out.HexCornerRotations = std::move(cornerRotations);
  ReportProgress(progress, 1.0);
  return Status::Success();
}

bool MapLatticePoint(const Points& original,
  const Points& lattice,
  const Tets& cells,
  const ChartPlanes& charts,
  int start,
  const Eigen::Vector3d& from,
  const Eigen::Vector3d& point,
  double tolerance,
  Eigen::RowVector3d& image,
  const PolycubeSeams* seams)
{
  const bool cut = seams && !seams->Empty();
  // Each visited tet with the map from the frame of `start` to its own.
  std::vector<std::pair<int, LatticeTransform>> stack = { { start, LatticeTransform() } };
  std::unordered_set<int> seen = { start };
  int best = -1;
  std::array<double, 4> bestLambda = {};
  double bestDepth = -std::numeric_limits<double>::max();
  while (!stack.empty())
  {
    const int t = stack.back().first;
    const LatticeTransform frame = stack.back().second;
    stack.pop_back();
    std::array<double, 4> lambda;
    if (Barycentric(TetLattice(lattice, cells, t), frame.Apply(point), tolerance, lambda))
    {
      const double depth = *std::min_element(lambda.begin(), lambda.end());
      if (depth > bestDepth)
      {
        bestDepth = depth;
        best = t;
        bestLambda = lambda;
      }
    }
    for (int f = 0; f < 4; ++f)
    {
      int n = charts.Neighbors(t, f);
      LatticeTransform next = frame;
      if (n < 0 && cut && seams->Neighbor(t, f) >= 0)
      {
        n = seams->Neighbor(t, f);
        next = seams->Across(t, f).After(frame);
      }
      if (n < 0 || seen.count(n))
      {
        continue;
      }
      const Eigen::Vector3d a = next.Apply(from);
      const Eigen::Vector3d b = next.Apply(point);
      if (OverlapsBox(
            lattice, cells, n, a.cwiseMin(b).array() - 1e-6, a.cwiseMax(b).array() + 1e-6))
      {
        seen.insert(n);
        stack.emplace_back(n, next);
      }
    }
  }
  if (best < 0)
  {
    return false;
  }
  image = MapToOriginal(original, cells, best, bestLambda, tolerance);
  return true;
}

std::vector<int> SeamVertexIdentity(int vertexCount, const PolycubeSeams* seams)
{
  std::vector<int> identity(static_cast<size_t>(vertexCount));
  std::iota(identity.begin(), identity.end(), 0);
  if (seams)
  {
    for (const SeamCopy& copy : seams->Copies)
    {
      const int a = FindRoot(identity, copy.Minus);
      const int b = FindRoot(identity, copy.Plus);
      identity[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
    }
  }
  for (int v = 0; v < vertexCount; ++v)
  {
    identity[static_cast<size_t>(v)] = FindRoot(identity, v);
  }
  return identity;
}

std::vector<int> GlueChartsAcrossSeams(const Tets& cells,
  const ChartPlanes& charts,
  const PolycubeSeams* seams)
{
  const int chartCount = static_cast<int>(charts.ChartLabel.size());
  std::vector<int> parent(static_cast<size_t>(chartCount));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::vector<int>> members(static_cast<size_t>(chartCount));
  for (int c = 0; c < chartCount; ++c)
  {
    members[static_cast<size_t>(c)] = { c };
  }
  if (seams && !seams->Empty() && cells.rows() > 0 &&
    charts.ChartNeighbors.size() == static_cast<size_t>(chartCount))
  {
    const std::vector<int> identity = SeamVertexIdentity(cells.maxCoeff() + 1, seams);
    // The charts of the labelled faces on each edge of M_c.
    std::map<std::pair<int, int>, std::vector<int>> edgeCharts;
    for (int t = 0; t < cells.rows(); ++t)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int chart = charts.FaceChart(t, k);
        for (int e = 0; e < 3 && chart >= 0; ++e)
        {
          const int a = cells(t, FaceTable[k][e]);
          const int b = cells(t, FaceTable[k][(e + 1) % 3]);
          edgeCharts[{ std::min(a, b), std::max(a, b) }].push_back(chart);
        }
      }
    }
    // Each cut face on the minus side, its copy on the plus side, and the charts along each of
    // their edges on either side.
    for (int t = 0; t < cells.rows(); ++t)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int n = seams->Neighbor(t, k);
        if (n < 0 || seams->Side(t, k) > 0)
        {
          continue;
        }
        std::array<int, 3> face;
        for (int i = 0; i < 3; ++i)
        {
          face[i] = cells(t, FaceTable[k][i]);
        }
        // The copy: the face of n across from t on the same points of M.
        std::array<int, 3> copy = { -1, -1, -1 };
        for (int k2 = 0; k2 < 4 && copy[0] < 0; ++k2)
        {
          if (seams->Neighbor(n, k2) != t)
          {
            continue;
          }
          std::array<int, 3> candidate = { -1, -1, -1 };
          for (int i = 0; i < 3; ++i)
          {
            for (int j = 0; j < 3; ++j)
            {
              const int w = cells(n, FaceTable[k2][j]);
              if (identity[static_cast<size_t>(w)] == identity[static_cast<size_t>(face[i])])
              {
                candidate[i] = w;
              }
            }
          }
          if (candidate[0] >= 0 && candidate[1] >= 0 && candidate[2] >= 0)
          {
            copy = candidate;
          }
        }
        if (copy[0] < 0)
        {
          continue;
        }
        const Eigen::Matrix3i rotation = seams->Across(t, k).Rotation;
        for (int e = 0; e < 3; ++e)
        {
          const auto minus = edgeCharts.find(
            { std::min(face[e], face[(e + 1) % 3]), std::max(face[e], face[(e + 1) % 3]) });
          const auto plus = edgeCharts.find(
            { std::min(copy[e], copy[(e + 1) % 3]), std::max(copy[e], copy[(e + 1) % 3]) });
          if (minus == edgeCharts.end() || plus == edgeCharts.end())
          {
            continue;
          }
          for (int a : minus->second)
          {
            for (int b : plus->second)
            {
              const int ra = FindRoot(parent, a);
              const int rb = FindRoot(parent, b);
              if (ra == rb ||
                TransformLabel(rotation, charts.ChartLabel[a]) != charts.ChartLabel[b])
              {
                continue;
              }
              bool adjacent = false;
              for (int x : members[static_cast<size_t>(ra)])
              {
                for (int y : members[static_cast<size_t>(rb)])
                {
                  const std::vector<int>& around = charts.ChartNeighbors[static_cast<size_t>(x)];
                  adjacent = adjacent || std::binary_search(around.begin(), around.end(), y);
                }
              }
              if (adjacent)
              {
                continue;
              }
              const int root = std::min(ra, rb);
              const int other = std::max(ra, rb);
              parent[static_cast<size_t>(other)] = root;
              std::vector<int>& into = members[static_cast<size_t>(root)];
              into.insert(into.end(),
                members[static_cast<size_t>(other)].begin(),
                members[static_cast<size_t>(other)].end());
              members[static_cast<size_t>(other)].clear();
            }
          }
        }
      }
    }
  }
  std::vector<int> glued(static_cast<size_t>(chartCount));
  for (int c = 0; c < chartCount; ++c)
  {
    glued[static_cast<size_t>(c)] = FindRoot(parent, c);
  }
  return glued;
}

std::vector<std::vector<int>> GluedVertexCharts(const LatticeHexMesh& lattice,
  const std::vector<int>& glued)
{
  std::vector<std::vector<int>> result(lattice.VertexCharts.size());
  for (size_t v = 0; v < lattice.VertexCharts.size(); ++v)
  {
    // The smallest glued id per label in the vertex's frame.
    std::array<int, 6> byLabel = { -1, -1, -1, -1, -1, -1 };
    for (size_t i = 0; i < lattice.VertexCharts[v].size(); ++i)
    {
      const int chart = glued[static_cast<size_t>(lattice.VertexCharts[v][i])];
      int& slot = byLabel[static_cast<size_t>(lattice.VertexChartLabels[v][i])];
      slot = slot < 0 ? chart : std::min(slot, chart);
    }
    for (int chart : byLabel)
    {
      if (chart >= 0)
      {
        result[v].push_back(chart);
      }
    }
    std::sort(result[v].begin(), result[v].end());
    result[v].erase(std::unique(result[v].begin(), result[v].end()), result[v].end());
  }
  return result;
}

} // namespace polycubehex
