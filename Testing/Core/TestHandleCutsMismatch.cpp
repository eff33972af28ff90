// SPDX-License-Identifier: BSD-3-Clause
// Mismatched edges (section 5.3 of the paper) on a hollow torus: the second cut crosses the
// first (an annulus joining the outer and the inner surface), so its boundary runs along both
// copies of every edge it shares with the first cut: no mismatched edge. Shifting its end along
// one copy only (a valid cut still, lowering beta_1 by one) must be reported as mismatched.
#include "CutMesh.h"
#include "CutRepair.h"
#include "CutSurface.h"
#include "HandleCuts.h"
#include "TestAssert.h"
#include "TetGeometry.h"
#include "TopologyAdjacency.h"
#include "TopologyBoundary.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <numeric>
#include <vector>

using polycubehex::TetMesh;

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Rings `first`..`last` of a polar disk of radius r (ring j: 6j points at radius r j / last;
/// ring 0 is the centre). Returns 2D points and triangles.
void PolarDisk(int first,
  int last,
  double r,
  std::vector<Eigen::Vector2d>& points,
  std::vector<std::array<int, 3>>& triangles)
{
  std::vector<int> ringStart;
  for (int j = first; j <= last; ++j)
  {
    ringStart.push_back(static_cast<int>(points.size()));
    const int count = j == 0 ? 1 : 6 * j;
    for (int k = 0; k < count; ++k)
    {
      const double angle = 2.0 * Pi * k / count;
      points.emplace_back(r * j / last * std::cos(angle), r * j / last * std::sin(angle));
    }
  }
  for (int j = first + 1; j <= last; ++j)
  {
    const int inner = ringStart[j - 1 - first];
    const int outer = ringStart[j - first];
    const int m = j - 1 == 0 ? 1 : 6 * (j - 1);
    const int n = 6 * j;
    if (m == 1)
    {
      for (int k = 0; k < n; ++k)
      {
        triangles.push_back({ inner, outer + k, outer + (k + 1) % n });
      }
      continue;
    }
    int a = 0;
    int b = 0;
    while (a < m || b < n)
    {
      // Advance on the ring whose next point comes first in angle.
      if (b < n && (a == m || static_cast<double>(b + 1) / n <= static_cast<double>(a + 1) / m))
      {
        triangles.push_back({ inner + a % m, outer + b, outer + (b + 1) % n });
        ++b;
      }
      else
      {
        triangles.push_back({ inner + a % m, outer + b % n, inner + (a + 1) % m });
        ++a;
      }
    }
  }
}

/// Appends the 3 tets of the prism (a0 a1 a2, b0 b1 b2); each quad is split along the diagonal
/// from its smallest vertex id, which makes neighbouring prisms conforming.
void SplitPrism(const std::array<int, 3>& a,
  const std::array<int, 3>& b,
  std::vector<std::array<int, 4>>& tets)
{
  std::array<int, 3> bottom = a;
  std::array<int, 3> top = b;
  // Rotate and mirror so that bottom[0] is the smallest of the six ids.
  int best = 0;
  for (int i = 1; i < 6; ++i)
  {
    const int id = i < 3 ? a[i] : b[i - 3];
    const int bestId = best < 3 ? a[best] : b[best - 3];
    if (id < bestId)
    {
      best = i;
    }
  }
  if (best >= 3)
  {
    std::swap(bottom, top);
    best -= 3;
  }
  std::rotate(bottom.begin(), bottom.begin() + best, bottom.end());
  std::rotate(top.begin(), top.begin() + best, top.end());
  tets.push_back({ bottom[0], top[0], top[1], top[2] });
  // The quad (bottom1, bottom2, top2, top1): diagonal from its smallest id.
  const int smallest = std::min({ bottom[1], bottom[2], top[1], top[2] });
  if (smallest == bottom[1] || smallest == top[2])
  {
    tets.push_back({ bottom[0], bottom[1], bottom[2], top[2] });
    tets.push_back({ bottom[0], bottom[1], top[2], top[1] });
  }
  else
  {
    tets.push_back({ bottom[0], bottom[1], bottom[2], top[1] });
    tets.push_back({ bottom[0], bottom[2], top[2], top[1] });
  }
}

/// A polar disk (or annulus, rings first..last) of radius r swept around the z axis at
/// distance R in `stations` steps: a solid torus (first = 0) or a hollow torus (first > 0).
TetMesh SweptTorus(double R, double r, int first, int last, int stations)
{
  std::vector<Eigen::Vector2d> disk;
  std::vector<std::array<int, 3>> triangles;
  PolarDisk(first, last, r, disk, triangles);
  const int p = static_cast<int>(disk.size());
  TetMesh mesh;
  mesh.Vertices.resize(static_cast<Eigen::Index>(p) * stations, 3);
  for (int s = 0; s < stations; ++s)
  {
    const double phi = 2.0 * Pi * s / stations;
    for (int i = 0; i < p; ++i)
    {
      mesh.Vertices.row(s * p + i) << (R + disk[i].x()) * std::cos(phi),
        (R + disk[i].x()) * std::sin(phi), disk[i].y();
    }
  }
  std::vector<std::array<int, 4>> tets;
  for (int s = 0; s < stations; ++s)
  {
    const int next = (s + 1) % stations;
    for (const auto& t : triangles)
    {
      SplitPrism({ s * p + t[0], s * p + t[1], s * p + t[2] },
        { next * p + t[0], next * p + t[1], next * p + t[2] },
        tets);
    }
  }
  mesh.Cells.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
  {
    mesh.Cells.row(t) << tets[t][0], tets[t][1], tets[t][2], tets[t][3];
    if (polycubehex::TetSignedVolume(mesh.Vertices, mesh.Cells, static_cast<int>(t)) < 0.0)
    {
      std::swap(mesh.Cells(t, 0), mesh.Cells(t, 1));
    }
  }
  return mesh;
}

} // namespace

