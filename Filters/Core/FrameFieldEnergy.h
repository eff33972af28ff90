// SPDX-License-Identifier: BSD-3-Clause
// Energy (1) of Fang et al. 2016 on unconstrained 3x3 matrices R_t (one per tet, rows = axes):
//   w_f (2) smoothness ||R_i - R_j||^2 on interior faces that are not cut faces,
//   w_c (3) the cube-symmetric h on the columns of R_plus R_minus^T on cut faces,
//   w_a (4) the smoothed l1 norm of R_t n_f on boundary faces,
//   w_d (5) ||R_i n_i - R_j n_j||^2 on boundary edges not on a cut,
//   w_R      ||R_t^T R_t - I||^2,
// each normalised by its total volume, area or face weight as in the paper, with an analytic
// gradient; and its minimisation by Ceres' L-BFGS. Internal to ComputeFrameField (FrameField.h).
#pragma once

#include "MeshTypes.h"
#include "Status.h"
#include "TetGeometry.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace polycubehex
{

/// The weights of eq. (1) that the paper fixes; w_f = V_F / (V_F + V_C) and w_c = V_C / (V_F + V_C)
/// follow from the mesh and the cuts.
struct FrameFieldEnergyWeights
{
  double Alignment = 0.1;         ///< w_a, eq. (4)
  double NormalDifference = 0.01; ///< w_d, eq. (5)
  /// (5) skips boundary edges whose two face normals are more than this apart (degrees).
  double NormalDifferenceMaxAngle = 45.0;
  double Orthogonality = 1.0;     ///< w_R
  double L1Epsilon = 1e-3;        ///< eps in |u| ~ sqrt(u^2 + eps)
};

/// The value of each weighted term.
struct FrameFieldEnergyTerms
{
  double Smoothness = 0.0;       ///< w_f * (2)
  double Cut = 0.0;              ///< w_c * (3)
  double Alignment = 0.0;        ///< w_a * (4)
  double NormalDifference = 0.0; ///< w_d * (5)
  double Orthogonality = 0.0;    ///< w_R * orthogonality
  double Total = 0.0;
};

class FrameFieldEnergy
{
public:
  /// @param mesh      #V by 3 vertices, #T by 4 positively oriented tets (any scale: every term
  ///                  is normalised, and (2), (3) are invariant under a uniform scaling)
  /// @param topology  ComputeTetTopology(mesh)
  /// @param faceCut   #T by 4 cut id of local face k, -1 if none (0 rows: no cuts)
  /// @param faceSide  #T by 4 side of that face: -1 minus, +1 plus (ignored where faceCut < 0)
  FrameFieldEnergy(const TetMesh& mesh,
    const TetTopology& topology,
    const Tets& faceCut,
    const Tets& faceSide,
    const FrameFieldEnergyWeights& weights);

  int TetCount() const { return this->NumberOfTets; }
  /// 9 #T: tet t owns x[9t .. 9t+8], its R row-major.
  int VariableCount() const { return 9 * this->NumberOfTets; }

  /// The energy at x, and its gradient if `gradient` is not null (same layout as x).
  double Evaluate(const double* x, double* gradient, FrameFieldEnergyTerms* terms = nullptr) const;

  /// Per tet, an estimate of the diagonal of the Hessian near a matched, aligned field (the same
  /// for its 9 variables): the minimiser scales the variables by its square root, which evens out
  /// tets of different sizes.
  std::vector<double> DiagonalEstimate() const;

  int SmoothFaceCount() const { return static_cast<int>(this->SmoothFaces.size()); }
  int CutFaceCount() const { return static_cast<int>(this->CutFaces.size()); }
  int NormalPairCount() const { return static_cast<int>(this->NormalPairs.size()); }

private:
  struct FacePair
  {
    int A, B; // for a cut face A is the minus side, B the plus side
    double Weight;
  };
  struct BoundaryTerm
  {
    int Tet;
    double Normal[3];
    double Weight;
  };
  struct NormalPair
  {
    int TetA, TetB;
    double NormalA[3], NormalB[3];
    double Weight;
  };
  int NumberOfTets = 0;
  double Epsilon = 1e-3;
  std::vector<FacePair> SmoothFaces;
  std::vector<FacePair> CutFaces;
  std::vector<BoundaryTerm> BoundaryTerms;
  std::vector<NormalPair> NormalPairs;
  std::vector<double> OrthogonalityWeights; // #T: w_R V_t / V
};

/// What the minimisation did.
struct FrameFieldMinimization
{
  int Iterations = 0;
  double InitialEnergy = 0.0;
  double FinalEnergy = 0.0;
  double FinalGradientNorm = 0.0; ///< L2 norm of the gradient at the result
  bool Converged = false;         ///< the gradient tolerance was reached
  std::string Report;             ///< Ceres' one-line report
};

/// Minimises the energy from x with Ceres' L-BFGS (ceres::GradientProblem) until the L2 norm of
/// the gradient falls below `gradientTolerance` or `maxIterations` is reached. A stop for another
/// reason (line search failure at rounding level) keeps the best point and is not an error.
/// @param x  9 #T variables, the start on input and the result on output
Status MinimizeFrameFieldEnergy(const FrameFieldEnergy& energy,
  std::vector<double>& x,
  double gradientTolerance,
  int maxIterations,
  FrameFieldMinimization& summary,
  const Progress& progress = {});

} // namespace polycubehex
