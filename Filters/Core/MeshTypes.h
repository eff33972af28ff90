// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products everywhere; without it they are left undefined

namespace polycubehex
{

/// Row-major so that a block of rows is contiguous and maps onto VTK arrays without a copy.
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Quads = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;
using Tets = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;
using Hexes = Eigen::Matrix<int, Eigen::Dynamic, 8, Eigen::RowMajor>;

/// A closed (or not yet checked) triangle surface.
struct SurfaceMesh
{
  Points Vertices;      ///< #V by 3 vertex positions
  Triangles Faces;      ///< #F by 3 vertex indices, counter-clockwise seen from outside
};

/// A tetrahedral mesh in VTK's node order; positively oriented tets have positive volume.
struct TetMesh
{
  Points Vertices; ///< #V by 3 vertex positions
  Tets Cells;      ///< #T by 4 vertex indices
};

/// A hexahedral mesh in VTK's node order.
struct HexMesh
{
  Points Vertices; ///< #V by 3 vertex positions
  Hexes Cells;     ///< #H by 8 vertex indices
};

} // namespace polycubehex
