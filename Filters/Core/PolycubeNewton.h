// SPDX-License-Identifier: BSD-3-Clause
// A damped Newton solver for PolycubeEnergy on reduced variables x = B y + c, with a line search
// that never lets a tet become non-positive. Internal to ComputePolycube.
//
// The reduction is how hard linear relations enter without densifying the system: fixed
// coordinates (chart planes) drop out of y and move into c; a cut copy u_plus = Pi u_minus + t
// becomes rows of B that point at the minus copy's variables (with t in c, or as extra columns of
// B when t is unknown). The Hessian in y is B^T H B, as sparse as H when each row of B has few
// entries.
//
// Measured on rockerarm (30.8k tets), same schedule: this solver with BlockPcg converges
// (residual < 1e-3) in 12-14 rounds of 5 iterations, about 1.6 s per round; with the direct
// LDL^T about 7 s per round; L-BFGS (ceres::GradientProblem, 300 iterations per round) took 62 s
// and stalled at residual 4.9e-3: ARAP on a graded mesh is too ill-conditioned for it.
#pragma once

#include "PolycubeEnergy.h"
#include "Status.h"

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <memory>
#include <vector>

namespace polycubehex
{

/// x = B y + Offset. x is 3#V (x[3v+a]), y is #Y.
struct VariableReduction
{
  Eigen::SparseMatrix<double> B; ///< 3#V by #Y
  Eigen::VectorXd Offset;        ///< 3#V
  /// #Y: the coordinate axis (0..2) each variable mostly moves; the preconditioner keeps only
  /// the couplings between variables of the same axis.
  std::vector<int> VariableAxis;
  bool IsIdentity = false;

  int VariableCount() const { return static_cast<int>(this->VariableAxis.size()); }

  /// x = B y + Offset.
  Eigen::VectorXd Expand(const Eigen::VectorXd& y) const;

  /// The y whose expansion is closest to x in the least-squares sense.
  Eigen::VectorXd Restrict(const Eigen::VectorXd& x) const;

  /// y = x: no relation.
  static VariableReduction Identity(int vertexCount);

  /// Coordinates fixed[i] (an index 3v+a) are held at values[i]; every other one is a variable.
  static VariableReduction FixCoordinates(int vertexCount,
    const std::vector<int>& fixed,
    const std::vector<double>& values);

  /// Coordinates with the same group (coordinateGroup[3v+a] >= 0) are one variable, placed after
  /// the ungrouped coordinates (group g is variable #ungrouped + g); the others are their own
  /// variable. E.g. every coordinate on one chart plane is the plane's value.
  static VariableReduction ShareCoordinates(int vertexCount,
    const std::vector<int>& coordinateGroup,
    int groupCount);
};

/// Settings of one call of PolycubeNewtonSolver::Minimize.
struct NewtonSettings
{
  enum class LinearSolverType
  {
    /// Conjugate gradients on the full Newton system, preconditioned by a Cholesky factorisation
    /// of its per-axis diagonal blocks (three scalar-sized systems instead of one coupled one).
    BlockPcg,
    /// Sparse LDL^T of the full Newton system.
    Direct
  };
  LinearSolverType LinearSolver = LinearSolverType::BlockPcg;
  int MaxIterations = 10;
  /// Stop when one step lowers the energy by less than this fraction of its value.
  double RelativeDecrease = 0.0;
  /// Stop when no vertex moved more than this in one step (a length: the solver works on the
  /// unit-diagonal copy, so this is a fraction of the diagonal).
  double StepTolerance = 1e-6;
  /// Stop when the gradient's infinity norm falls below this.
  double GradientTolerance = 1e-10;
  int MaxCgIterations = 40;
  /// Factorise the preconditioner only at the first iteration of a call and reuse it (the
  /// Hessian changes little within one continuation round; CG absorbs the difference).
  bool ReusePreconditioner = true;
  /// Inexact Newton: stop CG when the residual is this fraction of the gradient.
  double CgTolerance = 0.1;
  /// Ridge added to the Newton matrix, relative to its mean diagonal (translations are free).
  double Regularization = 1e-8;
};

/// What one call of Minimize did.
struct NewtonStats
{
  int Iterations = 0;
  int CgIterations = 0;
  int Evaluations = 0;
  bool LineSearchFailed = false;
  /// Line-search halvings because the trial inverted a tet or folded a guarded face (the
  /// barrier's domain), and because the Armijo decrease was not met; step of the last accepted
  /// iteration.
  int InfeasibleTrials = 0;
  int ArmijoTrials = 0;
  double LastStep = 0.0;
  PolycubeEnergyTerms Terms;  ///< at the returned x
  double SolveSeconds = 0.0;  ///< linear solves, factorisations included
  double FactorSeconds = 0.0; ///< factorisations only
  double EvaluateSeconds = 0.0;
};

class PolycubeNewtonSolver
{
public:
  PolycubeNewtonSolver(const PolycubeEnergy& energy, const VariableReduction& reduction);
  ~PolycubeNewtonSolver();

  /// Lowers the energy from x (3#V, must satisfy the reduction and have positive tets).
  /// Returns a failure only when the callback asks to abort.
  Status Minimize(Eigen::VectorXd& x,
    const NewtonSettings& settings,
    NewtonStats& stats,
    const Progress& progress = {});

  /// One step of a homotopy that moves coordinates the reduction holds fixed: `jump` moves
  /// them (it is zero on the variables' coordinates, which x carries as they are), and the
  /// variables follow by the Newton step of the energy with the jump imposed. x moves by the
  /// largest `fraction` of 1, 1/2, 1/4, ... of that combined move that keeps every tet positive
  /// and every guarded face unfolded; fraction is 0 (x unchanged) when 30 halvings do not.
  /// `blocking`, if given, receives the vertices that made the last rejected fraction
  /// infeasible (PolycubeEnergy::InfeasibleVertices; empty when the whole move was taken).
  /// With `minVolumeRatio` > 0 a fraction is also rejected when it leaves a tet's volume ratio
  /// at or below that value: a step must not crush tets that later stages need positive.
  /// Unlike a stiff penalty pulling the fixed coordinates, the system solved here is the
  /// energy's own, which the block preconditioner handles well.
  Status Follow(Eigen::VectorXd& x,
    const Eigen::VectorXd& jump,
    const NewtonSettings& settings,
    NewtonStats& stats,
    double& fraction,
    std::vector<int>* blocking = nullptr,
    double minVolumeRatio = 0.0);

private:
  /// The Newton system in the reduced variables: B^T H B from the current Hessian (or H itself
  /// for the identity), and gy = B^T gradient, ay = B^T areaGradient.
  const Eigen::SparseMatrix<double>* ReduceSystem(const Eigen::VectorXd& gradient,
    const Eigen::VectorXd& areaGradient,
    Eigen::VectorXd& gy,
    Eigen::VectorXd& ay);

  /// Solves (hy + mu I + c a a^T) direction = rhs (mu the settings' ridge, c a a^T the area
  /// term), by LDL^T or by CG preconditioned with the axis blocks (factorised anew when
  /// `refactor`).
  Status SolveNewtonSystem(const Eigen::SparseMatrix<double>& hy,
    const Eigen::VectorXd& rhs,
    const Eigen::VectorXd& ay,
    const NewtonSettings& settings,
    bool refactor,
    NewtonStats& stats,
    Eigen::VectorXd& direction);

  struct Factorizations;
  const PolycubeEnergy& Energy;
  const VariableReduction& Reduction;
  Eigen::SparseMatrix<double> Hessian;
  std::unique_ptr<Factorizations> Solvers;
};

} // namespace polycubehex
