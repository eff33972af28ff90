// SPDX-License-Identifier: BSD-3-Clause
// Quality tetrahedral mesh of the solid bounded by a closed triangle surface, with TetGen.
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <string>

namespace polycubehex
{

/// Settings of Tetrahedralize, each one a TetGen switch.
struct TetrahedralizeParameters
{
  /// Upper bound on a tet's circumradius divided by its shortest edge (TetGen -q). Default 2.0,
  /// valid range [1.0, 10]; smaller gives rounder and more tets (TetGen may not stop below ~1.1).
  double RadiusEdgeRatio = 2.0;
  /// Upper bound on a tet's volume in the input's units (TetGen -a); 0 = no bound. TetGen treats
  /// it approximately (tets up to ~10% above it), and with PreserveBoundary tets next to large
  /// boundary triangles may exceed it further.
  double MaxTetVolume = 0.0;
  /// Approximate number of tets wanted; 0 = no target. Converted to a volume bound from the
  /// enclosed volume; when MaxTetVolume is also set, the smaller of the two bounds is used. The
  /// surface's own resolution sets a minimum count that no target goes below.
  int TargetTetCount = 0;
  /// Keep the input triangles as the boundary faces of the tets, with no Steiner point on the
  /// boundary (TetGen -Y). Default off: TetGen may split boundary triangles to meet the quality.
  bool PreserveBoundary = false;
};

/// Tetrahedralizes the solid bounded by `surface` with TetGen (-p, -q, -a, -Y, quiet -Q).
/// The surface is first checked with CheckClosedSurface and refused, with that check's message,
/// unless it is closed, 2-manifold and consistently oriented. Nested components bound voids
/// (odd nesting depth): each gets a hole point, verified by winding number, so that the void
/// stays empty; solid islands inside voids are meshed. Self-intersections are reported by TetGen.
/// TetGen runs in a forked child process (TetGen 1.5 crashes its caller when it fails), after a
/// TetGen -d pass that reports self-intersections by triangle.
/// Without TetGen in the build (CMake option POLYCUBEHEX_USE_TETGEN off) it always fails.
/// @param surface       #V by 3 vertices, #F by 3 triangles; vertices in no triangle are ignored
/// @param out           the tets: vertices start with the input's used vertices in input order
///                      (so, when every vertex is used, input vertex i is output vertex i),
///                      followed by TetGen's Steiner points; #T by 4 cells in VTK's node order
///                      with positive volume
/// @param switchesUsed  the TetGen command-line switches that were run, e.g. "pq2Q"
/// @param progress      called with the fraction done; returning false aborts (between stages:
///                      TetGen itself cannot be interrupted)
Status Tetrahedralize(const SurfaceMesh& surface,
  const TetrahedralizeParameters& params,
  TetMesh& out,
  std::string& switchesUsed,
  const Progress& progress = {});

} // namespace polycubehex
