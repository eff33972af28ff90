// SPDX-License-Identifier: BSD-3-Clause
// Charts of a (nearly) polycube-shaped boundary: labels 0..5 = +X, -X, +Y, -Y, +Z, -Z by the
// dominant axis of each face normal, connected components of equal labels, their clean-up, and
// the corner count of DESIGN.md §4.
#pragma once

#include "MeshTypes.h"

#include <vector>

namespace polycubehex
{

/// Label of a normal: 2 * axis + (component < 0), axis = the largest |component|.
int PolycubeLabelOfNormal(const Eigen::Vector3d& normal);

/// Labels of the triangles `faces` of the surface with positions `x`.
/// @param x      #V by 3 positions
/// @param faces  #F by 3 triangles oriented outwards
/// @return #F labels 0..5
std::vector<int> PolycubeFaceLabels(const Points& x, const Triangles& faces);

/// Charts: connected components of faces with the same label (through shared edges).
struct PolycubeCharts
{
  std::vector<int> FaceChart;    ///< #F chart id per face
  std::vector<int> ChartLabel;   ///< #C label per chart
  std::vector<double> ChartArea; ///< #C area per chart
  int Count() const { return static_cast<int>(this->ChartLabel.size()); }
};

/// @param faces      #F by 3 triangles
/// @param adjacency  #F by 3 neighbour across each edge (ComputeFaceAdjacency), -1 if none
/// @param labels     #F labels
/// @param x          #V by 3 positions, for the chart areas
PolycubeCharts ComputePolycubeCharts(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<int>& labels);

/// Clean-up settings.
struct PolycubeChartCleanup
{
  /// A chart whose area is below this fraction of the total is merged into a neighbour.
  double MinAreaFraction = 2e-4;
  /// A chart with fewer faces than this is merged into a neighbour.
  int MinFaceCount = 3;
  /// A small chart is merged only if its extent along the new label's axis (the distance its
  /// vertices will move when flattened) is below this length; a taller one is a real step.
  double MaxMergeExtent = 2e-3;
  /// Give a face the label that two of its three neighbours share: all three of its vertices
  /// then already touch that chart, so the face lies in its plane and the chart boundary loses a
  /// one-face tooth (which would otherwise become a degenerate face on the crease).
  bool RemoveTeeth = true;
  /// A chart with a boundary loop along which the neighbours' axes change fewer times than
  /// this cannot be a flat rectilinear polygon (an island inside one chart has 0 changes and
  /// collapses when flattened; a loop needs at least 4 corners), so it is merged into a
  /// neighbour whatever its size. 0 turns the rule off.
  int MinBoundaryTurns = 4;
  /// Bound on the merge passes.
  int MaxPasses = 50;
};

/// For each chart, the fewest changes of the neighbouring charts' axis along one of its
/// boundary loops (INT_MAX for a chart without boundary). A flat rectilinear chart has at least
/// 4 on every loop.
std::vector<int> ChartBoundaryTurns(const Triangles& faces,
  const Triangles& adjacency,
  const PolycubeCharts& charts);

/// Relabels small charts (when flat enough along the new axis), charts that touch a chart of
/// the opposite label along an edge (+X next to -X cannot be flattened) and charts with a
/// boundary loop of fewer than MinBoundaryTurns corners, with the label of a
/// neighbouring chart: the one along whose axis the chart is thinnest, ties broken by the longest
/// shared boundary; never a label opposite to a neighbour's when avoidable. Returns the number
/// of relabelled faces.
int CleanUpPolycubeCharts(const Points& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const PolycubeChartCleanup& settings,
  std::vector<int>& labels);

/// Vertices where three or more charts meet.
/// @param vertexCount  #V
/// @param faces        #F by 3
/// @param faceChart    #F chart per face
/// @param isCorner     if not null, #V flags on return
int CountPolycubeCorners(int vertexCount,
  const Triangles& faces,
  const std::vector<int>& faceChart,
  std::vector<bool>* isCorner = nullptr);

} // namespace polycubehex
