// SPDX-License-Identifier: BSD-3-Clause
// Solids and surfaces generated for the core tests (header-only, shared so that each generator
// is written once): swept solid and hollow tori, a torus one tet thick, icospheres, tori, single
// and glued tets, the merge of two surfaces, grids of tets and of hexes, plus small helpers.
#pragma once

#include "MeshTypes.h"
#include "TetGeometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace polycubehex_test
{
using polycubehex::SurfaceMesh;
using polycubehex::TetMesh;

constexpr double Pi = 3.14159265358979323846;

/// Rings `first`..`last` of a polar disk of radius r (ring j: 6j points at radius r j / last;
/// ring 0 is the centre). Returns 2D points and triangles.
inline void PolarDisk(int first,
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
inline void SplitPrism(const std::array<int, 3>& a,
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

/// Sets mesh.Cells to `tets`, each flipped (first two corners swapped) where it is negative on
/// mesh.Vertices.
inline void SetPositiveCells(TetMesh& mesh, const std::vector<std::array<int, 4>>& tets)
{
  mesh.Cells.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
  {
    mesh.Cells.row(t) << tets[t][0], tets[t][1], tets[t][2], tets[t][3];
    if (polycubehex::TetSignedVolume(mesh.Vertices, mesh.Cells, static_cast<int>(t)) < 0.0)
    {
      std::swap(mesh.Cells(t, 0), mesh.Cells(t, 1));
    }
  }
}

/// A polar disk (or annulus, rings first..last) of radius r swept around the z axis at
/// distance R in `stations` steps: a solid torus (first = 0) or a hollow torus (first > 0).
inline TetMesh SweptTorus(double R, double r, int first, int last, int stations)
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
  SetPositiveCells(mesh, tets);
  return mesh;
}

/// A solid torus one tet thick: a regular `sides`-gon of radius r, fan-triangulated from its
/// first corner (no vertex inside), swept around the z axis at distance R in `stations` steps.
/// Every vertex lies on the boundary.
inline TetMesh ThinTorus(double R, double r, int sides, int stations)
{
  TetMesh mesh;
  mesh.Vertices.resize(static_cast<Eigen::Index>(sides) * stations, 3);
  for (int s = 0; s < stations; ++s)
  {
    const double phi = 2.0 * Pi * s / stations;
    for (int i = 0; i < sides; ++i)
    {
      const double v = 2.0 * Pi * i / sides;
      mesh.Vertices.row(s * sides + i) << (R + r * std::cos(v)) * std::cos(phi),
        (R + r * std::cos(v)) * std::sin(phi), r * std::sin(v);
    }
  }
  std::vector<std::array<int, 4>> tets;
  for (int s = 0; s < stations; ++s)
  {
    const int a = s * sides;
    const int b = ((s + 1) % stations) * sides;
    for (int i = 1; i + 1 < sides; ++i)
    {
      SplitPrism({ a, a + i, a + i + 1 }, { b, b + i, b + i + 1 }, tets);
    }
  }
  SetPositiveCells(mesh, tets);
  return mesh;
}

/// Icosahedron subdivided `levels` times (20 * 4^levels triangles) and projected on the sphere
/// of the given radius and centre (default: the origin); outward unless `inward` (for a void).
inline SurfaceMesh Icosphere(int levels,
  double radius,
  const Eigen::Vector3d& centre = Eigen::Vector3d::Zero(),
  bool inward = false)
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
      midpoints[key] = static_cast<int>(points.size()) - 1;
      return static_cast<int>(points.size()) - 1;
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
  mesh.Vertices.resize(points.size(), 3);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    mesh.Vertices.row(v) = (centre + radius * points[v].normalized()).transpose();
  }
  mesh.Faces.resize(faces.size(), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    // Convex around the centre: orient each face by its normal against its centroid.
    const Eigen::Vector3d p0 = points[faces[f][0]];
    const Eigen::Vector3d n = (points[faces[f][1]] - p0).cross(points[faces[f][2]] - p0);
    const bool outward = n.dot(p0 + points[faces[f][1]] + points[faces[f][2]]) > 0.0;
    if (outward == inward)
    {
      std::swap(faces[f][1], faces[f][2]);
    }
    mesh.Faces.row(f) << faces[f][0], faces[f][1], faces[f][2];
  }
  return mesh;
}

