// SPDX-License-Identifier: BSD-3-Clause
// Cut generation (Fang et al. 2016, section 2): cut a tet mesh M into a simply connected M_c with
// exactly beta_1(M) cuts made one at a time, each a connected, two-sided, properly embedded
// 2-manifold of interior faces whose boundary lies on the boundary of M or on earlier cuts, small
// in area, and each lowering beta_1 by exactly one. beta_1 is the sum of the genera of the
// boundary components (Dey and Guha 1998).
//
// Method (the paper grows and shrinks a tet region around a surface handle loop found with
// Dey et al. 2013; this is a global alternative with the same output contract):
//  1. Topology of the current cut mesh M_k (earlier cuts opened into boundary, CutMesh):
//     boundary components and genera (TopologyBoundary) and, independently, H^1 from the dual
//     complex (TopologyHomology) with a basis of integer cocycles. The two beta_1 must agree.
//  2. Every basis cocycle is moved within its cohomology class to a least-area surface by
//     minimum cuts in the cyclic cover it defines (CutMinimize, MaxFlow); a basis class whose
//     surface meets the smallest one is also tried as class -+ smallest (basis reduction). Each
//     surface is then repaired locally into a properly embedded one (CutRepair): no sheet
//     touching another, none touching the boundary at an isolated vertex.
//  3. Each connected component of each surface is a candidate; so are the surfaces found on the
//     input at step 0 (properly embedded in M, so they cross earlier cuts instead of ending on
//     them: no mismatched edge, section 5.3). A candidate must be connected, manifold, proper
//     and two-sided (CutSurface), must not separate its solid, and, cut open, must leave a
//     closed 2-manifold boundary with beta_1 lowered by exactly one, by both counts. The
//     smallest candidate without mismatched edges that passes becomes cut k (one with
//     mismatched edges only when no other passes).
//  4. Repeat on M_{k+1} until beta_1 = 0.
// Least-area is meant within the class and relative to the boundary of M_k, so a later cut may
// end on earlier cuts; with voids the first cut of a hollow torus is an annulus from the outer
// to the inner surface, the second a disk crossing it. The result does not depend on the scale
// of the input (capacities are areas relative to the largest face).
//
// Subdivision: when a step finds no valid cut (for example in a handle one tet thick, where every
// candidate touches the boundary at a vertex inside the cut), the interior edges joining two
// boundary vertices near that step's candidates are split at their midpoints (CutSubdivision)
// and the computation restarts on the refined mesh, at most MaxSubdivisionRounds times. A mesh
// that needs no subdivision is not touched and gets the same cuts as with 0 rounds.
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <array>
#include <vector>

