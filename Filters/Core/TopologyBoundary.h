// SPDX-License-Identifier: BSD-3-Clause
// The boundary surface of a tet mesh, its components and their genera; beta_1 of the solid by
// Alexander duality (Dey and Guha 1998): for a compact solid in R^3 with a closed 2-manifold
// boundary, beta_1 = sum of the genera of the boundary components, and
// beta_2 = #boundary components - #solid components.
#pragma once

#include "MeshTypes.h"
#include "Status.h"
#include "TopologyAdjacency.h"

#include <vector>

namespace polycubehex
{

struct BoundaryTopology
{
  /// The boundary faces as (tet, local face).
  std::vector<std::array<int, 2>> Faces;
  /// Per boundary face: its component (connected through boundary edges).
  std::vector<int> FaceComponent;
  /// Per boundary component: Euler characteristic V - E + F and genus (2 - chi) / 2.
  std::vector<int> ComponentEuler;
  std::vector<int> ComponentGenus;
  /// Connected components of the solid (tets joined through interior faces).
  int SolidComponentCount = 0;
  int Beta1 = 0; ///< sum of ComponentGenus
  int Beta2 = 0; ///< #boundary components - #solid components
};

/// Extracts the boundary and checks that it is a closed 2-manifold: every boundary edge in
/// exactly two boundary faces and the boundary faces around every boundary vertex forming a
/// single fan (one cycle). A failure names the offending edge or vertex. Also fails when a
/// component's Euler characteristic is odd or above 2 (not an orientable closed surface).
Status ComputeBoundaryTopology(const Tets& cells,
  const TetAdjacency& adjacency,
  BoundaryTopology& topology);

} // namespace polycubehex
