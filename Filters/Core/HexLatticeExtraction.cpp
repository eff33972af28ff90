// SPDX-License-Identifier: BSD-3-Clause
#include "HexLatticeExtraction.h"

#include "DisjointSets.h"
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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
} // namespace

Status extractLatticeHexes(const Points& original,
  const Points& lattice,
  const Tets& cells,
  const ChartPlanes& charts,
  const LatticeExtractionParameters& params,
  LatticeHexMesh& out,
  const Progress& progress)
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

  // 2. One vertex (one cube) per coordinate and connected group of tets.
  std::vector<PointGroup> vertices;
  std::unordered_map<Key, std::vector<int>> verticesAt;
  GroupHits(vertexHits, cells, charts, tol, vertices, verticesAt);
  std::vector<PointGroup> centres;
  std::unordered_map<Key, std::vector<int>> centresAt;
  GroupHits(centreHits, cells, charts, tol, centres, centresAt);
  if (!ReportProgress(progress, 0.7))
  {
    return Status::Failure("hex extraction aborted");
  }

  // 3. Hexes: the 8 corners of each cube whose centre is inside.
  std::vector<int> vertexIndex(vertices.size(), -1);
  std::vector<int> usedVertices;
  std::vector<std::array<int, 8>> hexes;
  std::vector<Eigen::RowVector3d> hexCentres;
  std::vector<int> visitStamp(tetCount, -1);
  for (int c = 0; c < static_cast<int>(centres.size()); ++c)
  {
    const PointGroup& centre = centres[c];
    std::array<int, 8> corners;
    bool complete = true;
    std::vector<int> neighbourhood; // tets around the cube, computed on demand
    for (int k = 0; k < 8 && complete; ++k)
    {
      const Key key = Pack(centre.Cell[0] + CubeCorners[k][0],
        centre.Cell[1] + CubeCorners[k][1],
        centre.Cell[2] + CubeCorners[k][2]);
      const auto found = verticesAt.find(key);
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
      if (neighbourhood.empty())
      {
        std::vector<int> stack(centre.Tets.begin(), centre.Tets.end());
        for (int t : stack)
        {
          visitStamp[t] = c;
        }
        while (!stack.empty())
        {
          const int t = stack.back();
          stack.pop_back();
          neighbourhood.push_back(t);
          for (int f = 0; f < 4; ++f)
          {
            const int n = charts.Neighbors(t, f);
            if (n < 0 || visitStamp[n] == c)
            {
              continue;
            }
            bool overlaps = true;
            for (int a = 0; a < 3 && overlaps; ++a)
            {
              double lo = lattice(cells(n, 0), a);
              double hi = lo;
              for (int i = 1; i < 4; ++i)
              {
                lo = std::min(lo, lattice(cells(n, i), a));
                hi = std::max(hi, lattice(cells(n, i), a));
              }
              overlaps = hi >= centre.Cell[a] - 1e-6 && lo <= centre.Cell[a] + 1 + 1e-6;
            }
            if (overlaps)
            {
              visitStamp[n] = c;
              stack.push_back(n);
            }
          }
        }
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
    }
    hexes.push_back(hex);
    hexCentres.push_back(MapToOriginal(original, cells, centre.Tet, centre.Lambda, tol));
  }

  // 4. Output arrays.
  const int vertexCount = static_cast<int>(usedVertices.size());
  out.Mesh.Vertices.resize(vertexCount, 3);
  out.LatticeVertices.resize(vertexCount, 3);
  out.VertexCharts.resize(vertexCount);
  out.VertexTets.resize(vertexCount);
  for (int v = 0; v < vertexCount; ++v)
  {
    const PointGroup& group = vertices[usedVertices[v]];
    out.Mesh.Vertices.row(v) = MapToOriginal(original, cells, group.Tet, group.Lambda, tol);
    for (int a = 0; a < 3; ++a)
    {
      out.LatticeVertices(v, a) = static_cast<double>(group.Cell[a]);
    }
    out.VertexCharts[v] = group.Charts;
    out.VertexTets[v] = group.Tet;
  }
  const int hexCount = static_cast<int>(hexes.size());
  out.Mesh.Cells.resize(hexCount, 8);
  out.HexCenters.resize(hexCount, 3);
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      out.Mesh.Cells(h, k) = hexes[h][k];
    }
    out.HexCenters.row(h) = hexCentres[h];
  }
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
  Eigen::RowVector3d& image)
{
  const Eigen::Vector3d low = from.cwiseMin(point).array() - 1e-6;
  const Eigen::Vector3d high = from.cwiseMax(point).array() + 1e-6;
  auto overlaps = [&](int t)
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
  };
  std::vector<int> stack = { start };
  std::unordered_set<int> seen = { start };
  int best = -1;
  std::array<double, 4> bestLambda = {};
  double bestDepth = -std::numeric_limits<double>::max();
  while (!stack.empty())
  {
    const int t = stack.back();
    stack.pop_back();
    std::array<Eigen::Vector3d, 4> u;
    for (int i = 0; i < 4; ++i)
    {
      u[i] = lattice.row(cells(t, i)).transpose();
    }
    std::array<double, 4> lambda;
    if (Barycentric(u, point, tolerance, lambda))
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
      const int n = charts.Neighbors(t, f);
      if (n >= 0 && !seen.count(n) && overlaps(n))
      {
        seen.insert(n);
        stack.push_back(n);
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

} // namespace polycubehex
