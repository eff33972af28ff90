// SPDX-License-Identifier: BSD-3-Clause
// Quality-guarded smoothing of an extracted hex mesh (not in the paper; the paper's meshes are
// the raw extraction). Each vertex moves towards the mean of its neighbours (Laplacian) when that
// raises the mean scaled Jacobian of its hexes without going below the mesh's minimum; a few more
// sweeps also take short steps along each vertex's directions that raise that mean further;
// around the worst hexes, a pattern search maximises the smallest scaled Jacobian of its hexes;
// last, a polish lifts the worst hexes by gradient steps on a soft minimum of their corners.
// The mesh's minimum scaled Jacobian never decreases. Boundary vertices stay on the input
// surface: a vertex on one chart slides on that chart's triangles, a vertex on two
// charts slides along their common feature curve, a vertex on three or more charts is fixed
// (HexSurfaceProjection.h).
#pragma once

#include "HexSurfaceProjection.h"
#include "MeshTypes.h"
#include "Status.h"

#include <vector>

namespace polycubehex
{

/// Settings of smoothHexMesh.
struct HexSmoothingParameters
{
  /// Gauss-Seidel sweeps over all vertices (default 20, >= 0).
  int Iterations = 20;
  /// Smoothing stops after a sweep that raises neither the minimum nor the mean scaled
  /// Jacobian by this much (default 1e-5).
  double Tolerance = 1e-5;
  /// Sweeps after the Laplacian ones (and in those between the polishes) in which every vertex,
  /// after its Laplacian step, also tries a step each way along each of its directions, kept
  /// when it raises the mean scaled Jacobian of its hexes under the Laplacian's rule. The
  /// Laplacian aims at evenly spaced vertices, not at square hexes: on the closed-form
  /// polycubes at the paper's counts three such sweeps raised the mean by about 0.01
  /// (rockerarm 0.927 -> 0.940) for about 2 more seconds per 17k hexes. Default 3; 0 turns the
  /// steps off everywhere.
  int MeanSearchSweeps = 3;
  /// Length of those steps, a fraction of the vertex's mean edge length (default 0.05; 0 turns
  /// them off).
  double MeanSearchStep = 0.05;
  /// Vertices whose hexes' mean scaled Jacobian is already at least this take no such steps
  /// (default 0.98): they gain little (rockerarm closed form, mean 0.9399 -> 0.9393) and skipping
  /// them saves a sixth of the smoothing time (2.6 -> 2.2 s).
  double MeanSearchBelow = 0.98;
  /// Vertices whose worst hex is within this of the mesh's minimum scaled Jacobian also get a
  /// pattern search that maximises it (default 0.1, >= 0; a negative value turns it off).
  double WorstBand = 0.1;
  /// Every vertex with a hex below this scaled Jacobian gets the pattern search too, whatever
  /// the mesh's minimum (default 0.1): inverted hexes scattered at different depths are all
  /// worked on in each sweep, not only the worst few.
  double UntangleBelow = 0.1;
  /// A boundary vertex on a polycube edge or corner moves on the surface across its charts
  /// where the input's normals about it vary by at most this (degrees, default 20; 0 holds
  /// every such vertex on its curve or in place; HexSurfaceProjection).
  double SoftFeatureAngle = DefaultSoftFeatureAngle;

  // The polish of the worst hexes, after the sweeps, where they stall: the sweeps move one
  // vertex at a time along fixed directions, and stop where two hexes around it are tied for
  // its worst. The polish climbs a soft minimum of the nine corner values of every hex around
  // the vertices of the worst hexes (smooth across such ties), each vertex alone, then all of
  // them together; a few sweeps then take back the mean, and the polish runs once more.
  /// Passes at most, each over the vertices of the hexes within PolishBand of the minimum
  /// (default 30; 0 turns the polish off). A pass that lifts the minimum by less than 1e-5 ends it.
  int PolishPasses = 30;
  /// Hexes this close to the minimum scaled Jacobian are polished (default 0.05).
  double PolishBand = 0.05;
  /// Sharpness of the soft minimum, min - log(sum exp(-s (value - min))) / s (default 40).
  double PolishSharpness = 40.0;
  /// Gradient steps of each vertex alone per pass (default 10).
  int PolishAscentSteps = 10;
  /// Gradient steps of all the pass's vertices together (default 20).
  int PolishJointSteps = 20;
  /// Sweeps between the two polishes (default 5).
  int SweepsAfterPolish = 5;
  /// Corners and curve vertices of the hexes within PolishReleaseBand of the minimum are
  /// released onto the surface before each polish pass where the input's normals about them
  /// vary by at most this many degrees (HexSurfaceProjection::SmoothAt); the polish can then
  /// move them; 0 keeps them. Larger than the projection's SoftFeatureAngle, which releases
  /// such vertices everywhere, it acts only where the mesh is worst. The default, 40 degrees,
  /// keeps the sharp edges and corners of a box (normals 45 and 54.7 degrees from their mean).
  double PolishReleaseAngle = 40.0;
  /// See PolishReleaseAngle (default 0.01).
  double PolishReleaseBand = 0.01;
  /// Those vertices are also released, whatever the spread of the normals about them, where no
  /// edge of the input within a hex edge is sharper than this many degrees (the normals of its
  /// two triangles further apart; HexSurfaceProjection::FreeOfSharpEdgesAt): a tight curve of a
  /// coarse surface is not a feature, while a box's edge (90 degrees) stays. Default 60; 0
  /// turns this off.
  double PolishSharpEdgeAngle = 60.0;
};

/// Quality before and after.
struct HexSmoothingResult
{
  double MinBefore = 0.0;
  double MeanBefore = 0.0;
  double MinAfter = 0.0;
  double MeanAfter = 0.0;
  int Sweeps = 0;               ///< sweeps run, for the mean and between the polishes included
  double MinBeforePolish = 0.0; ///< minimum scaled Jacobian after the first sweeps
  int PolishPasses = 0;         ///< polish passes run, every polish
  int PolishReleased = 0;       ///< corners and curve vertices the polish released
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

/// The same with the boundary vertices' kinds and projections given (for instance those the
/// untangling left, with the vertices it released; params.SoftFeatureAngle is then unused).
/// The polish may release more (PolishReleaseAngle).
Status smoothHexMesh(HexMesh& mesh,
  HexSurfaceProjection& projection,
  const HexSmoothingParameters& params,
  HexSmoothingResult& result,
  const Progress& progress = {});

} // namespace polycubehex
