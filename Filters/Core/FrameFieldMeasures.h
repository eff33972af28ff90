// SPDX-License-Identifier: BSD-3-Clause
// The measures of a frame field that every test, benchmark and report shares (DESIGN.md
// section 4): singular edges from the best-aligning cube rotations around each interior edge, and
// the area-weighted boundary alignment error.
#pragma once

#include "CubeSymmetry.h"
#include "MeshTypes.h"
#include "TetGeometry.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace polycubehex
{

/// An interior edge of the mesh around which the frames do not close up.
struct SingularEdge
{
  std::array<int, 2> Vertices{ { -1, -1 } }; ///< (smaller id, larger id)
  /// The product, once around the edge, of the best-aligning cube rotation across each face
  /// (an index for CubeRotation; never 0 here).
  int Holonomy = 0;
  CubeRotationClass Type = CubeRotationClass::Identity; ///< the class of the holonomy
  bool Interior = false;                                ///< neither vertex lies on the boundary
  /// Distance of the edge midpoint to the boundary surface, relative to the bounding-box diagonal.
  double Depth = 0.0;
};

/// Finds the singular edges: for each interior edge (its tets close up into a ring), composes
/// across each face of the ring the cube rotation Pi minimising ||Pi R_i - R_j|| (not any
/// matching or cut transition), and keeps the edge when the product is not the identity. Edges
/// come out in the order of TetTopology::Edges.
/// @param mesh      #V by 3 vertices, #T by 4 tets
/// @param topology  ComputeTetTopology(mesh)
/// @param frames    #T frames (rows = axes), need not be orthonormal
std::vector<SingularEdge> FindSingularEdges(const TetMesh& mesh,
  const TetTopology& topology,
  const std::vector<Eigen::Matrix3d>& frames);

/// The area-weighted mean, over boundary faces, of the angle in degrees between the face's normal
/// and the nearest axis (row) of its tet's frame. 0 for a perfectly aligned field; at most
/// acos(1/sqrt(3)) = 54.7 degrees.
double ComputeBoundaryAlignmentError(const TetMesh& mesh,
  const TetTopology& topology,
  const std::vector<Eigen::Matrix3d>& frames);

} // namespace polycubehex
