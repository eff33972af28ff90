// SPDX-License-Identifier: BSD-3-Clause
// The frame field of Fang et al. 2016, §3: one rotation per tet (rows = axes, grad u ~ R),
// smooth, aligned with the boundary, matched everywhere except across the cuts, with one cube
// rotation Pi_c per cut such that Pi_c R_minus ~ R_plus (DESIGN.md section 2).
//
// Steps: (1) a smooth boundary-aligned octahedral field in spherical harmonics (§3.2,
// OctahedralField.h); (2) its matching along a minimum spanning tree of the dual graph of the
// cut mesh (FrameFieldMatching.h); (3) energy (1) by L-BFGS (FrameFieldEnergy.h), then polar
// decomposition; (4) per cut the best of the 24 cube rotations, eq. (6); (5) the measures of
// DESIGN.md section 4 (FrameFieldMeasures.h).
#pragma once

#include "FrameFieldMeasures.h"
#include "MeshTypes.h"
#include "Status.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace polycubehex
{

/// The cut faces of a mesh, as the handle-cut step produces them (cell arrays `CutFaces` and
/// `CutSide`). Both tets of a cut face carry the same id, one with side -1 and one with +1.
/// Leave both empty (0 rows) for a mesh without cuts.
struct CutFaces
{
  Tets Ids;   ///< #T by 4: the cut id (0, 1, ...) of local face k, -1 if not a cut face
  Tets Sides; ///< #T by 4: -1 on the minus side, +1 on the plus side, 0 if not a cut face
};

struct FrameFieldParameters
{
  /// Weight of boundary alignment against smoothness in the initial spherical-harmonics field
  /// (§3.2; §5.2 compares 100 and 1000 in the paper's own, unstated, normalisation). Here it is
  /// dimensionless: smoothness is a volume mean of |grad q|^2 with lengths in units of the
  /// bounding-box diagonal, alignment an area mean. Lower: straighter field, singular lines
  /// pushed to the boundary; higher: tighter alignment, singular lines may stay deep inside and
  /// survive energy (1). Measured (initial -> final singular edges, max depth of the initial
  /// ones): kitten 10: 2 -> 0; 30: 181 (4.4%) -> 0; 100: 313 (10%) -> 101 (15.6% deep);
  /// rockerarm 30: 0 -> 0; 100: 3 -> 0; 1000: 172 (5.7%). Range (0, inf).
  double BoundaryAlignmentWeight = 30.0;
  /// On a mesh with cuts, the initial field is first computed with this weight instead, and
  /// BoundaryAlignmentWeight is the fallback: it runs only when the field from this one keeps
  /// singular edges after energy (1), and the field with fewer is kept (the paper's remedy, §6
  /// and Figure 13: a smaller alignment weight pushes the singular lines to the boundary). A
  /// field that follows the boundary tightly turns with it around the handles, and the cuts'
  /// transitions take up the turn; a straighter one crosses the handles unturned, with identity
  /// transitions, and the polycube needs more corners. Measured, closed form (corners; smoothed
  /// scaled Jacobian min / mean): 3holes, transitions I I I -> two half turns, 32 -> 16 corners,
  /// 0.768 / 0.955 -> 0.806 / 0.962; rockerarm, I -> a quarter turn, 62 -> 52, 0.591 / 0.938 ->
  /// 0.667 / 0.955; fertility 90 -> 68, 0.620 / 0.940 -> 0.649 / 0.935 (but more vertices off
  /// their planes); kitten keeps singular edges at 1000 (127) and falls back; the torus does not
  /// change. Not used without cuts, where tighter alignment only bends the field more (bunny 40
  /// -> 58 corners, spot 68 -> 74, elephant keeps singular edges). Default 1000; 0 turns it off
  /// (BoundaryAlignmentWeight everywhere). Range [0, inf).
  double CutMeshBoundaryAlignmentWeight = 1000.0;
  /// w_a of eq. (1): the smoothed l1 normal alignment (4). Range [0, inf).
  double AlignmentWeight = 0.1;
  /// w_d of eq. (1): the normal difference (5). Range [0, inf).
  double NormalDifferenceWeight = 0.01;
  /// Boundary edges sharper than this (the angle between the two face normals, degrees) are left
  /// out of (5). Our addition: past 45 degrees two faces fit a frame better on perpendicular axes
  /// than on one, so (5) there only pulls the frames off the faces (on a cube, 0.1 degree off at
  /// every edge). Smooth surfaces have no such edge and are unaffected; 180 restores the paper's
  /// sum over every edge. Range [0, 180].
  double NormalDifferenceMaxAngle = 45.0;
  /// w_R of eq. (1): the orthogonality penalty. Range (0, inf).
  double OrthogonalityWeight = 1.0;
  /// eps of the smoothed l1 norm |u| ~ sqrt(u^2 + eps). Range (0, inf).
  double L1Epsilon = 1e-3;
  /// L-BFGS stops when the L2 norm of the gradient of the normalised energy (1) is below this
  /// (the paper's rule and value). Every term of (1) is a volume-, area- or face-weighted mean,
  /// so the energy is O(1) whatever the mesh size and scale, and a tet's gradient and stiffness
  /// are both O(1/#T): the rule leaves each tet's frame about tol sqrt(#T) / 30 from
  /// stationary (order 1e-4 on 30k tets), reached in a few hundred iterations. Range [0, inf).
  double GradientTolerance = 1e-5;
  /// Iteration cap of L-BFGS (the paper: "usually less than 300"). 0 skips the optimisation
  /// and returns the matched initial field. Range [0, inf).
  int MaxIterations = 1000;
};

/// Everything ComputeFrameField returns.
struct FrameFieldResult
{
  /// #T by 9: the rotation R_t of tet t, row-major (row a = axis a), in the input's coordinates.
  Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> Frames;
  /// #T by 9: the matched initial field (before energy (1)), for inspection.
  Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> InitialFrames;
  /// #C by 9: Pi_c row-major, Pi_c R_minus ~ R_plus (a cut without faces gets the identity).
  Eigen::Matrix<int, Eigen::Dynamic, 9, Eigen::RowMajor> CutTransitions;

  std::vector<SingularEdge> SingularEdges; ///< of the final field (DESIGN.md section 4)
  int SingularEdgeCount = 0;
  int InteriorSingularEdgeCount = 0; ///< no vertex on the boundary
  double MaxSingularEdgeDepth = 0.0; ///< relative to the bounding-box diagonal; 0 if none
  int InitialSingularEdgeCount = 0;  ///< of the initial spherical-harmonics field
  /// The initial field's boundary alignment weight of the kept field
  /// (CutMeshBoundaryAlignmentWeight or BoundaryAlignmentWeight).
  double InitialAlignmentWeight = 0.0;
  /// Singular edges of the field from CutMeshBoundaryAlignmentWeight; -1 when it did not run.
  int AlignedSingularEdgeCount = -1;

  double BoundaryAlignmentError = 0.0;        ///< degrees, final field
  double InitialBoundaryAlignmentError = 0.0; ///< degrees, initial field
  double FrameEnergy = 0.0;                   ///< energy (1) at the end of L-BFGS
  double InitialFrameEnergy = 0.0;            ///< energy (1) at the matched initial field
  double FinalGradientNorm = 0.0;
  int FrameIterations = 0;
  bool Converged = false; ///< the gradient tolerance was reached within MaxIterations
  std::string SolverReport;

  double InitialFieldSeconds = 0.0;
  double MatchingSeconds = 0.0;
  double OptimizationSeconds = 0.0;
  double MeasureSeconds = 0.0;
  double DiscardedSeconds = 0.0; ///< the field computed and not kept (the fallback's rule)
};

/// Computes the frame field of §3 on a tet mesh with optional cuts.
/// @param mesh   #V by 3 vertices, #T by 4 positively oriented tets (VTK order), a manifold
/// @param cuts   cut faces (CutFaces above), or empty
/// @param out    the frames, transitions and measures
/// @param progress  fraction done in [0, 1]; return false to abort
Status ComputeFrameField(const TetMesh& mesh,
  const CutFaces& cuts,
  const FrameFieldParameters& parameters,
  FrameFieldResult& out,
  const Progress& progress = {});

} // namespace polycubehex
