// SPDX-License-Identifier: BSD-3-Clause
// Topology of tet meshes: boundary components, genera and beta_1 by Alexander duality, against
// beta_1 from the dual complex (TopologyHomology), on solids generated here: a swept solid torus,
// a swept hollow torus (a torus with a torus-shaped void), and, with TetGen, a ball, a ball with
// a spherical void and a ball with a torus-shaped void. Non-manifold boundaries are refused with
// a message naming the edge or the vertex.
#include "TestAssert.h"
#include "TetGeometry.h"
#include "Tetrahedralize.h"
#include "TopologyAdjacency.h"
#include "TopologyBoundary.h"
#include "TopologyHomology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using polycubehex::SurfaceMesh;
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

SurfaceMesh Icosphere(int levels, double radius)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> points = { { -1, t, 0 },
    { 1, t, 0 },
    { -1, -t, 0 },
    { 1, -t, 0 },
    { 0, -1, t },
    { 0, 1, t },
    { 0, -1, -t },
    { 0, 1, -t },
    { t, 0, -1 },
    { t, 0, 1 },
    { -t, 0, -1 },
    { -t, 0, 1 } };
  std::vector<std::array<int, 3>> faces = { { 0, 11, 5 },
    { 0, 5, 1 },
    { 0, 1, 7 },
    { 0, 7, 10 },
    { 0, 10, 11 },
    { 1, 5, 9 },
    { 5, 11, 4 },
    { 11, 10, 2 },
    { 10, 7, 6 },
    { 7, 1, 8 },
    { 3, 9, 4 },
    { 3, 4, 2 },
    { 3, 2, 6 },
    { 3, 6, 8 },
    { 3, 8, 9 },
    { 4, 9, 5 },
    { 2, 4, 11 },
    { 6, 2, 10 },
    { 8, 6, 7 },
    { 9, 8, 1 } };
  for (int level = 0; level < levels; ++level)
  {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b)
    {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      points.push_back(0.5 * (points[a] + points[b]));
      return midpoints[key] = static_cast<int>(points.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& f : faces)
    {
      const int ab = midpoint(f[0], f[1]);
      const int bc = midpoint(f[1], f[2]);
      const int ca = midpoint(f[2], f[0]);
      finer.push_back({ f[0], ab, ca });
      finer.push_back({ f[1], bc, ab });
      finer.push_back({ f[2], ca, bc });
      finer.push_back({ ab, bc, ca });
    }
    faces.swap(finer);
  }
  SurfaceMesh mesh;
  mesh.Vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v)
  {
    mesh.Vertices.row(v) = radius * points[v].normalized().transpose();
  }
  mesh.Faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
  {
    const Eigen::Vector3d p0 = points[faces[f][0]];
    const Eigen::Vector3d n = (points[faces[f][1]] - p0).cross(points[faces[f][2]] - p0);
    if (n.dot(p0) < 0.0)
    {
      std::swap(faces[f][1], faces[f][2]);
    }
    mesh.Faces.row(f) << faces[f][0], faces[f][1], faces[f][2];
  }
  return mesh;
}

SurfaceMesh TorusSurface(double R, double r, int n, int m)
{
  SurfaceMesh mesh;
  mesh.Vertices.resize(n * m, 3);
  mesh.Faces.resize(2 * n * m, 3);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const double u = 2.0 * Pi * i / n;
      const double v = 2.0 * Pi * j / m;
      mesh.Vertices.row(i * m + j) << (R + r * std::cos(v)) * std::cos(u),
        (R + r * std::cos(v)) * std::sin(u), r * std::sin(v);
      const int a = i * m + j;
      const int b = ((i + 1) % n) * m + j;
      const int c = ((i + 1) % n) * m + (j + 1) % m;
      const int d = i * m + (j + 1) % m;
      mesh.Faces.row(2 * a) << a, b, c;
      mesh.Faces.row(2 * a + 1) << a, c, d;
    }
  }
  return mesh;
}

SurfaceMesh Merge(const SurfaceMesh& a, const SurfaceMesh& b)
{
  SurfaceMesh mesh;
  mesh.Vertices.resize(a.Vertices.rows() + b.Vertices.rows(), 3);
  mesh.Vertices << a.Vertices, b.Vertices;
  mesh.Faces.resize(a.Faces.rows() + b.Faces.rows(), 3);
  mesh.Faces << a.Faces, (b.Faces.array() + static_cast<int>(a.Vertices.rows())).matrix();
  return mesh;
}

struct Expected
{
  int Beta1;
  std::vector<int> Genus; // sorted
};

