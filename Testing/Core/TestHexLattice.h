// SPDX-License-Identifier: BSD-3-Clause
// A cube lattice whose charts are the cube's six faces, for the tests of the untangling and the
// smoothing: its hexes, the charts of every vertex, and the cube's boundary as chart triangles.
#pragma once

#include "HexPadding.h"
#include "HexSurfaceProjection.h"
#include "MeshTypes.h"

#include "TestAssert.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace polycubehex
{
namespace testing
{
/// An n x n x n lattice of cubes filling [0, 1]^3, VTK node order; vertex (i, j, k) has id
/// i + (n + 1) (j + (n + 1) k).
struct Lattice
{
  int N = 0;
  HexMesh Mesh;
  std::vector<std::vector<int>> VertexCharts; ///< charts 0..5: x = 0, x = 1, y = 0, ... z = 1
  HexSmoothingSurface Surface;                ///< the cube's boundary, two triangles per quad

  int Id(int i, int j, int k) const { return i + (this->N + 1) * (j + (this->N + 1) * k); }
};

inline Lattice MakeLattice(int n)
{
  Lattice lattice;
  lattice.N = n;
  const int m = n + 1;
  HexMesh& mesh = lattice.Mesh;
  mesh.Vertices.resize(m * m * m, 3);
  lattice.VertexCharts.resize(static_cast<size_t>(m * m * m));
  for (int k = 0; k < m; ++k)
  {
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        const int v = lattice.Id(i, j, k);
        mesh.Vertices.row(v) << static_cast<double>(i) / n, static_cast<double>(j) / n,
          static_cast<double>(k) / n;
        const int index[3] = { i, j, k };
        for (int a = 0; a < 3; ++a)
        {
          if (index[a] == 0 || index[a] == n)
          {
            lattice.VertexCharts[static_cast<size_t>(v)].push_back(2 * a + (index[a] == n));
          }
        }
      }
    }
  }
  mesh.Cells.resize(n * n * n, 8);
  int h = 0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        mesh.Cells.row(h++) << lattice.Id(i, j, k), lattice.Id(i + 1, j, k),
          lattice.Id(i + 1, j + 1, k), lattice.Id(i, j + 1, k), lattice.Id(i, j, k + 1),
          lattice.Id(i + 1, j, k + 1), lattice.Id(i + 1, j + 1, k + 1), lattice.Id(i, j + 1, k + 1);
      }
    }
  }
  // The surface: the boundary quads of the unperturbed lattice, each quad's chart the face its
  // four vertices share.
  const Quads quads = ComputeHexBoundaryQuads(mesh);
  lattice.Surface.Vertices = mesh.Vertices;
  lattice.Surface.Faces.resize(2 * quads.rows(), 3);
  for (int q = 0; q < quads.rows(); ++q)
  {
    lattice.Surface.Faces.row(2 * q) << quads(q, 0), quads(q, 1), quads(q, 2);
    lattice.Surface.Faces.row(2 * q + 1) << quads(q, 0), quads(q, 2), quads(q, 3);
    std::vector<int> common = lattice.VertexCharts[static_cast<size_t>(quads(q, 0))];
    for (int c = 1; c < 4; ++c)
    {
      const auto& other = lattice.VertexCharts[static_cast<size_t>(quads(q, c))];
      std::vector<int> both;
      std::set_intersection(
        common.begin(), common.end(), other.begin(), other.end(), std::back_inserter(both));
      common.swap(both);
    }
    PCH_CHECK(common.size() == 1);
    lattice.Surface.FaceChart.push_back(common.front());
    lattice.Surface.FaceChart.push_back(common.front());
  }
  return lattice;
}

/// Largest distance of a vertex from where its charts allow it: on each of its faces' planes,
/// and inside the cube.
inline double SurfaceError(const Lattice& lattice, const Points& x)
{
  double error = 0.0;
  for (int v = 0; v < x.rows(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      error = std::max({ error, -x(v, a), x(v, a) - 1.0 });
    }
    for (int chart : lattice.VertexCharts[static_cast<size_t>(v)])
    {
      const double plane = chart % 2 == 0 ? 0.0 : 1.0;
      error = std::max(error, std::fabs(x(v, chart / 2) - plane));
    }
  }
  return error;
}

} // namespace testing
} // namespace polycubehex
