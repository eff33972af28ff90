// SPDX-License-Identifier: BSD-3-Clause
// The l1-polycube energy of Fang et al. 2016, eq. (9)-(13), after Huang et al. 2014, on the
// vertex positions of a tet mesh: value, analytic gradient, and a positive semi-definite
// approximation of its Hessian assembled into a sparse matrix whose pattern never changes.
// Internal to ComputePolycube (PolycubeDeformation.h).
#pragma once

#include "MeshTypes.h"

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <array>
#include <vector>

namespace polycubehex
{

/// Weights of the terms of E = Arap E_arap + Alignment E_align + NormalDifference E_diff +
/// Area E_area. All terms are dimensionless (normalised by the rest volume or boundary area).
struct PolycubeEnergyWeights
{
  double Arap = 1.0;
  double Alignment = 0.0;
  /// Smoothing of the l1 norm: |n_i| ~ sqrt(n_i^2 + eps |n|^2) per component.
  double AlignmentEpsilon = 0.01;
  double NormalDifference = 0.0;
  /// Penalty (A / A_rest - 1)^2 on the boundary area A (eq. 9's area constraint).
  double Area = 0.0;
  /// Inversion barrier: (1/#T) sum_t b(det J_t), b(d) = -(d - d0)^2 log(d / d0) for d < d0, else
  /// 0 (C2, infinite at d = 0): it lets the Newton model see a tet about to collapse.
  double Barrier = 0.0;
  double BarrierThreshold = 0.1; ///< d0, a volume ratio
  /// Penalty sum_i (x_i - target_i)^2 on the anchored coordinates (SetAnchors).
  double Anchor = 0.0;
  /// Chart-orientation barrier (1/#F) sum_f b(d_f) over the faces given a label (SetFaceLabels),
  /// d_f = the face's area projected on its label's direction / its rest area: a face must not
  /// fold over within its chart's plane while the charts are flattened.
  double FaceBarrier = 0.0;
  double FaceBarrierThreshold = 0.1;
  /// Unfolding penalty (1/#F) sum_f max(0, t - d_f)^2, t = FaceBarrierThreshold, over the faces
  /// given by SetUnfoldFaces: faces that are folded over their label's direction when the
  /// flattening starts, so that the barrier cannot hold them yet.
  double FaceUnfold = 0.0;
};

/// The value of each term at one configuration.
struct PolycubeEnergyTerms
{
  double Arap = 0.0;               ///< eq. (11): sum_t V_t / V ||J_t - polar(J_t)||^2
  double Alignment = 0.0;          ///< eq. (10), smoothed, divided by the current boundary area
  double Residual = 0.0;           ///< DESIGN.md §4: sum_f a_f (||n_f||_1 - 1) / sum_f a_f, exact
  double Difference = 0.0;         ///< eq. (12) with rest-area weights
  double Area = 0.0;               ///< (A / A_rest - 1)^2
  double Barrier = 0.0;            ///< the inversion barrier, unweighted
  double Anchor = 0.0;             ///< sum of squared anchor deviations
  double FaceBarrier = 0.0;        ///< the chart-orientation barrier, unweighted
  double FaceUnfold = 0.0;         ///< the unfolding penalty, unweighted
  double MaxAnchorDeviation = 0.0; ///< largest |x_i - target_i|
  double BoundaryArea = 0.0;       ///< current boundary area A
  double Total = 0.0;              ///< the weighted sum
};

/// A symmetric sparse pattern over 3x3 vertex blocks: entry (3v+a, 3w+b) exists for every
/// vertex pair (v, w) in the pattern. The Eigen matrix is column-major with full storage, so a
/// block entry has a fixed position in its value array.
class BlockPattern
{
public:
  /// @param vertexCount  #V
  /// @param pairs        vertex pairs (v, w) coupled by some term, both orders not needed
  void Build(int vertexCount, const std::vector<std::array<int, 2>>& pairs);

  /// The position of block (v, w) in the pair list, or -1.
  int Find(int v, int w) const;

