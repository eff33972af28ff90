// SPDX-License-Identifier: BSD-3-Clause
// All-hex mesh extraction from a polycube-deformed tet mesh (Fang et al. 2016, §4.3): scale to
// the requested resolution, round every chart plane to an integer (IntegerRounding.h), extract
// the unit cubes of the lattice per tet and map them back (HexLatticeExtraction.h), then
// optionally add a padding layer (HexPadding.h) and smooth (HexSmoothing.h).
//
// The cut transition u_plus = Pi u_minus + t of a closed-form polycube enters in three places:
// the rounding (t as integer variables, plus-side coordinates eliminated), the extraction (points
// and cube centres on a cut face found from both sides are united, and the walk from a cube's
// centre to its corners applies the transition on crossing a cut face; HexLatticeExtraction.h),
// and the padding and smoothing (offsets per vertex frame seen from each hex through a rotation,
// charts glued across the seams; HexLatticePadding.h, GlueChartsAcrossSeams).
#pragma once

#include "HexSurfaceProjection.h"
#include "MeshTypes.h"
#include "Status.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace polycubehex
{

/// A polycube-deformed tet mesh: port 0 of the deformation (shared/DESIGN.md section 2).
struct PolycubeTetMesh
{
  Points OriginalVertices; ///< #V by 3 input positions (`OriginalPoints`), positive tets
  Points PolycubeVertices; ///< #V by 3 polycube positions, positive tets, charts flat
  Tets Cells;              ///< #T by 4 tets in VTK's node order
  /// #T by 4 `PolycubeLabels`: label 0..5 (+X, -X, +Y, -Y, +Z, -Z) of local face k (vtkTetra
  /// face order) when it lies on the boundary, -1 otherwise.
  Tets FaceLabels;
  /// The cuts of a closed-form polycube (both empty for a uniform one): Pi_c per cut
  /// (CutTransitions) and t_c in the units of PolycubeVertices (CutTranslations). The cut faces
  /// are the unlabelled boundary faces (PolycubeSeams.h).
  std::vector<Eigen::Matrix3i> CutRotations;
  std::vector<Eigen::Vector3d> CutTranslations;
};

/// Settings of extractHexMesh; the names match the filter's properties.
struct HexExtractionParameters
{
  /// Hexes wanted, padding layer included (default 5000, >= 1). Used when TargetEdgeLength <= 0.
  int TargetHexCount = 5000;
  /// Hex edge length wanted, in input units (default 0 = use TargetHexCount). The polycube is
  /// scaled so that its volume in unit cubes is the input's volume over the edge cubed.
  double TargetEdgeLength = 0.0;
  /// Insert one layer of hexes under the boundary (default on).
  bool Padding = true;
  /// Thickness of the padding layer before smoothing, in hex edges (default 1/3, in (0, 0.5)):
  /// a part one hex thick becomes three equal layers (1/2 would merge the copies of its sides).
  double PaddingThickness = 1.0 / 3.0;
  /// Without Smoothing: place each inner copy of the padding layer, in the input's space,
  /// between its mapped position and its boundary vertex pushed along the surface normal, where
  /// its hexes are best, then move the copies together to raise their hexes' scaled Jacobians
  /// (HexPaddingPlacement.h; default on). With Smoothing the inner copies are
  /// optimised by the untangling and the sweeps, from their mapped positions (measured better).
  bool PaddingPlacement = true;
  /// Quality-guarded Laplacian smoothing after extraction (default on; the paper has none).
  bool Smoothing = true;
  /// Smoothing sweeps (default 20, >= 0).
  int SmoothingIterations = 20;
  /// With Smoothing: before the local sweeps, untangle and optimise all vertex positions at
  /// once (HexUntangling.h; default on). Kept only where it makes the mesh no worse.
  bool Untangling = true;
  /// With Smoothing: remove hexes no positions can make valid (HexDoublets.h; default on): one
  /// of every boundary doublet (two hexes sharing two faces) and those overlapping others where
  /// the extraction folded. Each leaves a dent in the boundary (rockerarm Uniform: Hausdorff
  /// distance about 9 to 18.5 for a valid mesh).
  bool RemoveDoublets = true;
  /// With Smoothing: after the sweeps, polish the worst hexes by gradient steps on a soft
  /// minimum of their corners' scaled Jacobians (HexSmoothing.h; default on). The minimum
  /// never decreases.
  bool Polish = true;
  /// With Polish: corners and curve vertices of the hexes nearest the minimum may leave their
  /// place where the input's normals about them vary by at most this many degrees
  /// (HexSmoothingParameters::PolishReleaseAngle; default 40, which keeps a box's sharp edges
  /// and corners; 0: they all stay).
  double PolishReleaseAngle = 40.0;
  /// The polish also releases those corners and curve vertices where no input edge within a hex
  /// edge is sharper than this (HexSmoothingParameters::PolishSharpEdgeAngle; default 60; 0
  /// turns it off).
  double PolishSharpEdgeAngle = 60.0;
  /// With Smoothing: sweeps in which each vertex also takes steps that raise the mean scaled
  /// Jacobian of its hexes (HexSmoothingParameters::MeanSearchSweeps; default 3; 0 turns them
  /// off).
  int MeanSearchSweeps = 3;
  /// With Smoothing and Untangling: 2 (the default) forks the untangling where the count of
  /// inverted hexes first has set no new low for two main rounds
  /// (HexUntanglingParameters::ForkStallRounds): the second path ends its main rounds there,
  /// both are smoothed, side by side on two threads, and the better mesh is kept (fewer
  /// inverted hexes, then the larger minimum where they differ by more than PathMinimumMargin,
  /// else the larger mean), so its minimum is never more than the margin below that of 1, which
  /// untangles and smooths once. An untangling that never stalls never forks.
  int UntanglingPaths = 2;
  /// With two paths: minima closer than this (default 0.01) count as a tie, broken by the mean
  /// (BetterHexQuality). Measured with 0 (the larger minimum always wins): torus l1 at 10k hexes
  /// kept path 2 at 0.768 / 0.949 over path 1 at 0.767 / 0.957.
  double PathMinimumMargin = 0.01;
  /// With Smoothing: a boundary vertex on a polycube edge or corner may leave it and move on
  /// the surface across its charts where the input's normals about it vary by at most this
  /// (degrees, default 20, >= 0; 0 holds every such vertex on its curve or in place).
  double SoftFeatureAngle = DefaultSoftFeatureAngle;
  /// Integers tried per chart plane in the greedy rounding (default 4, >= 1).
  int RoundingCandidates = 4;
  /// Smallest tet volume ratio (rounded over original polycube) the rounding accepts (default
  /// 1e-4, in (0, 1)).
  double MinimumVolumeRatio = 1e-4;
  /// Scales tried when rounding fails, 1 to 7 (default 5): the target scale, then +-1 %, +-2 %
  /// (+-3 % for 6 and 7), so that the hex count stays within 10 % of the target. Where the
  /// planes fall between integers decides whether greedy rounding can keep every tet positive
  /// (1 % of a 30-unit model moves a plane by 0.3). A best effort because the polycube's
  /// charts cannot all be flat (IntegerRoundingResult::UnflattenableCharts) ends the attempts:
  /// that does not depend on the scale. Each scale gets the fast path only; when none is clean,
  /// the target scale is rounded once more with the slow fallbacks (IntegerRounding.h).
  int RoundingAttempts = 5;
  /// With Smoothing: when the smoothed mesh's minimum scaled Jacobian is below
  /// ScaleRetryBelow, the whole extraction runs again at a lattice scale 1 % larger, then (2)
  /// 1 % smaller, until one reaches it, and the best mesh is kept (BetterHexQuality with
  /// PathMinimumMargin). Where the lattice falls on the polycube's folds decides whether the
  /// untangling can lift every hex: rockerarm l1 at 23,617 / 23,762 / 24,272 / 24,676 hexes left
  /// 0 / 3 / 5 / 0 inverted, and its smoothed minimum was 0.594 / 0.207 / 0.208 / 0.461
  /// (Hausdorff 8.1 / 18.5 / 19.6 / 10.2). Each retry costs one more extraction. Default 2,
  /// 0..2; 0 turns the retries off.
  int ScaleRetries = 2;
  /// The minimum scaled Jacobian below which ScaleRetries retries (default 0.3, the floor the
  /// benchmark asks of every smoothed mesh).
  double ScaleRetryBelow = 0.3;
  /// Smooth the rounded polycube map over its free coordinates before the extraction, chart
  /// planes and cut relations held (PolycubeMapSmoothing.h; default off). It is kept only when
  /// it leaves no tet inverted. Measured with the hex smoothing on, it raised the minimum scaled
  /// Jacobian of bunny (0.275 -> 0.382 l1, 0.144 -> 0.325 closed form) and fandisk (0.204 ->
  /// 0.296, 0.289 -> 0.333), lowered kitten's closed form (0.562/0.947 -> 0.556/0.941), and
  /// on rockerarm, elephant and kitten l1, where the planes force inverted tets, it gives up
  /// after 1-7 s of work; hence off.
  bool MapSmoothing = false;
};

/// The hex mesh and the measures of shared/DESIGN.md section 4 that the core can compute.
struct HexExtractionResult
{
  HexMesh Mesh;                        ///< in the input's units and position
  Eigen::VectorXd ScaledJacobian;      ///< #H
  Quads BoundaryQuads;                 ///< #B by 4, counter-clockwise seen from outside
  std::vector<int> BoundaryQuadLabels; ///< #B `PolycubeLabel` 0..5 of each boundary quad
  Points LatticeVertices;              ///< #V by 3 lattice coordinates of each hex vertex
  Points RoundedPolycube;              ///< #V_tet by 3 tet vertices in lattice units, rounded

  int HexCount = 0;
  int PaddingHexCount = 0;
  /// Padding copies placed by the fallback rule (mean of hex centres) because their lattice
  /// position could not be located in the tets (0 normally).
  int UnmappedPaddingVertexCount = 0;
  /// Inner copies PaddingPlacement moved off their mapped position, and the padding hexes'
  /// mean scaled Jacobian before and after it.
  int PlacedPaddingVertexCount = 0;
  /// Of those, the copies the joint optimisation after the search moved and kept there.
  int OptimizedPaddingVertexCount = 0;
  double PaddingScaledJacobianMeanBeforePlacement = 0.0;
  double PaddingScaledJacobianMean = 0.0;
  double ScaledJacobianMin = 0.0;
  double ScaledJacobianMean = 0.0;
  int InvertedHexCount = 0; ///< hexes with scaled Jacobian <= 0
  int IrregularBoundaryVertexCount = 0;

  double LatticeScale = 0.0; ///< lattice units per polycube unit
  /// The lattice scale the targets ask for (LatticeScale differs after a rounding or a scale
  /// retry), and how many extractions ScaleRetries ran again.
  double TargetLatticeScale = 0.0;
  int ScaleRetryCount = 0;
  int ChartCount = 0;
  int PlaneCount = 0;
  int RoundingFallbackCount = 0; ///< planes not rounded to their nearest integer
  int RoundingAttempts = 0;      ///< roundings tried (1 when the target scale worked)
  /// How the kept rounding was reached: "fast" (the separations alone, one re-solve and
  /// untangling), "careful" (a volume check per candidate), "relaxed" (the barrier-guarded
  /// relaxation) or "best effort" (tets left inverted).
  std::string RoundingPath;
  /// With cuts: the translation t_c of each cut in lattice units, integers (the data contract's
  /// IntegerCutTranslations).
  std::vector<Eigen::Vector3d> IntegerCutTranslations;
  /// Tets left inverted by a best-effort rounding (IntegerRoundingParameters::
  /// AcceptInvertedTets), 0 normally.
  int RoundingInvertedTetCount = 0;
  /// What the user should know about a mesh that was made anyway (shown as VTK warnings).
  std::vector<std::string> Warnings;
  double MaxPlaneShift = 0.0; ///< largest rounding move of a plane, lattice units
  double RoundingMinVolumeRatio = 0.0;
  /// The rounded map's mean distortion energy (FoldoverFreeEnergy.h; 1 for a similarity) before
  /// and after its smoothing, and the smoothing's L-BFGS iterations (MapSmoothing).
  double MapEnergyBefore = 0.0;
  double MapEnergyAfter = 0.0;
  int MapSmoothingIterations = 0;
  double ScaledJacobianMinBeforeSmoothing = 0.0;
  double ScaledJacobianMeanBeforeSmoothing = 0.0;
  int SmoothingSweeps = 0;
  /// Minimum scaled Jacobian after the sweeps, before the polish (the final one without it).
  double ScaledJacobianMinBeforePolish = 0.0;
  int PolishReleasedVertexCount = 0; ///< corners and curve vertices the polish released
  /// After the untangling, before the local smoothing (equal to the raw values without it).
  double ScaledJacobianMinAfterUntangling = 0.0;
  double ScaledJacobianMeanAfterUntangling = 0.0;
  int InvertedHexCountAfterUntangling = 0;
  int UntanglingRounds = 0;
  int UntanglingIterations = 0;
  /// Which untangling path was kept (UntanglingPaths; 1 the full untangling, 2 the one stopped
  /// at a stall), 0 without untangling.
  int UntanglingPath = 0;
  /// False when the untangling did not run or its result was worse than its input (discarded).
  bool UntanglingKept = false;
  /// Boundary vertices on a polycube edge or corner released onto the surface (SoftFeatureAngle,
  /// HexUntanglingParameters::ReleaseBelow).
  int ReleasedBoundaryVertexCount = 0;
  /// Hexes removed as doublets or overlaps (HexExtractionParameters::RemoveDoublets).
  int RemovedDoubletHexCount = 0;
  /// Lattice hexes removed before the padding where the boundary pinched (RemovePinchingHexes).
  int RemovedPinchHexCount = 0;

  /// Wall seconds per stage.
  double RoundingSeconds = 0.0;
  double ExtractionSeconds = 0.0;
  double PaddingSeconds = 0.0;
  double UntanglingSeconds = 0.0;
  double SmoothingSeconds = 0.0; ///< the local sweeps after the untangling
  double MeasuresSeconds = 0.0;  ///< quality, validity and boundary quads of the result
  /// Extractions run and not kept (ScaleRetries).
  double DiscardedSeconds = 0.0;

  /// The seconds of all the stages above, the discarded extractions included.
  double TotalSeconds() const
  {
    return this->RoundingSeconds + this->ExtractionSeconds + this->PaddingSeconds +
      this->UntanglingSeconds + this->SmoothingSeconds + this->MeasuresSeconds +
      this->DiscardedSeconds;
  }
};

/// Extracts an all-hex mesh from a polycube-deformed tet mesh.
/// @return Failure with a readable message when the input is refused (sizes, an inverted or
///         flat tet in either space: a volume under 1e-14 of the diagonal cubed and under
///         1e-12 of its own longest edge cubed; missing or inconsistent labels), when rounding
///         cannot keep every chart (resolution too low) or when no hex fits.
Status extractHexMesh(const PolycubeTetMesh& input,
  const HexExtractionParameters& params,
  HexExtractionResult& result,
  const Progress& progress = {});

} // namespace polycubehex
