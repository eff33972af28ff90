// SPDX-License-Identifier: BSD-3-Clause
// The matching of Fang et al. 2016, §3.2: frames are defined up to the 24 cube symmetries; this
// picks one representative per tet so that neighbours agree everywhere except across cuts.
// Internal to ComputeFrameField (FrameField.h).
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>

#include <vector>

namespace polycubehex
{

/// Builds a minimum spanning forest of the dual graph of the cut mesh (tets joined through
/// interior faces that are not cut faces), weighted by the alignment error
/// min_Pi ||Pi R_i - R_j||^2 of the face, then walks it from a root per component (its lowest
/// tet index, whose frame is kept) and replaces each frame R by Pi R, Pi the cube rotation that
/// best matches its tree parent. Deterministic: ties are broken by face order.
/// @param neighbors  #T by 4: the tet across local face k, -1 on the boundary
/// @param faceCut    #T by 4: the cut id of local face k, -1 if none (may have 0 rows: no cuts)
/// @param frames     #T rotations (rows = axes), re-expressed in place
/// @return the number of connected components of the cut mesh
int MatchFramesAlongSpanningTree(const Tets& neighbors,
  const Tets& faceCut,
  std::vector<Eigen::Matrix3d>& frames);

} // namespace polycubehex