/// A torus of radii R > r around the z axis, n by m quads split into triangles, outward.
inline SurfaceMesh Torus(double R, double r, int n, int m)
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
      // Counter-clockwise seen from outside for this parametrization.
      mesh.Faces.row(2 * a) << a, b, c;
      mesh.Faces.row(2 * a + 1) << a, c, d;
    }
  }
  return mesh;
}

/// The four outward faces of a positive tet (VTK's local face table).
inline SurfaceMesh TetSurface(const std::array<Eigen::Vector3d, 4>& p)
{
  SurfaceMesh mesh;
  mesh.Vertices.resize(4, 3);
  for (int v = 0; v < 4; ++v)
  {
    mesh.Vertices.row(v) = p[v].transpose();
  }
  mesh.Faces.resize(4, 3);
  mesh.Faces << 0, 1, 3, 1, 2, 3, 2, 0, 3, 0, 2, 1;
  return mesh;
}

/// The disjoint union of two surfaces: b's vertices follow a's, b's faces are renumbered.
inline SurfaceMesh Merge(const SurfaceMesh& a, const SurfaceMesh& b)
{
  SurfaceMesh mesh;
  mesh.Vertices.resize(a.Vertices.rows() + b.Vertices.rows(), 3);
  mesh.Vertices << a.Vertices, b.Vertices;
  mesh.Faces.resize(a.Faces.rows() + b.Faces.rows(), 3);
  mesh.Faces << a.Faces, (b.Faces.array() + static_cast<int>(a.Vertices.rows())).matrix();
  return mesh;
}

/// Two tet surfaces glued at the first `shared` vertices of the second onto the first's: a
/// non-manifold surface sharing an edge (shared == 2) or a vertex (shared == 1).
inline SurfaceMesh GlueTets(int shared)
{
  const SurfaceMesh a = TetSurface({ Eigen::Vector3d(0, 0, 0),
    Eigen::Vector3d(1, 0, 0),
    Eigen::Vector3d(0, 1, 0),
    Eigen::Vector3d(0, 0, 1) });
  SurfaceMesh b = shared == 2 ? TetSurface({ Eigen::Vector3d(0, 0, 0),
                                  Eigen::Vector3d(1, 0, 0),
                                  Eigen::Vector3d(0, -1, 0),
                                  Eigen::Vector3d(0, 0, -1) })
                              : TetSurface({ Eigen::Vector3d(0, 0, 0),
                                  Eigen::Vector3d(0, -1, 0),
                                  Eigen::Vector3d(-1, 0, 0),
                                  Eigen::Vector3d(0, 0, -1) });
  SurfaceMesh glued = Merge(a, b);
  // Vertex i < shared of b is vertex i of a: renumber, leaving b's copy unused.
  for (Eigen::Index f = a.Faces.rows(); f < glued.Faces.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (glued.Faces(f, k) < 4 + shared)
      {
        glued.Faces(f, k) -= 4;
      }
    }
  }
  return glued;
}

/// True when `part` occurs in `text`; otherwise prints both and returns false.
inline bool Contains(const std::string& text, const std::string& part)
{
  const bool found = text.find(part) != std::string::npos;
  if (!found)
  {
    std::cerr << "message \"" << text << "\" does not contain \"" << part << "\"" << std::endl;
  }
  return found;
}