void CheckTopology(const std::string& name, const TetMesh& mesh, const Expected& expected)
{
  polycubehex::TetAdjacency adjacency;
  const auto built =
    polycubehex::BuildTetAdjacency(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency);
  PCH_CHECK(built.Ok());
  polycubehex::BoundaryTopology boundary;
  const auto status = polycubehex::ComputeBoundaryTopology(mesh.Cells, adjacency, boundary);
  if (!status)
  {
    std::cerr << name << ": " << status.Message() << std::endl;
  }
  PCH_CHECK(status.Ok());
  std::vector<int> genus = boundary.ComponentGenus;
  std::sort(genus.begin(), genus.end());
  polycubehex::CohomologyBasis basis;
  const auto homology = polycubehex::ComputeCohomologyBasis(mesh.Cells, adjacency, true, basis);
  if (!homology)
  {
    std::cerr << name << ": " << homology.Message() << std::endl;
  }
  PCH_CHECK(homology.Ok());
  std::cout << name << ": " << mesh.Cells.rows() << " tets, boundary components " << genus.size()
            << ", beta1 (genus) " << boundary.Beta1 << ", beta1 (homology) " << basis.Beta1
            << ", beta2 " << boundary.Beta2 << "; after collapse " << basis.RemainingFaceCount
            << " faces in " << basis.SheetCount << " sheets, " << basis.RelationCount
            << " seam relations" << std::endl;
  PCH_CHECK(boundary.Beta1 == expected.Beta1);
  PCH_CHECK(basis.Beta1 == expected.Beta1);
  PCH_CHECK(genus == expected.Genus);
  PCH_CHECK(static_cast<int>(basis.Cocycles.size()) == expected.Beta1);
  for (const auto& cocycle : basis.Cocycles)
  {
    PCH_CHECK(polycubehex::IsCocycle(mesh.Cells, adjacency, cocycle));
  }
}

bool Tetrahedralized(const SurfaceMesh& surface, TetMesh& mesh)
{
  std::string switches;
  polycubehex::TetrahedralizeParameters params;
  const auto status = polycubehex::Tetrahedralize(surface, params, mesh, switches);
  if (!status)
  {
    std::cerr << "Tetrahedralize: " << status.Message() << std::endl;
  }
  return status.Ok();
}

bool FailsMentioning(const TetMesh& mesh, const std::string& words)
{
  polycubehex::TetAdjacency adjacency;
  if (!polycubehex::BuildTetAdjacency(
        static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency))
  {
    return false;
  }
  polycubehex::BoundaryTopology boundary;
  const auto status = polycubehex::ComputeBoundaryTopology(mesh.Cells, adjacency, boundary);
  std::cout << "refused: " << status.Message() << std::endl;
  return !status.Ok() && status.Message().find(words) != std::string::npos;
}
} // namespace

int main(int, char*[])
{
  CheckTopology("swept solid torus", SweptTorus(2.0, 0.5, 0, 3, 24), { 1, { 1 } });
  CheckTopology("swept hollow torus", SweptTorus(2.0, 0.8, 2, 5, 32), { 2, { 1, 1 } });
  CheckTopology("swept thin torus", SweptTorus(2.0, 0.5, 0, 1, 8), { 1, { 1 } });

  TetMesh mesh;
  if (Tetrahedralized(Icosphere(2, 1.0), mesh))
  {
    CheckTopology("ball", mesh, { 0, { 0 } });
  }
  if (Tetrahedralized(Merge(Icosphere(3, 2.0), Icosphere(2, 1.0)), mesh))
  {
    CheckTopology("ball with a spherical void", mesh, { 0, { 0, 0 } });
  }
  if (Tetrahedralized(Merge(Icosphere(3, 2.0), TorusSurface(1.0, 0.35, 32, 12)), mesh))
  {
    CheckTopology("ball with a torus-shaped void", mesh, { 1, { 0, 1 } });
  }
  if (Tetrahedralized(Merge(TorusSurface(2.0, 0.8, 48, 16), TorusSurface(2.0, 0.4, 40, 12)), mesh))
  {
    CheckTopology("hollow torus (TetGen)", mesh, { 2, { 1, 1 } });
  }

  // Two tets sharing only a vertex, then only an edge: non-manifold boundaries.
  TetMesh pinched;
  pinched.Vertices.resize(7, 3);
  pinched.Vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
  pinched.Cells.resize(2, 4);
  pinched.Cells << 0, 1, 2, 3, 0, 4, 6, 5;
  PCH_CHECK(FailsMentioning(pinched, "vertex 0"));
  TetMesh hinge;
  hinge.Vertices.resize(6, 3);
  hinge.Vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1;
  hinge.Cells.resize(2, 4);
  hinge.Cells << 0, 1, 2, 3, 0, 1, 5, 4;
  PCH_CHECK(FailsMentioning(hinge, "edge (0, 1)"));
  return PCH_TEST_RESULT();
}
