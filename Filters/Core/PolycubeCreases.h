// SPDX-License-Identifier: BSD-3-Clause
// Creases of a labelled polycube surface and their monotonicity. Two charts of different axes
// meet along a polycube edge, which runs along the third axis; the mesh path of that edge must
// move along the axis in one direction only. Where it goes back and forth ("turns back", the
// monotonicity of PolyCut, Livesu et al. 2013), flattening both charts folds the faces between
// the turning points onto the edge's line: they collapse, and the vertices around them stay off
// their planes or invert a tet in the rounding.
#pragma once

#include "MeshTypes.h"
#include "PolycubeCharts.h"

#include <vector>

namespace polycubehex
{

/// One crease: a maximal path of boundary edges shared by the same two charts.
struct PolycubeCrease
{
  int ChartA = -1;
  int ChartB = -1;
  int Axis = -1;             ///< the axis the crease runs along (neither chart's axis)
  std::vector<int> Vertices; ///< in order along the path; first == last for a closed loop
  double NetLength = 0.0;    ///< |change of the Axis coordinate| from the first to the last vertex
  /// (total variation of the Axis coordinate along the path - NetLength) / 2: how far the path
  /// runs back against its own direction; 0 for a monotone crease.
  double TurnBack = 0.0;
};

/// The creases of charts of different axes, measured in the positions `x` (typically the
/// deformed or the flattened shape). Charts of one axis (a +X chart next to a -X chart, which
/// the clean-up removes) do not make creases. A vertex where the two charts meet along more than
/// two edges ends the paths through it.
/// @param x          #V by 3 positions
/// @param faces      #F by 3 boundary triangles
/// @param adjacency  #F by 3 neighbour across each edge (-1 if none; on a cut mesh the cut's
///                   border, so that creases end there)
/// @param charts     the charts of `faces`
std::vector<PolycubeCrease> ComputePolycubeCreases(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const PolycubeCharts& charts);

/// Relabels where creases turn back: walking each open crease from its start towards its end
/// (the direction of its net change), a vertex behind the farthest point reached so far (by more
/// than `tolerance`) lies on a part that runs back. The faces of the crease's two charts around
/// such vertices all take the label of the chart that holds most of them, which removes the
/// thinner of the tooth and the pocket that the crease wraps around. Creases with TurnBack up to
/// `tolerance` are left alone. Returns the number of faces relabelled.
int ShaveTurnedBackCreases(const Points& x,
  const Triangles& faces,
  const PolycubeCharts& charts,
  const std::vector<PolycubeCrease>& creases,
  double tolerance,
  std::vector<int>& labels);

/// How much of its length a crease keeps along its axis: NetLength over the length of its path
/// in `rest` (the input). A polycube edge follows its axis, so a crease that runs across the
/// axis in the input is squashed onto a short edge, and the tets along it with it: rockerarm's
/// l1 polycube has one crease at 0.10 (7 edges, 7 % of the diagonal long) where every other is
/// far above, and its worst hexes, its Hausdorff distance and its vertices off their planes are
/// all there. 1 for a cube's edges; 0 for a closed loop or a path of zero rest length.
double CreaseStretch(const Points& rest, const PolycubeCrease& crease);

/// Whether `crease` is squashed: an open path at least `minRestLength` long in `rest` whose
/// stretch is below `maxStretch`. Its stretch goes to `stretch` when the path is long enough
/// (left as it is otherwise).
bool IsSquashedCrease(const Points& rest,
  const PolycubeCrease& crease,
  double maxStretch,
  double minRestLength,
  double* stretch = nullptr);

/// Creases at least `minRestLength` long in `rest` whose stretch is below `maxStretch`; the
/// smallest stretch of those long enough (1 if none) in `smallest`.
int CountSquashedCreases(const Points& rest,
  const std::vector<PolycubeCrease>& creases,
  double maxStretch,
  double minRestLength,
  double* smallest = nullptr);

/// Largest TurnBack over `creases` (0 if none), and how many exceed `tolerance`.
double MaxCreaseTurnBack(const std::vector<PolycubeCrease>& creases,
  double tolerance,
  int* countAbove = nullptr);

} // namespace polycubehex
