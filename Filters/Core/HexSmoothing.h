// SPDX-License-Identifier: BSD-3-Clause
// Quality-guarded smoothing of an extracted hex mesh (not in the paper; the paper's meshes are
// the raw extraction). Each vertex moves towards the mean of its neighbours (Laplacian) when that
// raises the mean scaled Jacobian of its hexes without going below the mesh's minimum; then,
// around the worst hexes, a pattern search maximises the smallest scaled Jacobian of its hexes.
// The mesh's minimum scaled Jacobian never decreases. Boundary vertices stay
// on the input surface: a vertex on one chart slides on that chart's triangles, a vertex on two
// charts slides along their common feature curve, a vertex on three or more charts is fixed.
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <vector>

namespace polycubehex
{

/// The surface boundary vertices stay on: the input's boundary triangles with their charts.
struct HexSmoothingSurface
{
  Points Vertices;            ///< #S by 3 positions (same space as the hex mesh)
  Triangles Faces;            ///< #F by 3 boundary triangles
  std::vector<int> FaceChart; ///< #F chart of each triangle
};

/// The boundary triangles of a tet mesh with their charts, for smoothHexMesh.
/// @param vertices   #V by 3 positions of the surface (the input's)
/// @param cells      #T by 4 tets
/// @param faceChart  #T by 4 chart of local face k (vtkTetra order) or -1 (ChartPlanes::FaceChart)
/// @param chartIds   #C: the number each chart gets in the surface (its glued chart across the
///                   seams of a cut polycube, GlueChartsAcrossSeams), or empty for the charts'
///                   own numbers
/// @param identity   #V: the vertex each one stands for (the copies across a seam as one,
///                   SeamVertexIdentity, so that feature curves continue across it), or empty
HexSmoothingSurface MakeChartSurface(const Points& vertices,
  const Tets& cells,
  const Tets& faceChart,
  const std::vector<int>& chartIds = {},
  const std::vector<int>& identity = {});

/// Settings of smoothHexMesh.
struct HexSmoothingParameters
{
  /// Gauss-Seidel sweeps over all vertices (default 20, >= 0).
  int Iterations = 20;
  /// Smoothing stops after a sweep that raises neither the minimum nor the mean scaled
  /// Jacobian by this much (default 1e-5).
  double Tolerance = 1e-5;
  /// Vertices whose worst hex is within this of the mesh's minimum scaled Jacobian also get a
  /// pattern search that maximises it (default 0.1, >= 0; a negative value turns it off).
  double WorstBand = 0.1;
  /// Every vertex with a hex below this scaled Jacobian gets the pattern search too, whatever
  /// the mesh's minimum (default 0.1): inverted hexes scattered at different depths are all
  /// worked on in each sweep, not only the worst few.
  double UntangleBelow = 0.1;
};

/// Quality before and after.
struct HexSmoothingResult
{
  double MinBefore = 0.0;
  double MeanBefore = 0.0;
  double MinAfter = 0.0;
  double MeanAfter = 0.0;
  int Sweeps = 0;
};

/// Smooths `mesh` in place.
/// @param mesh          #V by 3, #H by 8 hexes in VTK order
/// @param vertexCharts  #V: charts each vertex lies on (empty for interior vertices)
/// @param surface       the input's boundary triangles, each with the chart it belongs to
/// @return Failure when the sizes disagree or the caller aborted.
Status smoothHexMesh(HexMesh& mesh,
  const std::vector<std::vector<int>>& vertexCharts,
  const HexSmoothingSurface& surface,
  const HexSmoothingParameters& params,
  HexSmoothingResult& result,
  const Progress& progress = {});

} // namespace polycubehex