namespace polycubehex
{

struct HandleCutParameters
{
  /// Sheets of the cyclic cover in one minimum-cut window (>= 1). With 1 a round finds the
  /// least-area surface that does not cross the current one (the solid cut open along it, source
  /// on one side, sink on the other); rounds repeat until the area stops falling. With 2 a round
  /// may also cross it once. Measured on fertility and rockerarm: the same cuts, but with 2
  /// sheets the augmenting paths run twice around the handle and a round costs 6 to 50 times more.
  int CoverCopies = 1;
  /// At most this many minimum cuts per class and step.
  int MaxMinCutRounds = 8;
  /// Budget of local repair moves per candidate surface, per face of the surface.
  int RepairMovesPerFace = 4;
  /// Prefer cuts without mismatched edges (section 5.3): a cut that ends on an earlier cut from
  /// one side only, instead of crossing it, makes the transitions around those interior edges of
  /// M compose to its own transition: a singular edge. Candidates with mismatched edges are then
  /// tried after all the others, and the least-area surfaces of the input's classes (computed at
  /// step 0, properly embedded in M, so crossing earlier cuts wherever they meet them) stay
  /// candidates at every later step.
  bool MatchedCuts = true;
  /// Minimise every class of the current cut mesh at every step (a cut may then be smaller than
  /// any surface of the input's classes: on 3holes the second and third cuts are 0.030 instead of
  /// 0.043). Off: only when no surface of the input passes any more (with MatchedCuts): one
  /// minimisation per class in all when the handles are apart (fertility: 1.7 s instead of 3 s).
  bool RecomputeEachStep = true;
  /// After minimising every basis class, re-minimise each class whose surface meets the
  /// smallest class's surface as class - smallest and class + smallest, keeping the smaller.
  /// A basis class may be a sum (for a hollow torus: washer + meridian annulus), whose
  /// least-area surface is one connected surface through both summands, so that the smaller
  /// summand would otherwise never be a candidate.
  bool ReduceBasis = true;
  /// When a step finds no valid cut: rounds of splitting interior edges between two boundary
  /// vertices near the failed candidates, each followed by a restart (>= 0). 0 fails instead.
  int MaxSubdivisionRounds = 2;
};

/// One cut.
struct HandleCut
{
  /// Its faces: (minus-side tet, local face); the plus-side tet is the neighbour across it.
  std::vector<std::array<int, 2>> Faces;
  /// Its boundary loops (handle loops) as closed polylines of vertex ids of Mesh (an input
  /// vertex keeps its id; split-edge midpoints follow the input's vertices), first vertex not
  /// repeated; oriented as the boundary of the cut seen with normals from minus to plus side
  /// (for positively oriented tets).
  std::vector<std::vector<int>> Loops;
  double Area = 0.0;
  int EulerCharacteristic = 0; ///< of the cut surface: 1 for a disk, 0 for an annulus
  /// Interior edges of Mesh where this cut ends on an earlier cut from one side only
  /// (section 5.3); 0 when the cut crosses earlier cuts or stays apart from them.
  int MismatchedEdgeCount = 0;
  int Beta1Before = 0; ///< beta_1 of the mesh cut by the earlier cuts
  int Beta1After = 0;  ///< after this cut too (Beta1Before - 1)
};

struct HandleCutResult
{
  int Beta1 = 0;                  ///< beta_1 of the input
  std::vector<int> BoundaryGenus; ///< genus of each boundary component of the input
  /// The mesh the cuts refer to: the input, or the input with some tets subdivided. Its first
  /// #V vertices are the input's; the midpoints of split edges follow. Tet t keeps id t for one
  /// of its halves; the other children are appended.
  TetMesh Mesh;
  /// #T' (Mesh's tets): the input tet each tet of Mesh lies in (the identity without subdivision).
  std::vector<int> OriginalCellId;
  /// Per vertex of Mesh after the input's (vertex #V + i is entry i): the two vertices whose
  /// midpoint it is (either may itself be a midpoint, of a smaller id).
  std::vector<std::array<int, 2>> MidpointParents;
  int SubdivisionRounds = 0;  ///< rounds of refinement that were needed (0: Mesh is the input)
  int SplitEdgeCount = 0;     ///< edges split in all rounds
  int SubdividedTetCount = 0; ///< input tets with more than one child in Mesh
  /// #T' by 4 (Mesh's tets): cut id of local face k of tet t, -1 if none; both tets of a cut
  /// face carry it.
  Tets CutFaces;
  /// #T' by 4: -1 on the minus side of a cut face, +1 on the plus side, 0 elsewhere.
  Tets CutSide;
  std::vector<HandleCut> Cuts;
  /// The cut mesh M_c: Mesh's tets on vertices split along every cut (same tet ids and local
  /// order), with positions, and per vertex the vertex of Mesh it copies.
  TetMesh CutMesh;
  std::vector<int> CutMeshOriginalVertex;
  int Beta1After = 0; ///< beta_1 of M_c (0), both counts agreeing
  /// Diagnostics of the last round: minimum cuts computed, classes minimised, repair moves
  /// made, candidate surfaces examined and rejected.
  int MinCutCount = 0;
  int ClassCount = 0;
  int RepairMoveCount = 0;
  int CandidateCount = 0;
  int RejectedCandidateCount = 0;
};

/// Computes the cuts. Fails when the boundary of the input is not a closed 2-manifold (naming
/// the edge or vertex), when the two beta_1 counts disagree, or when no valid cut is found at a
/// step even after MaxSubdivisionRounds rounds of subdivision (naming the step and the best
/// candidate's problem).
/// @param progress  fraction done after each cut; returning false aborts
Status ComputeHandleCuts(const TetMesh& mesh,
  const HandleCutParameters& params,
  HandleCutResult& result,
  const Progress& progress = {});

} // namespace polycubehex
