// SPDX-License-Identifier: BSD-3-Clause
// Smoothing of the rounded polycube map before the hexes are extracted (not in the paper).
//
// The hexes are the lattice's unit cubes mapped back to the input through the tets, so their
// shape is the inverse map's distortion at the scale of a hex. The deformation's map is far from
// smooth inside: its barrier lets tets shrink to a tenth of their volume, and the rounding's
// energy keeps the deformation's own Jacobians, so that neighbouring tets differ by a factor of
// 50 to 150 in condition number (kitten's closed form), and a unit cube spanning them comes back
// inverted even where every tet is positive. Here every coordinate that the rounding left free
// (x = FreeBasis y + constant: the chart planes and the cut relations stay exact) minimises the
// foldover-free energy of the map from the input to the polycube (FoldoverFreeEnergy.h), its
// Jacobians divided by the map's mean scale, weighted by the input tets' volumes. The boundary
// slides in its chart planes and along the polycube edges, corners stay. The same energy
// untangles tets the rounding left inverted, where the planes allow it. The result is kept only
// when it has no more inverted tets than the input (by default: none).
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <Eigen/SparseCore>

namespace polycubehex
{

/// Settings of smoothPolycubeMap.
struct PolycubeMapSmoothingParameters
{
  /// Rounds at most, each one L-BFGS solve for one eps of the energy (default 6, >= 0; 0 turns
  /// the smoothing off). A map without inverted tets needs one or two.
  int MaxRounds = 6;
  /// L-BFGS iterations per round at most (default 200, >= 1).
  int IterationsPerRound = 200;
  /// Share of the volume term, in [0, 1) (default 0.1), as in the hex untangling.
  double VolumeWeight = 0.1;
  /// The rounds stop once no tet is inverted and a round lowers the energy by less than this
  /// fraction (default 1e-3).
  double Tolerance = 1e-3;
  /// Keep the result only when it leaves no tet inverted (default on). Where the planes force
  /// inverted tets, the smoothed map spreads them: kitten's l1 polycube kept 43 of 99 and its
  /// hexes' Hausdorff distance went from 11.8 to 33.7, rockerarm's closed form kept 27 of 42
  /// and its smoothed minimum scaled Jacobian fell from 0.325 to 0.198.
  bool RequireUntangled = true;
};

/// What smoothPolycubeMap did.
struct PolycubeMapSmoothingResult
{
  double EnergyBefore = 0.0; ///< mean energy per unit volume (1 for a similarity)
  double EnergyAfter = 0.0;
  int InvertedTetsBefore = 0;
  int InvertedTetsAfter = 0;
  int Rounds = 0;
  int Iterations = 0;
  bool Kept = false; ///< false when the result was worse than the input and discarded
  /// True when, under RequireUntangled, a round left more than half of the inverted tets it
  /// started from and the rounds stopped there (the result is then discarded).
  bool GaveUp = false;
};

/// Smooths the map from `rest` to `positions` over the free coordinates, in place.
/// @param rest        #V by 3 input positions, positive tets
/// @param cells       #T by 4 tets
/// @param freeBasis   #3V by #F: coordinate i (row-major, 3v + a) moves with free variable f by
///                    freeBasis(i, f); rows without an entry stay where they are
/// @param positions   #V by 3 polycube positions (lattice units), consistent with freeBasis
/// @return Failure on mismatched sizes or when aborted (positions then unchanged).
Status smoothPolycubeMap(const Points& rest,
  const Tets& cells,
  const Eigen::SparseMatrix<double>& freeBasis,
  const PolycubeMapSmoothingParameters& params,
  Points& positions,
  PolycubeMapSmoothingResult& result,
  const Progress& progress = {});

} // namespace polycubehex