  /// Position in the value array of entry (a, b) of block p (p from Find).
  int ValueIndex(int p, int a, int b) const { return this->Base[p] + b * this->Stride[p] + a; }

  /// A 3#V by 3#V matrix with this pattern and zero values.
  Eigen::SparseMatrix<double> ZeroMatrix() const;

  int VertexCount = 0;
  std::vector<int> Offset; ///< #V+1: pairs of column vertex w are [Offset[w], Offset[w+1])
  std::vector<int> Rows;   ///< the row vertex of each pair, sorted within a column
  std::vector<int> Base;   ///< value index of entry (0, 0) of each pair
  std::vector<int> Stride; ///< distance between the columns of a block in the value array
};

/// Two boundary faces that are neighbours on the input M but not on the cut mesh M_c: they sit
/// on the two sides of a cut's loop. Eq. (12) compares them through the cut's transition,
/// Pi n_minus against n_plus (Fang et al. §4.2: normals are transformed across cut boundaries).
struct FacePairAcrossCut
{
  int MinusFace = -1;         ///< boundary face on the cut's minus side
  int PlusFace = -1;          ///< its neighbour on M, on the plus side
  Eigen::Matrix3d Transition; ///< Pi_c
};

/// Evaluates the energy on the positions x (3#V, x[3v+a] = coordinate a of vertex v).
class PolycubeEnergy
{
public:
  /// @param rest           #V by 3 rest positions (the normalised input), positive tets
  /// @param cells          #T by 4 tets
  /// @param boundaryFaces  #F by 3 boundary triangles, oriented outwards
  /// @param acrossCuts     on a cut mesh, the neighbours across the cuts' loops, whose normal
  ///                       difference (12) is taken through the transition (empty otherwise)
  PolycubeEnergy(const Points& rest,
    const Tets& cells,
    const Triangles& boundaryFaces,
    const std::vector<FacePairAcrossCut>& acrossCuts = {});

  void SetWeights(const PolycubeEnergyWeights& weights) { this->Weights = weights; }

  /// Coordinates (indices 3v+a) pulled towards targets by the Anchor term.
  void SetAnchors(const std::vector<int>& coordinates, const std::vector<double>& targets)
  {
    this->AnchorIndex = coordinates;
    this->AnchorTarget = targets;
  }
  const PolycubeEnergyWeights& GetWeights() const { return this->Weights; }

  /// Per-tet target rotations (#T, or empty): when set, the Arap term becomes
  /// sum_t V_t / V ||J_t - R_t||^2, the least-squares (Poisson) fit of the deformation gradient
  /// to a frame field (Fang et al. eq. 7), instead of the distance to the nearest rotation.
  void SetTargetRotations(const std::vector<Eigen::Matrix3d>& rotations)
  {
    this->TargetRotation = rotations;
  }

  /// Faces (#F, labels 0..5, or -1) whose projected orientation the FaceBarrier protects.
  void SetFaceLabels(const std::vector<int>& labels) { this->FaceLabel = labels; }

  /// Faces (#F, labels 0..5, or -1) whose alignment term drops their label's axis: a labelled
  /// face is then pulled onto its label's axis (either way: FaceBarrier or FaceUnfold sets the
  /// side) instead of the nearest one. Empty: the l1 alignment of eq. (10) for every face.
  void SetAlignmentLabels(const std::vector<int>& labels) { this->AlignmentLabel = labels; }

  /// Faces (#F, labels 0..5, or -1) that the FaceUnfold penalty turns towards their label's
  /// direction. They do not count in IsFeasible.
  void SetUnfoldFaces(const std::vector<int>& labels) { this->UnfoldLabel = labels; }

  /// Smallest signed tet volume of x divided by its rest volume (> 0 when no tet is inverted or
  /// flat).
  double MinVolumeRatio(const double* x) const;

  /// Every tet positive and, with face labels set, every labelled face positively oriented on
  /// its label's direction: where the energy is finite.
  bool IsFeasible(const double* x) const;

