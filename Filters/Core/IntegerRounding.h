// SPDX-License-Identifier: BSD-3-Clause
// Integer constraints for hex extraction (Fang et al. 2016, §4.3): every chart of the polycube
// is moved onto an integer plane by greedy rounding (Bommes et al. 2009, "Mixed-integer
// quadrangulation" §4: round the variable nearest to an integer, fix it, re-solve the rest),
// under a quadratic distortion energy with the chart planes as hard equalities.
//
// The energy is the Dirichlet energy of the displacement from a reference polycube (the one the
// deformation produced, in lattice units), measured on the rest tets (the input):
// E(x) = sum_t V_t |grad x - J_t|^2, with gradients on the rest tet and J_t the reference's
// Jacobian there. The reference itself has E = 0, so the energy measures only what the rounding
// changes. The rest metric matters: the polycube's own tets are often slivers, and the FEM
// Laplacian on them breaks the maximum principle badly (a plane moved by 0.3 dragged an interior
// vertex by 1.7 and inverted a tet on Data/torus.obj); on the input's quality tets the
// displacement interpolates the plane moves. Without cuts it is separable per axis; a cut
// transition u_plus = Pi u_minus + t (Fang et al. §4.3) couples the axes only through the
// identification of the plus-side coordinates with the minus side's (CoordinateRelations), with
// t as three more integer variables: x = Bf f + Bz z + Offset, z the planes and translations.
//
// The planes are eliminated once: the free coordinates are factored (one sparse LDL^T), and the
// energy is reduced to a dense quadratic in the plane values (a Schur complement), so each greedy
// step is a small dense solve. Pairs of planes that bound a chart or a tet stay ordered and one
// unit apart (an active set in the continuous re-solve, longest paths for the integer choice).
// The linear re-solve does not keep every sliver of a real polycube positive, so the result is
// untangled (a local pattern search, then a penalised L-BFGS over all free coordinates) and
// checked; a volume check per candidate is the fallback. When the reference's charts cannot all
// be flat without inverting a tet (the deformation left vertices off their planes), no fallback
// rescued the rounding on the models tried (rockerarm, kitten: 0 of 7 scales), so the first
// rounding comes back as a best effort at once.
#pragma once