int main(int, char*[])
{
  const TetMesh mesh = SweptTorus(2.0, 0.8, 2, 5, 40);
  polycubehex::HandleCutParameters params;
  polycubehex::HandleCutResult result;
  const auto status = polycubehex::ComputeHandleCuts(mesh, params, result);
  PCH_CHECK(status.Ok());
  PCH_CHECK(result.Cuts.size() == 2);
  if (!status || result.Cuts.size() != 2)
  {
    return PCH_TEST_RESULT();
  }
  PCH_CHECK(result.Cuts[0].EulerCharacteristic == 0 && result.Cuts[0].Loops.size() == 2);
  PCH_CHECK(result.Cuts[1].MismatchedEdgeCount == 0);

  // M_1: the input opened along the first cut.
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  polycubehex::TetAdjacency input;
  polycubehex::BuildTetAdjacency(vertexCount, mesh.Cells, input);
  std::vector<char> cut(input.InteriorFaces.size(), 0);
  for (size_t f = 0; f < input.InteriorFaces.size(); ++f)
  {
    cut[f] = result.CutFaces(input.InteriorFaces[f][0], input.InteriorFaces[f][1]) == 0 ? 1 : 0;
  }
  TetMesh opened;
  std::vector<int> toOriginal;
  polycubehex::SplitAlongFaces(vertexCount, mesh.Cells, input, cut, opened.Cells, toOriginal);
  opened.Vertices.resize(static_cast<Eigen::Index>(toOriginal.size()), 3);
  for (size_t v = 0; v < toOriginal.size(); ++v)
  {
    opened.Vertices.row(v) = mesh.Vertices.row(toOriginal[v]);
  }
  polycubehex::TetAdjacency adjacency;
  polycubehex::BuildTetAdjacency(static_cast<int>(toOriginal.size()), opened.Cells, adjacency);

  // The second cut on M_1: crosses the first, so no mismatched edge.
  std::vector<int> cocycle(adjacency.InteriorFaces.size(), 0);
  std::vector<polycubehex::CutFaceEntry> entries;
  for (const auto& face : result.Cuts[1].Faces)
  {
    const int id = adjacency.InteriorFaceId(face[0], face[1]);
    const int side = adjacency.InteriorFaces[id][0] == face[0] ? 1 : -1;
    entries.push_back({ id, side });
    cocycle[id] = side;
  }
  polycubehex::CutSurfaceReport report;
  polycubehex::AnalyzeCutSurface(opened.Cells, adjacency, opened.Vertices, entries, report);
  PCH_CHECK(report.Valid());
  const int matched = polycubehex::CountMismatchedCutEdges(input, report.Loops, toOriginal);
  std::cout << "second cut: " << report.Area << " area, " << matched << " mismatched edges"
            << std::endl;
  PCH_CHECK(matched == 0);

  // Shift its end along the copies of the first cut that got new vertex ids (one side only):
  // move the minus-side tets touching them across, then repair.
  std::vector<char> inK(adjacency.TetCount, 0);
  for (const auto& face : result.Cuts[1].Faces)
  {
    const int t = face[0];
    for (int i = 0; i < 4; ++i)
    {
      inK[t] = inK[t] || opened.Cells(t, i) >= vertexCount;
    }
  }
  for (int t = 0; t < adjacency.TetCount; ++t)
  {
    if (!inK[t])
    {
      continue;
    }
    for (int k = 0; k < 4; ++k)
    {
      const int n = adjacency.Neighbor(t, k);
      if (n >= 0 && !inK[n])
      {
        cocycle[adjacency.InteriorFaceId(t, k)] -= polycubehex::InteriorFaceSign(adjacency, t, k);
      }
    }
  }
  std::vector<double> faceArea(adjacency.InteriorFaces.size());
  for (size_t f = 0; f < faceArea.size(); ++f)
  {
    faceArea[f] =
      polycubehex::InteriorFaceArea(opened.Cells, adjacency, opened.Vertices, static_cast<int>(f));
  }
  PCH_CHECK(polycubehex::RepairCocycleSurface(opened.Cells, adjacency, faceArea, cocycle, 10000));
  entries.clear();
  for (size_t f = 0; f < cocycle.size(); ++f)
  {
    if (cocycle[f] != 0)
    {
      entries.push_back({ static_cast<int>(f), cocycle[f] > 0 ? 1 : -1 });
    }
  }
  polycubehex::AnalyzeCutSurface(opened.Cells, adjacency, opened.Vertices, entries, report);
  if (!report.Valid())
  {
    std::cerr << report.Problem << std::endl;
  }
  PCH_CHECK(report.Valid());
  const int mismatched = polycubehex::CountMismatchedCutEdges(input, report.Loops, toOriginal);
  std::cout << "shifted second cut: " << report.Area << " area, " << mismatched
            << " mismatched edges" << std::endl;
  PCH_CHECK(mismatched > 0);

  // It is still a valid cut: beta_1 of M_1 cut along it is 0.
  std::vector<char> second(adjacency.InteriorFaces.size(), 0);
  for (const auto& entry : entries)
  {
    second[entry.Face] = 1;
  }
  TetMesh twice;
  std::vector<int> splitToOld;
  polycubehex::SplitAlongFaces(
    static_cast<int>(toOriginal.size()), opened.Cells, adjacency, second, twice.Cells, splitToOld);
  polycubehex::TetAdjacency twiceAdjacency;
  polycubehex::BuildTetAdjacency(static_cast<int>(splitToOld.size()), twice.Cells, twiceAdjacency);
  polycubehex::BoundaryTopology boundary;
  PCH_CHECK(polycubehex::ComputeBoundaryTopology(twice.Cells, twiceAdjacency, boundary).Ok());
  PCH_CHECK(boundary.Beta1 == 0);
  return PCH_TEST_RESULT();
}