  /// Where IsFeasible fails: the vertices (sorted, unique) of the tets whose volume ratio at x
  /// is not above `minVolumeRatio` (0: not positive) and of the labelled faces folded over their
  /// label's direction.
  std::vector<int> InfeasibleVertices(const double* x, double minVolumeRatio = 0.0) const;

  /// Projected area ratio d_f of a labelled face (see FaceBarrier).
  double FaceOrientation(const double* x, int face) const
  {
    return this->FaceOrientation(x, face, this->FaceLabel[static_cast<size_t>(face)]);
  }

  /// The face's area projected on the direction of `label` over its rest area.
  double FaceOrientation(const double* x, int face, int label) const;

  /// Energy terms at x. Returns false (terms undefined) when a tet is not positive.
  bool Evaluate(const double* x, PolycubeEnergyTerms& terms) const;

  /// Energy terms, and when `gradient` has size 3#V on entry, the gradient (overwritten) and, if
  /// `hessian` is not null, the PSD approximate Hessian (3#V by 3#V, the pattern of
  /// Pattern().ZeroMatrix(), values overwritten). The rank-one part of the area penalty's
  /// Hessian is not assembled; `areaGradient` receives the gradient of A so that a solver can
  /// add it (AreaRankOneCoefficient). Returns false (nothing defined) when x is not feasible.
  bool EvaluateDerivatives(const double* x,
    PolycubeEnergyTerms& terms,
    Eigen::VectorXd& gradient,
    Eigen::SparseMatrix<double>* hessian,
    Eigen::VectorXd* areaGradient = nullptr) const;

  /// Coefficient c of the rank-one Hessian term c a a^T of the area penalty (a = grad A).
  double AreaRankOneCoefficient() const;

  const BlockPattern& Pattern() const { return this->Blocks; }
  int VertexCount() const { return this->NumVertices; }
  double RestBoundaryArea() const { return this->RestArea; }

private:
  /// One term of eq. (12): Weight |Rotation n_0 - n_1|^2 for the faces' unit normals n_0, n_1.
  struct DiffEdge
  {
    std::array<int, 2> Faces; ///< the two boundary faces
    /// face 0's corners, then face 1's corners that are not face 0's: 4 vertices for two faces
    /// that share an edge, 6 across a cut (the shared edge is two pairs of copies)
    std::array<int, 6> Vertices;
    int VertexCount;
    std::array<int, 3> Face1Slots; ///< position in Vertices of face 1's corners
    Eigen::Matrix3d Rotation;      ///< identity, or Pi_c across a cut
    bool Rotated;                  ///< Rotation is not the identity
    double Weight;                 ///< (A_i + A_j) / (3 A)
    std::array<int, 36> Pairs;     ///< block positions of (Vertices[i], Vertices[j])
  };

  /// Signed volume of tet t at x over its rest volume.
  double VolumeRatio(const double* x, int t) const;

  void ArapTerm(const double* x,
    double& arap,
    double& barrier,
    Eigen::VectorXd* gradient,
    double* hessian) const;

  int NumVertices = 0;
  Tets Cells;
  Triangles Faces;
  PolycubeEnergyWeights Weights;
  std::vector<Eigen::Matrix3d> RestInverse; ///< Dm^-1 per tet
  std::vector<double> TetWeight;            ///< V_t / V
  std::vector<double> RestVolume;
  double RestArea = 0.0;
  std::vector<DiffEdge> DiffEdges;
  BlockPattern Blocks;
  std::vector<std::array<int, 16>> TetPairs;
  std::vector<std::array<int, 9>> FacePairs;
  std::vector<double> ArapHessianValues; ///< value array of the constant ARAP Hessian (weight 1)
  std::vector<int> FaceLabel;
  std::vector<Eigen::Matrix3d> TargetRotation;
  std::vector<int> UnfoldLabel;
  std::vector<int> AlignmentLabel;
  std::vector<double> FaceRestArea;
  std::vector<int> AnchorIndex;
  std::vector<double> AnchorTarget;
  std::vector<int> DiagonalValueIndex; ///< value index of entry (i, i), i = 3v+a
};

} // namespace polycubehex
