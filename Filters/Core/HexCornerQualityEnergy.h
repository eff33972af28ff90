// SPDX-License-Identifier: BSD-3-Clause
// A smooth energy whose minimum over some vertices raises the scaled Jacobians of the hexes
// around them: the sum, over the nine Jacobians of each hex that HexScaledJacobian.h measures
// (eight corners and the centre), of -log chi(s), s that Jacobian's normalised determinant and
// chi(s) = (s + sqrt(eps^2 + s^2)) / 2 (the regularisation of Garanzha et al. 2021, so that an
// inverted corner costs a finite amount and can be pulled back). -log s is a barrier at s = 0 that
// is blind to the lengths of the edges: a hex's edges may differ in length (a padding hex is a
// third of a hex thick) as long as they meet at right angles, which is what the scaled Jacobian
// asks. A Jacobian with an edge of zero length has no direction to improve and is left out.
#pragma once

#include "MeshTypes.h"

#include <vector>

namespace polycubehex
{

/// Value of the energy over `hexes` of `mesh` (positions `x`, #V by 3) and, when `gradient` is
/// not null, its gradient with respect to every vertex (#V by 3, overwritten; zero for vertices
/// of no listed hex).
/// @param epsilon  the regularisation (> 0); the energy of a Jacobian is -log s to within
///                 eps^2 / (4 s^2) once s is well above it
double HexCornerQualityEnergy(const Points& x,
  const Hexes& cells,
  const std::vector<int>& hexes,
  double epsilon,
  Points* gradient = nullptr);

} // namespace polycubehex
