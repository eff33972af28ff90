// SPDX-License-Identifier: BSD-3-Clause
// Boundary doublets of an extracted hex mesh (not in the paper). Two hexes that share two faces
// share the edge between those faces with no other hex around it, so each fills half of the
// turn about that edge: both have a flat corner along it (their Jacobians there are the same
// three edge vectors in opposite orders, det and -det), and no placement of the vertices makes
// both positive. The extraction leaves such pairs at the boundary where the integer rounding
// left tets inverted (the last, flat hexes of rockerarm and fertility Uniform and of bunny).
// Removing one hex of the pair leaves a dent of one padding layer but lets the other become a
// proper hex: its corner at the fold vertex is then a boundary corner. Hexes overlapping others
// where the extraction folded are removed the same way when that makes the mesh valid.
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>

#include <vector>

namespace polycubehex
{

/// Pairs of hexes that share two or more faces, each as (hex, hex) with the smaller first.
Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> FindHexDoublets(const HexMesh& mesh);

/// Removes one hex of every doublet whose two hexes both have a boundary face (a dent, never a
/// cavity): the one with the smaller `quality` (the later one on a tie), and only when none of
/// its vertices would be left unused and the boundary stays a closed 2-manifold (else none is
/// removed). Returns the hexes removed; `removed` (if set) receives their indices in `mesh`
/// before the removal, ascending.
int RemoveBoundaryDoublets(HexMesh& mesh,
  const Eigen::VectorXd& quality,
  std::vector<int>* removed = nullptr);

/// Removes hexes that overlap others where the extraction folded (a quad used by three hexes, or
/// two hexes on the same side of their common quad; rockerarm Uniform, next to the tets the
/// rounding left inverted): greedily, worst `quality` first, each removal kept only when it
/// lowers the number of combinatorial defects (checkHexMeshValidity) and leaves no vertex
/// unused. Returns the hexes removed.
int RemoveOverlappingHexes(HexMesh& mesh, const Eigen::VectorXd& quality);

/// Removes hexes where the boundary pinches: an edge of four boundary quads (two hexes touching
/// along an edge only) or a vertex with two fans of boundary quads. The lattice of a rounding
/// that left tets inverted can have them (fertility closed form at 16,247 hexes), and a padding
/// layer over a pinched edge gives a quad of four hexes. Greedily, worst `quality` first among
/// the hexes at the pinches, each removal kept only when it lowers the number of combinatorial
/// defects and leaves no vertex unused; repeated while that mends more. Returns the hexes
/// removed; `removed` (if set) receives their indices in `mesh` before the removal, ascending.
int RemovePinchingHexes(HexMesh& mesh,
  const Eigen::VectorXd& quality,
  std::vector<int>* removed = nullptr);

} // namespace polycubehex