/// Enclosed volume of a closed, consistently oriented surface (positive when outward).
inline double PolyhedronVolume(const SurfaceMesh& mesh)
{
  // Relative to a vertex: far from the origin the plain sum cancels catastrophically.
  const Eigen::Vector3d origin = mesh.Vertices.row(0).transpose();
  double sixVolume = 0.0;
  for (int f = 0; f < mesh.Faces.rows(); ++f)
  {
    const Eigen::Vector3d p0 = mesh.Vertices.row(mesh.Faces(f, 0)).transpose() - origin;
    const Eigen::Vector3d p1 = mesh.Vertices.row(mesh.Faces(f, 1)).transpose() - origin;
    const Eigen::Vector3d p2 = mesh.Vertices.row(mesh.Faces(f, 2)).transpose() - origin;
    sixVolume += p0.dot(p1.cross(p2));
  }
  return sixVolume / 6.0;
}

/// An n^3 grid of the cube [-1, 1]^3, each grid cube split into 6 tets around its main
/// diagonal, positively oriented (a negative tet gets its vertices 2 and 3 swapped).
inline TetMesh CubeGrid(int n)
{
  TetMesh mesh;
  const int m = n + 1;
  mesh.Vertices.resize(m * m * m, 3);
  auto id = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k)
        mesh.Vertices.row(id(i, j, k)) << -1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n,
          -1.0 + 2.0 * k / n;
  const int perms[6][3] = {
    { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
  };
  mesh.Cells.resize(6 * n * n * n, 4);
  int t = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& p : perms)
        {
          int c[3] = { i, j, k };
          mesh.Cells(t, 0) = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++c[p[s]];
            mesh.Cells(t, s + 1) = id(c[0], c[1], c[2]);
          }
          if (polycubehex::TetSignedVolume(mesh.Vertices, mesh.Cells, t) < 0.0)
          {
            std::swap(mesh.Cells(t, 2), mesh.Cells(t, 3));
          }
          ++t;
        }
  return mesh;
}

/// An n x n x n grid of unit hexes with its minimum corner at the origin, in VTK's node order
/// (positive volume).
inline polycubehex::HexMesh HexCubeGrid(int n)
{
  const int m = n + 1;
  auto id = [m](int i, int j, int k) { return i + m * (j + m * k); };
  polycubehex::HexMesh mesh;
  mesh.Vertices.resize(m * m * m, 3);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        mesh.Vertices.row(id(i, j, k)) << i, j, k;
  mesh.Cells.resize(n * n * n, 8);
  int h = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        mesh.Cells.row(h++) << id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1);
  return mesh;
}

/// The integer corners (i, j, k) of an nx by ny by nz block of unit cubes.
inline std::vector<std::array<int, 3>> BlockCells(int nx, int ny, int nz)
{
  std::vector<std::array<int, 3>> cubes;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        cubes.push_back({ i, j, k });
  return cubes;
}

// Flips tets of negative volume into VTK's positive order.
inline void Orient(TetMesh& mesh)
{
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    if (polycubehex::TetSignedVolume(mesh.Vertices, mesh.Cells, t) < 0.0)
    {
      std::swap(mesh.Cells(t, 2), mesh.Cells(t, 3));
    }
  }
}

// A 2D triangulation: points and counter-clockwise triangles.
struct Planar
{
  std::vector<Eigen::Vector2d> Points;
  std::vector<std::array<int, 3>> Triangles;
};

// The unit disk in n concentric rings of 6k points.
inline Planar MakeDisk(int n)
{
  Planar disk;
  disk.Points.push_back(Eigen::Vector2d::Zero());
  std::vector<std::vector<int>> rings = { { 0 } };
  for (int k = 1; k <= n; ++k)
  {
    std::vector<int> ring;
    for (int j = 0; j < 6 * k; ++j)
    {
      const double a = 2.0 * Pi * j / (6 * k);
      ring.push_back(static_cast<int>(disk.Points.size()));
      disk.Points.push_back(Eigen::Vector2d(std::cos(a), std::sin(a)) * k / n);
    }
    const std::vector<int>& inner = rings.back();
    const int m0 = static_cast<int>(inner.size());
    const int m1 = static_cast<int>(ring.size());
    int i = 0;
    int j = 0;
    while (j < m1 || (m0 > 1 && i < m0))
    {
      const double nextInner = m0 > 1 ? (i + 1.0) / m0 : 2.0;
      const double nextOuter = (j + 1.0) / m1;
      if (j < m1 && (m0 == 1 || i >= m0 || nextOuter <= nextInner))
      {
        disk.Triangles.push_back({ inner[i % m0], ring[j % m1], ring[(j + 1) % m1] });
        ++j;
      }
      else
      {
        disk.Triangles.push_back({ inner[i % m0], ring[j % m1], inner[(i + 1) % m0] });
        ++i;
      }
    }
    rings.push_back(ring);
  }
  return disk;
}

