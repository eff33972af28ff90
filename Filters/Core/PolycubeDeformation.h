// SPDX-License-Identifier: BSD-3-Clause
// The l1-based polycube deformation of Huang et al. 2014 as used by Fang et al. 2016 (§4.2,
// eq. 9-13), `Uniform` guidance: no frame field and no cuts. A tet mesh of any genus is deformed
// until its boundary normals are axis-aligned, its boundary is split into charts labelled
// +X,-X,+Y,-Y,+Z,-Z, and each chart is flattened onto its plane with every tet positive.
//
// Pipeline: normalise (unit diagonal) -> split interior edges joining two boundary vertices ->
// optional l1-optimal rotation -> continuation of damped Newton solves (PolycubeNewton.h) on
// E_arap + w_align E_align + w_diff E_diff + w_area E_area + barrier (PolycubeEnergy.h) ->
// labels, chart clean-up (PolycubeCharts.h) -> splits of the edges and tets the charts would force
// flat -> flattening: a growing penalty towards the chart planes, then the planes hard (their
// coordinates eliminated from the unknowns) and an ARAP relaxation -> back to input units.
//
// With frames (FrameField guidance) the continuation starts from the frame fit of eq. 7. With
// frames and cuts (the closed form, §4.1-4.2) everything runs on the cut mesh M_c
// (PolycubeCutMesh.h): the copies across cut c are tied by x_plus = Pi_c x_minus + t_c, t_c
// unknown, in every solve (CoordinateRelations.h); the fit of eq. 7 is then one linear solve;
// only the boundary of M is aligned, labelled and flattened; labels agree across each cut;
// charts are glued across the cuts for the clean-up and the corners, but each side keeps its own
// plane (the two planes differ by t_c); the final flattening keeps the planes as unknowns.
#pragma once

