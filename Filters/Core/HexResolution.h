// SPDX-License-Identifier: BSD-3-Clause
// The resolution of hex extraction: how many lattice units (hex edges) one polycube unit spans.
#pragma once

namespace polycubehex
{

/// The lattice scale s (lattice coordinates = s * polycube coordinates) for a requested size.
/// The polycube scaled by s holds about s^3 V unit cubes; a padding layer adds one hex per
/// boundary quad, about s^2 A more, so with padding s solves s^3 V + s^2 A = N.
/// @param polycubeVolume    volume V of the polycube, in its own units (> 0)
/// @param polycubeArea      boundary area A of the polycube
/// @param inputVolume       volume of the input tet mesh, in input units (> 0)
/// @param targetHexCount    hexes wanted N, padding included; used when targetEdgeLength <= 0
/// @param targetEdgeLength  hex edge wanted, in input units: s^3 V = input volume / edge^3;
///                          takes precedence when > 0
/// @param padding           whether a padding layer will be added
/// @return s > 0, or 0 when the volumes or both targets are not positive
double ComputeLatticeScale(double polycubeVolume,
  double polycubeArea,
  double inputVolume,
  int targetHexCount,
  double targetEdgeLength,
  bool padding);

} // namespace polycubehex