// The square [-1, 1]^2 in n^2 cells, each split into 4 triangles at its centre, so that the
// triangulation is invariant under quarter turns. `quarter` maps each point to its image.
inline Planar MakeSquare(int n, std::vector<int>& quarter)
{
  Planar square;
  const int m = n + 1;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      square.Points.push_back(Eigen::Vector2d(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const int centre = static_cast<int>(square.Points.size());
      square.Points.push_back(
        Eigen::Vector2d(-1.0 + (2.0 * i + 1.0) / n, -1.0 + (2.0 * j + 1.0) / n));
      const int c[4] = { i * m + j, (i + 1) * m + j, (i + 1) * m + j + 1, i * m + j + 1 };
      for (int e = 0; e < 4; ++e)
      {
        square.Triangles.push_back({ centre, c[e], c[(e + 1) % 4] });
      }
    }
  quarter.assign(square.Points.size(), -1);
  for (size_t p = 0; p < square.Points.size(); ++p)
  {
    const Eigen::Vector2d image(-square.Points[p](1), square.Points[p](0));
    for (size_t q = 0; q < square.Points.size(); ++q)
    {
      if ((square.Points[q] - image).norm() < 1e-9)
      {
        quarter[p] = static_cast<int>(q);
      }
    }
  }
  return square;
}

// Sweeps a planar triangulation through `layers` layers of prisms, each split into 3 tets with
// the diagonal of each side quad from the lower 2D index at the bottom to the higher one at the
// top (consistent between neighbours). `place(layer, point)` positions the copies; with
// `periodic` the last layer's top is layer 0 with its points renumbered by `seam`.
inline TetMesh Sweep(const Planar& planar,
  int layers,
  bool periodic,
  const std::vector<int>& seam,
  const std::function<Eigen::Vector3d(int, const Eigen::Vector2d&)>& place)
{
  const int nv = static_cast<int>(planar.Points.size());
  const int copies = periodic ? layers : layers + 1;
  TetMesh mesh;
  mesh.Vertices.resize(copies * nv, 3);
  for (int l = 0; l < copies; ++l)
    for (int v = 0; v < nv; ++v)
      mesh.Vertices.row(l * nv + v) = place(l, planar.Points[v]).transpose();
  mesh.Cells.resize(3 * layers * static_cast<int>(planar.Triangles.size()), 4);
  int t = 0;
  for (int l = 0; l < layers; ++l)
  {
    for (std::array<int, 3> tri : planar.Triangles)
    {
      std::sort(tri.begin(), tri.end());
      auto bottom = [&](int v) { return l * nv + v; };
      auto top = [&](int v)
      {
        if (periodic && l == layers - 1)
        {
          return seam.empty() ? v : seam[v];
        }
        return (l + 1) * nv + v;
      };
      const int a = tri[0], b = tri[1], c = tri[2];
      mesh.Cells.row(t++) << bottom(a), bottom(b), bottom(c), top(c);
      mesh.Cells.row(t++) << bottom(a), bottom(b), top(b), top(c);
      mesh.Cells.row(t++) << bottom(a), top(a), top(b), top(c);
    }
  }
  Orient(mesh);
  return mesh;
}

} // namespace polycubehex_test