#include "MeshTypes.h"
#include "PolycubeMapSmoothing.h"
#include "PolycubeSeams.h"
#include "Status.h"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace polycubehex
{

/// The charts of a polycube and the plane variables they lie on.
struct ChartPlanes
{
  /// #T by 4: the tet across local face k (vtkTetra face order), or -1 on the boundary.
  Tets Neighbors;
  /// #T by 4: the chart of local face k of tet t, or -1 for an interior face.
  Tets FaceChart;
  /// #C: the label 0..5 (+X, -X, +Y, -Y, +Z, -Z) shared by the faces of each chart. A chart is a
  /// maximal set of boundary faces with one label connected through boundary edges.
  std::vector<int> ChartLabel;
  /// #C: the plane variable each chart lies on. Charts of one axis that share a vertex lie on the
  /// same plane (that vertex has one coordinate), so several charts may share a plane.
  std::vector<int> ChartPlane;
  /// #P: the axis 0, 1, 2 (x, y, z) of each plane.
  std::vector<int> PlaneAxis;
  /// #V by 3: the plane that coordinate a of vertex v equals, or -1 when that coordinate is free.
  Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> VertexPlane;
  /// Pairs (lower, upper) of planes of one axis that must not meet: the planes a tet spans, and
  /// for each chart C the neighbours it leaves towards +b (lower bounds of its extent along b)
  /// paired with those it leaves towards -b (upper bounds), e.g. both sides of a slab seen from
  /// its rim, or the two steps a riser joins. Rounding keeps each pair in its order and at least
  /// one unit apart when they were apart, so that no chart and no layer of tets collapses.
  std::vector<std::array<int, 2>> PlanePairs;
  /// #C: the charts adjacent to each chart through a boundary edge, sorted.
  std::vector<std::vector<int>> ChartNeighbors;
};

/// Finds the charts and their plane variables.
/// @param positions   #V by 3 polycube positions (any scale): they order the plane pairs and tell
///                    on which side of a neighbour a chart lies
/// @param cells       #T by 4 tets
/// @param faceLabels  #T by 4: label 0..5 of local face k when it lies on the boundary, -1
///                    otherwise (PolycubeLabels in the data contract)
/// @param seams       the cuts of a closed-form polycube (nullptr for a uniform one): their faces
///                    are boundary faces of the cut mesh but lie inside M, so they carry no
///                    label and belong to no chart (Neighbors stays -1 there: the tet across is
///                    in seams->Neighbor)
/// @return Failure when a boundary face has no label, an interior face (or a cut face) has one,
///         a label is out of range, an index is out of range, or a face is shared by more than
///         two tets.
Status ComputeChartPlanes(const Points& positions,
  const Tets& cells,
  const Tets& faceLabels,
  ChartPlanes& charts,
  const PolycubeSeams* seams = nullptr);

/// The distortion energy of a polycube with its chart planes as hard equalities, reduced to the
/// plane values. Build it once per reference; Solve maps plane values to vertex positions.
class PolycubePlaneSolver
{
public:
  PolycubePlaneSolver();
  ~PolycubePlaneSolver();
  PolycubePlaneSolver(const PolycubePlaneSolver&) = delete;
  PolycubePlaneSolver& operator=(const PolycubePlaneSolver&) = delete;

  /// @param rest       #V by 3 positions the energy is measured on (the input, any scale);
  ///                   positive tets
  /// @param reference  #V by 3 reference positions (the polycube to stay close to); positive
  ///                   tets
  /// @param cells      #T by 4 tets
  /// @param charts     from ComputeChartPlanes on the same tets
  /// @param seams      the cuts of a closed-form polycube (nullptr or empty for a uniform one),
  ///                   translations in the units of `reference`. Then every copy pair stays
  ///                   related, x_plus = Pi x_minus + t, and the integer variables are the
  ///                   independent planes followed by the free translations t (a plane that
  ///                   crosses a cut is one variable, its other side differs by t).
  /// @return Failure when a tet is not positive in either, when the free coordinates are not
  ///         pinned by any plane (a component without charts of some axis), or when the
  ///         transitions contradict the charts.
  Status Build(const Points& rest,
    const Points& reference,
    const Tets& cells,
    const ChartPlanes& charts,
    const PolycubeSeams* seams = nullptr);

  /// #Z: the reference values of the integer variables: for a uniform polycube the mean
  /// reference coordinate of the vertices of each plane (exact when the charts are flat); with
  /// cuts, the least-squares fit of the reference by planes and translations.
  const Eigen::VectorXd& ReferencePlanes() const { return this->RefPlanes; }

  /// Pairs of integer variables that must stay ordered and apart (ChartPlanes::PlanePairs in
  /// the integer variables; with cuts, only the pairs whose planes are in one frame).
  const std::vector<std::array<int, 2>>& SeparationPairs() const { return this->Pairs; }

  /// #Z: a chart plane that each integer variable carries, or -1 for a translation.
  const std::vector<int>& PlaneOfVariable() const { return this->VariablePlane; }

  /// The cut translations t_c for given integer variables (empty without cuts).
  std::vector<Eigen::Vector3d> CutTranslations(const Eigen::VectorXd& planes) const;

  /// #P: the value of every chart plane (ChartPlanes numbering) for given integer variables.
  Eigen::VectorXd ChartPlaneValues(const Eigen::VectorXd& planes) const;

  /// The energy as a function of the planes alone: E(P) = P^T H P - 2 g^T P + c (the free
  /// coordinates at their optimum). H is #P by #P, symmetric positive semi-definite (a
  /// translation of all planes of one axis costs nothing).
  const Eigen::MatrixXd& PlaneHessian() const { return this->H; }
  const Eigen::VectorXd& PlaneGradient() const { return this->G; }

  /// Positions for given plane values: coordinates on a plane equal its value exactly, the free
  /// ones minimise the energy.
  /// @param planes     #P plane values
  /// @param positions  #V by 3 output
  void Solve(const Eigen::VectorXd& planes, Points& positions) const;

  /// The distortion energy sum_t V_t |grad x - J_t|^2 of `positions` (0 at the reference).
  double Energy(const Points& positions) const;

  /// Raises the volume ratio of tets below `target` by moving the free coordinates of their
  /// vertices (a pattern search per vertex on the smallest ratio of its tets, a few sweeps);
  /// plane coordinates never move. The linear solve keeps the energy low but not every sliver
  /// of the polycube positive: a plane moved by 0.3 flips a tet of relative thickness 0.04.
  /// @return the smallest volume ratio afterwards
  double Untangle(Points& positions, double target) const;

  /// Raises the volume ratio of every tet towards `target` by minimising, over the free
  /// coordinates at once (L-BFGS), the distortion energy plus a penalty on the tets below the
  /// target, escalated until every tet is above half the target or three weights were tried.
  /// For the slivers the local search cannot free.
  /// @param rings  move only the free coordinates within this many rings of tets around the tets
  ///               below the target (the rest is the linear solve's optimum already); -1: all
  /// @param stall  end a weight's L-BFGS run once the count of tets below half the target has
  ///               not fallen for this many iterations (checked every 10; 0: run to convergence)
  /// @return the smallest volume ratio afterwards
  double UntangleGlobally(Points& positions, double target, int rings = -1, int stall = 0) const;

  /// Smallest ratio of a tet's signed volume in `positions` to its volume in the reference.
  double MinVolumeRatio(const Points& positions) const;

  /// #3V by #F: how the free variables move the coordinates (x = Bf f + Bz z + Offset).
  const Eigen::SparseMatrix<double>& FreeBasis() const;

private:
  struct Impl;
  std::unique_ptr<Impl> Data;
  Eigen::VectorXd RefPlanes;
  Eigen::MatrixXd H;
  Eigen::VectorXd G;
  std::vector<std::array<int, 2>> Pairs;
  std::vector<int> VariablePlane;
};

/// Settings of roundPolycubePlanes.
struct IntegerRoundingParameters
{
  /// Integers tried for each plane, nearest first, before giving up (default 4, >= 1).
  int CandidateCount = 4;
  /// A candidate is refused when some tet's volume shrinks below this fraction of its reference
  /// volume (default 1e-4, in (0, 1)): a collapsed chart flattens the tets next to it.
  double MinimumVolumeRatio = 1e-4;
  /// Two planes of a pair closer than this (lattice units) count as one level and need not
  /// stay apart (default 1e-6).
  double SeparationTolerance = 1e-6;
  /// After each re-solve, tets whose volume ratio is below this are untangled (default 0.05,
  /// in [0, 1); 0 turns it off).
  double UntangleTarget = 0.05;
  /// When no path keeps every tet above MinimumVolumeRatio, return the first rounding as it is
  /// (BestEffort, with its inverted tets counted) instead of failing (default on). The planes the
  /// deformation could not realise (a chart squeezed between planes it got too close) leave a
  /// few such tets; a mesh with a few bad hexes and a warning serves better than none.
  bool AcceptInvertedTets = true;
  /// Try the slow fallbacks even when the reference's charts cannot all be flat without
  /// inverting a tet (default off: then the first rounding comes back as a best effort at once,
  /// see IntegerRoundingResult::UnflattenableCharts).
  bool FallbacksWhenUnflattenable = false;
  /// Wall seconds the slow fallbacks may take after the first rounding failed (default 10): the
  /// barrier relaxation starts only within the first half, and the careful path stops at the end
  /// (then AcceptInvertedTets decides). Both rarely rescue a polycube whose labels the
  /// deformation could not flatten, and on 75k tets they took minutes.
  double TimeBudgetSeconds = 10.0;
  /// Rings of tets around the tets below UntangleTarget that the nonlinear untangling moves
  /// (PolycubePlaneSolver::UntangleGlobally; default 4, -1 for the whole mesh) where the charts
  /// can be flat; where they cannot, it always gets the whole mesh. Kitten's l1 polycube
  /// (55k tets, three scales): rounding 14.9 s with the whole mesh, 6.9 s with 4 rings. Where the
  /// charts cannot be flat the untangling starts from tets it cannot free, and its outcome
  /// depended on the region erratically (rockerarm closed form, smoothed: min 0.325 / Hausdorff
  /// 8.4 with the whole mesh, 0.244 / 18.3 with 4 rings; fertility closed form 0.081 / 0.134).
  int UntangleRings = 4;
  /// The nonlinear untangling ends a weight's L-BFGS run once the count of tets below half of
  /// UntangleTarget has not fallen for this many iterations (default 50; 0: each run goes to
  /// convergence or 500 iterations). Where the charts cannot be flat some tets cannot be freed,
  /// and the iterations after the last tet freed cost a full evaluation each: elephant's l1
  /// polycube (77k tets) spent 925 iterations and 11 s taking 43 inverted tets to 1; with 50
  /// it stops at 1 inverted tet after 277 iterations and 3.5 s (hex stage 15.4 -> 9.7 s).
  int UntangleStallIterations = 50;
  /// Stop after the fast path (greedy rounding, one re-solve, untangling): when a tet stays
  /// below MinimumVolumeRatio, return it as a best effort without the slow fallbacks (default
  /// off). The hex stage tries the fast path at several scales first, which is cheaper than
  /// the fallbacks at one (kitten Uniform: 0.2-1.2 s per scale against 5-8 s).
  bool FastPathOnly = false;
  /// The last step, when on: the rounded map is smoothed over its free coordinates, planes and
  /// cut relations held (PolycubeMapSmoothing.h; default off).
  bool SmoothMap = false;
  PolycubeMapSmoothingParameters MapSmoothing;
};

/// What roundPolycubePlanes produced.
struct IntegerRoundingResult
{
  Points Positions;             ///< #V by 3 positions, every chart on an integer plane
  Eigen::VectorXd PlanesBefore; ///< #P plane values of the reference
  Eigen::VectorXd PlanesAfter;  ///< #P integer plane values
  int FallbackCount = 0;        ///< planes rounded to another integer than their nearest
  double MaxPlaneShift = 0.0;   ///< max |after - before| (lattice units)
  double MinVolumeRatio = 0.0;  ///< smallest tet volume ratio after rounding
  double Energy = 0.0;          ///< distortion energy of the rounded polycube
  /// False when rounding with the separations alone, then re-solving and untangling, kept every
  /// tet positive; true when the careful path (a volume check per candidate) was needed.
  bool CarefulPath = false;
  /// True when the planes were moved to their integers by the barrier-guarded relaxation
  /// (PolycubePlaneRelaxation.h) because the linear re-solve and untangling left a tet below
  /// MinimumVolumeRatio.
  bool Relaxed = false;
  /// True when AcceptInvertedTets returned the first rounding with tets below the minimum.
  bool BestEffort = false;
  std::string BestEffortReason;
  /// True when the reference's charts cannot all be flat (each plane at the mean of its
  /// coordinates) without inverting a tet: the deformation left vertices off their planes. The
  /// slow fallbacks were skipped (they rescued no such polycube we tried and took 85-95 % of
  /// the hex stage), and the property does not depend on the scale, so other scales are not
  /// tried either.
  bool UnflattenableCharts = false;
  int InvertedTetCount = 0; ///< non-positive tets in Positions (0 unless BestEffort)
  /// With cuts: the integer translation t_c of each cut, and the largest distance of a chart
  /// plane from an integer (0 up to round-off).
  std::vector<Eigen::Vector3d> CutTranslations;
  double MaxPlaneFraction = 0.0;
  /// What the smoothing of the rounded map did (IntegerRoundingParameters::MapSmoothing).
  PolycubeMapSmoothingResult MapSmoothing;
};

/// Rounds every chart plane of `reference` to an integer greedily and re-solves the vertices.
/// Fast path: greedy rounding under the separations alone, one re-solve, then untangling (local,
/// then global if needed). If a tet stays below MinimumVolumeRatio, the careful path rounds
/// again with a re-solve and a local untangling per candidate, and untangles the result.
/// @param rest       #V by 3 input positions (any scale), positive tets: the energy's metric
/// @param reference  #V by 3 polycube positions in lattice units (one unit = one hex edge),
///                   positive tets
/// @param cells      #T by 4 tets
/// @param charts     from ComputeChartPlanes
/// @param seams      the cuts of a closed-form polycube, translations in lattice units (nullptr
///                   or empty for a uniform one): the translations are rounded with the planes
///                   (Fang et al. 2016 §4.3), and the barrier relaxation fallback is not used
/// @return Failure (naming the chart) when no candidate integer keeps every tet positive and
///         every plane pair apart; the message suggests a finer resolution.
Status roundPolycubePlanes(const Points& rest,
  const Points& reference,
  const Tets& cells,
  const ChartPlanes& charts,
  const IntegerRoundingParameters& params,
  IntegerRoundingResult& result,
  const Progress& progress = {},
  const PolycubeSeams* seams = nullptr);

} // namespace polycubehex