#include "MeshTypes.h"
#include "PolycubeCutMesh.h"
#include "Status.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace polycubehex
{

/// Settings of ComputePolycube. Lengths and areas are relative to the input's bounding-box
/// diagonal (DESIGN.md "Scale"). The defaults were measured on Data/rockerarm.mesh (30.8k tets,
/// genus 1): 12 rounds, residual 8.0e-4, 39 charts, 70 corners (the paper's l1 baseline: 88),
/// no inverted tet, about 20 s on 2 shared cores; AlignmentBarrierThreshold on fertility and
/// elephant as well (TetGen -pq2.0, 78k and 75k tets), which stalled with the old 0.1.
struct PolycubeParameters
{
  /// Rotate the model first by the rotation minimising the area-weighted l1 norm of its normals
  /// (PolycubeRotation.h; of the 24 equivalent ones, the closest to the identity). The polycube
  /// is then axis-aligned in the rotated frame (InitialRotation in the result).
  bool AlignInitialRotation = true;

  /// Before optimising, split every interior edge whose two ends are on the boundary: such an
  /// edge (and a tet with two boundary faces) is forced flat as soon as its ends reach one chart
  /// plane, and the line search would then stall against it.
  bool PresplitBoundaryEdges = true;

  /// Continuation (after the public code of Huang et al.'s group): round k minimises
  /// E_arap + w_k E_align + w_diff E_diff + w_area E_area + w_barrier,k E_barrier with
  /// w_k = AlignmentWeight * AlignmentWeightGrowth^k and the l1 smoothing
  /// eps_k = max(MinAlignmentEpsilon, AlignmentEpsilon * AlignmentEpsilonDecay^k), until the
  /// polycube residual is below ResidualTolerance. Starting at 0.05 as the public code does only
  /// adds two rounds that barely move the shape on rockerarm.
  double AlignmentWeight = 0.2;
  double AlignmentWeightGrowth = 2.0;
  double AlignmentEpsilon = 0.1;
  double AlignmentEpsilonDecay = 0.7;
  double MinAlignmentEpsilon = 0.01;
  int MaxRounds = 30;
  /// Newton iterations per round (fewer when the steps become negligible).
  int IterationsPerRound = 5;
  /// DESIGN.md §4: below this the deformation counts as converged.
  double ResidualTolerance = 1e-3;

  /// w_diff of eq. (12): smoothness of the normals along boundary edges (fewer small charts). On
  /// rockerarm: 0 gives 74 charts and 137 corners, 0.3 gives 54 and 100, 1 gives 39 and 70, at
  /// about the same cost.
  double NormalDifferenceWeight = 1.0;
  /// On a cut mesh, also compare the normals of neighbours across each cut's loop, the minus
  /// face's turned by Pi_c (Fang et al. §4.2). Off by default, by measurement: on kitten's closed
  /// form it leaves 3 vertices off their planes and 5 tets inverted by the integer rounding (0
  /// and 0 without), and on 3holes it changes nothing (32 corners, same hexes).
  bool NormalDifferenceAcrossCuts = false;
  /// Penalty weight on (A / A_rest - 1)^2, A the boundary area (eq. 9's area constraint; the
  /// alignment term is normalised by the current area, so it has no incentive to shrink).
  double AreaWeight = 1.0;
  /// Inversion barrier weight, multiplied by max(1, w_k) in round k (PolycubeEnergy.h).
  double BarrierWeight = 1.0;
  /// Volume ratio (deformed / rest) below which the barrier acts (frame fit and flattening).
  double BarrierThreshold = 0.1;
  /// The wider barrier zone of a starved continuation. The barrier's Newton model only sees a
  /// tet inside its zone, so a tet above it can be carried through zero volume by one step. At
  /// 0.1, on fertility and elephant, thousands of tets ended up between 1e-5 and 0.1 of their
  /// volume, every Newton step was halved 7-8 times to keep them positive, and the residual
  /// stalled (0.039 and 0.0155 after 30 rounds). At 0.3 the steps keep their length: fertility
  /// converges in 14 rounds (Uniform) and 13 (closed form), elephant in 11, smallest volume ratio
  /// about 0.1 instead of 1e-5. From the first round it would cost corners where 0.1 converges:
  /// tets no longer collapse to let small features go flat (bunny Uniform 46 instead of 36,
  /// closed form 54 instead of 40; kitten's closed form 40 instead of 36). So the continuation
  /// starts at BarrierThreshold and widens the zone to this one for the remaining rounds once a
  /// round is starved (StarvedHalvingsPerIteration).
  double AlignmentBarrierThreshold = 0.3;
  /// A continuation round is starved when its line search halved the Newton steps more than this
  /// many times per iteration on average to keep every tet positive. Measured: rockerarm at most
  /// 3.8 per iteration in any round, fertility and elephant 7-9 from their fourth round on.
  double StarvedHalvingsPerIteration = 5.0;
  /// The same for FrameField guidance, where the continuation starts from the frame fit. Lower,
  /// by measurement (BENCHMARKS.md, smoothed hexes at the paper's counts): at 5, fertility's closed
  /// form let tets collapse in rounds 4-5 (smallest volume ratio 0.0099, then 0.00017) before its
  /// sixth round was starved; the faces over them hid as thin tongues that turn creases back by
  /// 15 % of the diagonal (11 creases, 4 squashed, 186 vertices off their planes; hexes 0.177 /
  /// Hausdorff 19.1e-3). At 2 the zone widens from round 4: 2 creases turn back by 0.7 %, 1 is
  /// squashed, 104 vertices off their planes, hexes 0.620 / 7.05e-3, and 52 s instead of 84 s.
  /// Kitten's closed form: 36 corners either way, 0.727 -> 0.693. Rockerarm's squashes an edge
  /// to 0.016 at 2, which SquashedRetryStretch catches.
  double FrameGuidedStarvedHalvingsPerIteration = 2.0;
  /// When the result has a polycube edge squashed below this stretch (PolycubeResult's
  /// MinCreaseStretch), the whole deformation runs once more with the other guidance's
  /// starvation setting (StarvedHalvingsPerIteration <-> FrameGuidedStarvedHalvingsPerIteration)
  /// and the result whose smallest stretch is larger is kept (then the one with fewer vertices
  /// off their planes). The outcome of the continuation is chaotic in that setting: on rockerarm's
  /// closed form, 2 squashes an edge to 0.016 and 5 to 0.038, with smoothed hexes of 0.35 and
  /// 0.59. 0 turns the retry off.
  double SquashedRetryStretch = 0.05;

  /// Chart clean-up: charts below this fraction of the boundary area, or with fewer faces than
  /// MinChartFaceCount, are merged into a neighbour when they are thin along its axis (see
  /// PolycubeChartCleanup).
  double MinChartAreaFraction = 2e-4;
  int MinChartFaceCount = 3;

  /// Flatten each chart exactly onto its plane (otherwise stop after labelling).
  bool Flatten = true;
  /// FrameField guidance: Newton iterations of the frame fit (eq. 7) before the l1 stage.
  int FrameGuidedIterations = 30;
  /// A labelling the mesh cannot flatten (e.g. a tongue of one chart between two sides of
  /// another, which must collapse to a line) shows up as faces the penalised flattening squeezes
  /// below CollapseAreaRatio of their rest area. They take a neighbouring chart's label and the
  /// flattening restarts, at most this many times (0: keep the labels and release the vertices).
  int CollapseRelabelAttempts = 2;
  double CollapseAreaRatio = 1e-2;
  /// Uniform guidance: rounds of crease repair after labelling. A crease whose mesh path runs
  /// back along its axis by more than MonotoneRepairTolerance (a fraction of the diagonal)
  /// would fold when flattened; its charts' faces around the part that runs back take one label
  /// (ShaveTurnedBackCreases) and the shape is deformed again with every face pulled onto its
  /// label's axis. 0: off.
  int MonotoneRepairRounds = 6;
  double MonotoneRepairTolerance = 1e-3;
  int MonotoneRepairIterations = 3; ///< Newton iterations of each repair round's deformation
  /// Flattening: anchor penalty rounds (weight x10 each, from 1e3 times the final barrier
  /// weight) before the planes become hard.
  int FlattenRounds = 8;
  /// Flattening: Newton iterations per anchor round and for the final hard-constrained solve.
  int FlattenIterations = 5;
  /// Flattening, Uniform guidance: after the penalty rounds, at most this many homotopy steps
  /// carry the chart coordinates the rest of the way to their planes with the planes hard
  /// (PolycubeHomotopy.h), each followed by FlattenRelaxIterations Newton iterations. Off (0)
  /// by default: with 40 steps the vertices off their planes by over 1e-9 of the diagonal went
  /// 162 -> 57 on fertility and 24 -> 2 on elephant (rockerarm: 10 either way, at its fold), but
  /// the integer rounding then inverted more tets and the smoothed hex minima fell (fertility
  /// 0.638 -> 0.507 at 17,910 hexes, rockerarm 0.208 -> 0.022 at 24,346, elephant 0.542 -> 0.344
  /// at 10,000), so it waits until that is understood.
  int FlattenHomotopySteps = 0;
  int FlattenRelaxIterations = 2;
  /// A homotopy step that can take less than this fraction of its move freezes the anchors that
  /// block it (HomotopySettings::FreezeBelow).
  double FlattenFreezeBelow = 1.0 / 16.0;

  /// Linear solver of the Newton steps.
  enum class LinearSolverType
  {
    /// CG preconditioned by a Cholesky factorisation of the per-axis blocks of the Newton matrix
    /// (three scalar-sized systems, factorised once per round). Rockerarm: about 1.6 s per round.
    BlockPcg,
    /// Sparse LDL^T of the coupled 3#V system, every iteration. Rockerarm: about 7 s per round.
    Direct
  };
  LinearSolverType LinearSolver = LinearSolverType::BlockPcg;
};

/// One continuation round of ComputePolycube, for diagnostics (PolycubeResult::RoundLog).
struct PolycubeRound
{
  double Weight = 0.0;           ///< w_k
  double Epsilon = 0.0;          ///< eps_k
  double BarrierThreshold = 0.0; ///< the barrier's zone in this round (a volume ratio)
  double Residual = 0.0;         ///< polycube residual at the end of the round
  double MinVolumeRatio = 0.0;   ///< smallest deformed / rest tet volume at the end
  double Arap = 0.0;             ///< E_arap at the end
  int Iterations = 0;            ///< Newton iterations
  int CgIterations = 0;
  int InfeasibleTrials = 0; ///< line-search halvings because a tet would invert
  int ArmijoTrials = 0;     ///< line-search halvings for the sufficient decrease
  double LastStep = 0.0;    ///< step length of the last accepted Newton iteration
  bool LineSearchFailed = false;
  double Seconds = 0.0;
};

/// Where a polycube is defective, per vertex: bit flags of PolycubeResult::VertexDefects, so
/// that a user can see where its hexes will be poor (the field counts only say how many).
enum PolycubeVertexDefect : int
{
  OffChartPlane = 1,      ///< farther than 1e-9 of the diagonal from one of its chart planes
  OnTurnedBackCrease = 2, ///< on a crease that turns back over 1e-3 of the diagonal
  OnSquashedCrease = 4    ///< on a squashed crease (SquashedCreaseStretch)
};

/// Output of ComputePolycube, on the mesh after the splits.
struct PolycubeResult
{
  Points Positions; ///< #V' by 3 polycube positions, in input units
  Tets Cells;       ///< #T' by 4 tets (positive in Positions when InvertedTetCount is 0)
  std::vector<int> OriginalPointId; ///< #V': input vertex, or -1 for a vertex made by a split
  Points OriginalPoints;            ///< #V' by 3: input position (interpolated for split vertices)
  std::vector<int> OriginalCellId;  ///< #T': the input tet each tet comes from
  /// #T' by 4: label 0..5 (+X,-X,+Y,-Y,+Z,-Z) of local face k when it is on the boundary,
  /// -1 otherwise. Local faces follow vtkTetra (TetGeometry.h).
  Tets FaceLabels;
  Triangles BoundaryFaces;            ///< #F by 3 boundary triangles, oriented outwards
  std::vector<int> BoundaryFaceTet;   ///< #F owning tet
  std::vector<int> BoundaryFaceLabel; ///< #F label 0..5
  std::vector<int> ChartId;           ///< #F chart id
  std::vector<double> ChartPlane;     ///< per chart: its coordinate along its axis, input units
  int ChartCount = 0;
  int CornerCount = 0;            ///< vertices where three or more charts meet
  int InvertedTetCount = 0;       ///< tets with non-positive volume in Positions
  double MinVolumeRatio = 0.0;    ///< smallest deformed / rest volume over the tets
  double Residual = 0.0;          ///< polycube residual before flattening (DESIGN.md §4)
  bool Converged = false;         ///< Residual < ResidualTolerance
  double MaxPlaneDeviation = 0.0; ///< largest distance of a chart vertex to its plane, input units
  /// Vertices farther than 1e-9 of the diagonal from one of their chart planes (DESIGN.md's
  /// tolerance): the flattening could not bring them there without inverting a tet or folding
  /// a chart face (a labelling the connectivity cannot realise). 0 means every chart is exact.
  int UnflattenedVertexCount = 0;
  /// Vertices whose planes were not imposed exactly at the end (snapping them would have
  /// inverted a tet or folded a chart face); the flattening may still have brought them within
  /// the tolerance above.
  int ReleasedVertexCount = 0;
  /// How the flattening of the last labelling ended, before the snap: the largest distance of
  /// an anchored coordinate to its plane (a fraction of the diagonal; the penalty alone reaches
  /// at most about 1e-8 where the labels can be flattened, the homotopy 0 but at its frozen
  /// anchors), and the line-search
  /// halvings that kept every tet positive, over all its Newton iterations and homotopy steps.
  /// Many halvings with a large deviation mean the flattening stalled, not that it converged
  /// onto bad labels.
  double FlattenDeviation = 0.0;
  int FlattenHalvings = 0;
  /// Homotopy steps taken after the penalty rounds (FlattenHomotopySteps), the smallest
  /// fraction of its remaining move one of them could take (1: nothing held it back), and the
  /// anchored coordinates it froze where a fold blocked them (HomotopySettings::FreezeBelow).
  int FlattenHomotopySteps = 0;
  double FlattenHomotopyFraction = 1.0;
  int FlattenFrozenAnchors = 0;
  /// Largest turn-back of a crease (PolycubeCreases.h: how far the mesh path of a polycube edge
  /// runs back along the edge's axis, folding the faces between its turning points), in input
  /// units: in the shape the charts were labelled on, and in the result. 0 for monotone creases.
  double CreaseTurnBackBeforeFlattening = 0.0;
  double CreaseTurnBack = 0.0;
  int TurnedBackCreaseCount = 0; ///< creases of the result turning back over 1e-3 of the diagonal
  int MonotoneRepairRounds = 0;  ///< crease repair rounds run (PolycubeParameters)
  int ShavedFaceCount = 0;       ///< faces they relabelled
  /// Creases of the result squashed along their axis (PolycubeCreases.h CreaseStretch): their
  /// length along the axis over their length in the input is below SquashedCreaseStretch,
  /// counting those at least SquashedCreaseMinLength of the diagonal long in the input; and the
  /// smallest stretch of those (1 if none). Charts labelled across the edge's axis: the
  /// tets along such an edge are crushed, and so may be the hexes (rockerarm), though not
  /// always (kitten's l1 polycube has one at 0.16 and rounds cleanly).
  static constexpr double SquashedCreaseStretch = 0.25;
  static constexpr double SquashedCreaseMinLength = 0.02;
  int SquashedCreaseCount = 0;
  double MinCreaseStretch = 1.0;
  /// #V': PolycubeVertexDefect flags of each vertex (0 where the polycube is sound), the
  /// vertices counted by UnflattenedVertexCount, TurnedBackCreaseCount and SquashedCreaseCount.
  std::vector<int> VertexDefects;
  /// Boundary faces folded over their label's direction when the flattening started (the
  /// optimisation leaves a few where tiny charts were merged), and at the end (0 on success:
  /// the hex extraction refuses a folded face).
  int InitiallyFoldedFaceCount = 0;
  int FoldedFaceCount = 0;
  /// Applied before deforming: the l1-optimal rotation, or with frames the mean frame rotation.
  Eigen::Matrix3d InitialRotation = Eigen::Matrix3d::Identity();
  /// True when the call failed because the frame field describes no valid map: the
  /// frame-guided Poisson reconstruction (eq. 7, with the cut transitions) inverts tets or is
  /// singular. Another frame field, or Uniform guidance, may succeed where this one did not.
  bool FrameFieldRefused = false;
  /// With frames: sum_t V_t / V ||J_t - R_t||^2 after the frame fit (0 = integrable field).
  double FrameFitResidual = 0.0;
  /// Closed form: per cut, t_c of x_plus = Pi_c x_minus + t_c (input units; 0 rows without
  /// cuts), and the number of copy pairs the relations tie.
  Points CutTranslations;
  int CopyCount = 0;
  int Rounds = 0; ///< continuation rounds (0: the input was already a polycube)
  /// The starvation setting of the kept result (PolycubeParameters::StarvedHalvingsPerIteration
  /// or FrameGuidedStarvedHalvingsPerIteration), and whether the deformation ran twice
  /// (SquashedRetryStretch); the kept result's seconds include both runs.
  double StarvedHalvingsPerIteration = 0.0;
  bool Retried = false;
  std::vector<PolycubeRound> RoundLog; ///< one entry per continuation round
  int Iterations = 0;                  ///< Newton iterations, all phases
  int PresplitEdgeCount = 0;
  int SplitEdgeCount = 0;              ///< edges split after labelling
  int SplitTetCount = 0;               ///< tets split at their centroid after labelling
  int RelabelledFaceCount = 0;         ///< faces relabelled by the chart clean-up
  int CollapseRelabelledFaceCount = 0; ///< faces relabelled because flattening collapsed them
  double RotationSeconds = 0.0;
  double OptimizationSeconds = 0.0;
  double LabelingSeconds = 0.0; ///< labels, clean-up and splits
  double FlatteningSeconds = 0.0;
  double TotalSeconds = 0.0;
  std::vector<std::string> Warnings;
};

/// Deforms `input` into a polycube.
/// @param input     #V by 3 vertices and #T by 4 positively oriented tets (VTK order)
/// @param params    settings
/// @param out       the result; valid only on success
/// @param progress  fraction done, return false to abort
/// Fails on an empty mesh, an index out of range, a non-finite coordinate, a non-positive tet,
/// a face shared by more than two tets, or an abort.
/// @param tetFrames #T rotations R_t (row a = frame axis a, input coordinates) of a frame field
///                  without singularities (FrameFieldResult::Frames), or empty for the Uniform
///                  guidance. With frames, the l1 stage starts from the map whose gradient best
///                  fits them (§4.1, eq. 7) instead of the input rotated.
/// @param cuts      with frames, the cuts and their transitions (the closed form, §4.1-4.2):
///                  the mesh is cut open, the copies across each cut are related by
///                  x_plus = Pi_c x_minus + t_c (t_c unknown) in every solve, and the result is
///                  the cut mesh with CutTranslations. Null or no cut: the uncut mesh.
Status ComputePolycube(const TetMesh& input,
  const PolycubeParameters& params,
  PolycubeResult& out,
  const Progress& progress = {},
  const std::vector<Eigen::Matrix3d>& tetFrames = {},
  const PolycubeCuts* cuts = nullptr);

} // namespace polycubehex
