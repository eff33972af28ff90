// SPDX-License-Identifier: BSD-3-Clause
// The seams of a closed-form polycube: where the cut mesh M_c (port 0 of the deformation, points
// of cut faces duplicated) was opened, and the transition between the two sides' polycube
// frames, u_plus = Pi_c u_minus + t_c (Fang et al. 2016, eq. 8). Hex extraction needs them twice:
// the integer rounding keeps every copy pair related with t_c integer, and the extraction walks
// from one side's lattice frame into the other's, so that the hex mesh is seamless (§4.3).
//
// The seams are found from the geometry alone: a cut face is a boundary face of M_c without a
// polycube label, and its partner is the other such face on the same three input points. Each
// pair is assigned the cut whose transition maps one side's polycube positions onto the other's.
// Nothing depends on per-tet cut arrays, which tets split by the deformation carry over only
// approximately.
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace polycubehex
{

/// An affine map between two lattice frames: u_to = Rotation u_from + Translation.
struct LatticeTransform
{
  Eigen::Matrix3i Rotation = Eigen::Matrix3i::Identity();
  Eigen::Vector3d Translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d Apply(const Eigen::Vector3d& u) const
  {
    return this->Rotation.cast<double>() * u + this->Translation;
  }
  /// The map back: u_from = R^T (u_to - t).
  LatticeTransform Inverse() const
  {
    LatticeTransform inverse;
    inverse.Rotation = this->Rotation.transpose();
    inverse.Translation = -(inverse.Rotation.cast<double>() * this->Translation);
    return inverse;
  }
  /// `this` after `first`: u -> this(first(u)).
  LatticeTransform After(const LatticeTransform& first) const
  {
    LatticeTransform composed;
    composed.Rotation = this->Rotation * first.Rotation;
    composed.Translation = this->Rotation.cast<double>() * first.Translation + this->Translation;
    return composed;
  }
};

/// One vertex pair across a cut: u_Plus = Pi_Cut u_Minus + t_Cut.
struct SeamCopy
{
  int Minus = -1;
  int Plus = -1;
  int Cut = -1;
};

struct PolycubeSeams
{
  /// #T by 4: for local face k of tet t on a cut, the tet across the cut, else -1.
  Tets Neighbor;
  /// #T by 4: the cut of local face k, or -1.
  Tets Cut;
  /// #T by 4: -1 when tet t is on the minus side of the cut at face k, +1 on the plus side, 0.
  Tets Side;
  std::vector<Eigen::Matrix3i> Rotations;    ///< Pi_c per cut
  std::vector<Eigen::Vector3d> Translations; ///< t_c per cut, in the units of the positions
  std::vector<SeamCopy> Copies;              ///< each copy pair once

  bool Empty() const { return this->Copies.empty(); }
  int CutCount() const { return static_cast<int>(this->Rotations.size()); }

  /// The map from the frame of tet t to the frame of Neighbor(t, k) (k a cut face of t).
  LatticeTransform Across(int t, int k) const
  {
    LatticeTransform minusToPlus;
    const int cut = this->Cut(t, k);
    minusToPlus.Rotation = this->Rotations[static_cast<size_t>(cut)];
    minusToPlus.Translation = this->Translations[static_cast<size_t>(cut)];
    return this->Side(t, k) < 0 ? minusToPlus : minusToPlus.Inverse();
  }
};

/// Finds the seams of a cut polycube.
/// @param original      #V by 3 input positions (the copies of one point are equal)
/// @param polycube      #V by 3 polycube positions
/// @param cells         #T by 4 tets
/// @param faceLabels    #T by 4 PolycubeLabels (-1 on cut faces)
/// @param rotations     Pi_c per cut (CutTransitions)
/// @param translations  t_c per cut in the units of `polycube` (CutTranslations)
/// @return Failure when an unlabelled boundary face has no partner on the same input points, or
///         when no cut's transition maps a pair's polycube positions onto each other (to 1e-6 of
///         the polycube's size). With no cuts, the seams are empty and every face is labelled.
Status FindPolycubeSeams(const Points& original,
  const Points& polycube,
  const Tets& cells,
  const Tets& faceLabels,
  const std::vector<Eigen::Matrix3i>& rotations,
  const std::vector<Eigen::Vector3d>& translations,
  PolycubeSeams& seams);

} // namespace polycubehex
