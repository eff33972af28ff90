// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeNewton.h"

#include "SparseCholesky.h"
#include "ThreadCount.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <thread>

namespace polycubehex
{

using SparseMatrix = Eigen::SparseMatrix<double>;

namespace
{
double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Runs task(i) for i in [0, count) on up to `count` threads.
template<typename Task>
void RunTasks(int count, const Task& task)
{
  const int threads = std::min(count, static_cast<int>(ThreadCount()));
  if (threads <= 1)
  {
    for (int i = 0; i < count; ++i)
    {
      task(i);
    }
    return;
  }
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
  {
    workers.emplace_back(
      [&task, t, threads, count]()
      {
        for (int i = t; i < count; i += threads)
        {
          task(i);
        }
      });
  }
  for (int i = 0; i < count; i += threads)
  {
    task(i);
  }
  for (auto& worker : workers)
  {
    worker.join();
  }
}

/// out = m v for a symmetric matrix stored in full: each entry is the dot product of a column
/// with v, so rows can be split over threads without changing a bit of the result.
void SymmetricProduct(const SparseMatrix& m, const Eigen::VectorXd& v, Eigen::VectorXd& out)
{
  out.resize(m.cols());
  const int n = static_cast<int>(m.cols());
  const int chunks = n < 20000 ? 1 : 4;
  const auto* outer = m.outerIndexPtr();
  const auto* inner = m.innerIndexPtr();
  const double* values = m.valuePtr();
  RunTasks(chunks,
    [&](int chunk)
    {
      const int begin = static_cast<int>(static_cast<long>(n) * chunk / chunks);
      const int end = static_cast<int>(static_cast<long>(n) * (chunk + 1) / chunks);
      for (int col = begin; col < end; ++col)
      {
        double sum = 0.0;
        for (auto k = outer[col]; k < outer[col + 1]; ++k)
        {
          sum += values[k] * v(inner[k]);
        }
        out(col) = sum;
      }
    });
}
} // namespace

/// The per-axis diagonal blocks of the Newton matrix, factorised separately (and in parallel) by
/// CHOLMOD (SparseCholesky.h).
class AxisBlockPreconditioner
{
public:
  /// Factorises the blocks of hy + mu I; false if a block is not positive definite.
  bool Factorize(const SparseMatrix& hy, const std::vector<int>& axis, double mu)
  {
    const SerialOpenMPScope serial; // the three blocks are factorised in parallel already
    if (hy.nonZeros() != this->SourceNonZeros)
    {
      this->Build(hy, axis);
    }
    const double* source = hy.valuePtr();
    for (int a = 0; a < 3; ++a)
    {
      std::fill(
        this->Blocks[a].valuePtr(), this->Blocks[a].valuePtr() + this->Blocks[a].nonZeros(), 0.0);
    }
    for (size_t k = 0; k < this->ValueMap.size(); ++k)
    {
      const auto& target = this->ValueMap[k];
      if (target.first >= 0)
      {
        this->Blocks[static_cast<size_t>(target.first)].valuePtr()[target.second] = source[k];
      }
    }
    bool ok[3] = { true, true, true };
    RunTasks(3,
      [&](int a)
      {
        if (this->Blocks[static_cast<size_t>(a)].rows() == 0)
        {
          return;
        }
        ok[a] =
          this->Solvers[static_cast<size_t>(a)].Factorize(this->Blocks[static_cast<size_t>(a)], mu);
      });
    return ok[0] && ok[1] && ok[2];
  }

  Eigen::VectorXd Solve(const Eigen::VectorXd& r) const
  {
    Eigen::VectorXd z(r.size());
    RunTasks(3,
      [&](int a)
      {
        const auto& vars = this->Variables[static_cast<size_t>(a)];
        if (vars.empty())
        {
          return;
        }
        Eigen::VectorXd local(static_cast<Eigen::Index>(vars.size()));
        for (size_t i = 0; i < vars.size(); ++i)
        {
          local(static_cast<Eigen::Index>(i)) = r(vars[i]);
        }
        local = this->Solvers[static_cast<size_t>(a)].Solve(local);
        for (size_t i = 0; i < vars.size(); ++i)
        {
          z(vars[i]) = local(static_cast<Eigen::Index>(i));
        }
      });
    return z;
  }

private:
  void Build(const SparseMatrix& hy, const std::vector<int>& axis)
  {
    const int n = static_cast<int>(hy.cols());
    std::vector<int> local(static_cast<size_t>(n));
    for (auto& vars : this->Variables)
    {
      vars.clear();
    }
    for (int i = 0; i < n; ++i)
    {
      auto& vars = this->Variables[static_cast<size_t>(axis[static_cast<size_t>(i)])];
      local[static_cast<size_t>(i)] = static_cast<int>(vars.size());
      vars.push_back(i);
    }
    std::array<std::vector<Eigen::Triplet<double>>, 3> triplets;
    for (int col = 0; col < n; ++col)
    {
      const int a = axis[static_cast<size_t>(col)];
      for (SparseMatrix::InnerIterator it(hy, col); it; ++it)
      {
        if (axis[static_cast<size_t>(it.row())] == a)
        {
          triplets[static_cast<size_t>(a)].emplace_back(
            local[static_cast<size_t>(it.row())], local[static_cast<size_t>(col)], 0.0);
        }
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      const auto size = static_cast<Eigen::Index>(this->Variables[static_cast<size_t>(a)].size());
      this->Blocks[static_cast<size_t>(a)].resize(size, size);
      this->Blocks[static_cast<size_t>(a)].setFromTriplets(
        triplets[static_cast<size_t>(a)].begin(), triplets[static_cast<size_t>(a)].end());
      this->Blocks[static_cast<size_t>(a)].makeCompressed();
      if (size > 0)
      {
        this->Solvers[static_cast<size_t>(a)].AnalyzePattern(this->Blocks[static_cast<size_t>(a)]);
      }
    }
    // Entries of a block column come in the same (increasing row) order as in hy's column.
    this->ValueMap.assign(static_cast<size_t>(hy.nonZeros()), { -1, -1 });
    for (int col = 0; col < n; ++col)
    {
      const int a = axis[static_cast<size_t>(col)];
      int next =
        this->Blocks[static_cast<size_t>(a)].outerIndexPtr()[local[static_cast<size_t>(col)]];
      for (auto k = hy.outerIndexPtr()[col]; k < hy.outerIndexPtr()[col + 1]; ++k)
      {
        if (axis[static_cast<size_t>(hy.innerIndexPtr()[k])] == a)
        {
          this->ValueMap[static_cast<size_t>(k)] = { a, next++ };
        }
      }
    }
    this->SourceNonZeros = hy.nonZeros();
  }

  std::array<std::vector<int>, 3> Variables;
  std::array<SparseMatrix, 3> Blocks;
  std::array<SparseCholesky, 3> Solvers;
  std::vector<std::pair<int, int>> ValueMap;
  Eigen::Index SourceNonZeros = -1;
};

Eigen::VectorXd VariableReduction::Expand(const Eigen::VectorXd& y) const
{
  if (this->IsIdentity)
  {
    return y;
  }
  return this->B * y + this->Offset;
}

Eigen::VectorXd VariableReduction::Restrict(const Eigen::VectorXd& x) const
{
  if (this->IsIdentity)
  {
    return x;
  }
  const SparseMatrix bt = this->B.transpose();
  const SparseMatrix normal = bt * this->B;
  Eigen::SimplicialLDLT<SparseMatrix> solver(normal);
  return solver.solve(bt * (x - this->Offset));
}

VariableReduction VariableReduction::Identity(int vertexCount)
{
  VariableReduction reduction;
  const int n = 3 * vertexCount;
  reduction.B.resize(n, n);
  reduction.B.setIdentity();
  reduction.Offset.setZero(n);
  reduction.VariableAxis.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    reduction.VariableAxis[static_cast<size_t>(i)] = i % 3;
  }
  reduction.IsIdentity = true;
  return reduction;
}

VariableReduction VariableReduction::FixCoordinates(int vertexCount,
  const std::vector<int>& fixed,
  const std::vector<double>& values)
{
  VariableReduction reduction;
  const int n = 3 * vertexCount;
  std::vector<int> column(static_cast<size_t>(n), 0);
  reduction.Offset.setZero(n);
  for (size_t i = 0; i < fixed.size(); ++i)
  {
    column[static_cast<size_t>(fixed[i])] = -1;
    reduction.Offset(fixed[i]) = values[i];
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < n; ++i)
  {
    if (column[static_cast<size_t>(i)] == 0)
    {
      triplets.emplace_back(i, static_cast<int>(reduction.VariableAxis.size()), 1.0);
      reduction.VariableAxis.push_back(i % 3);
    }
  }
  reduction.B.resize(n, static_cast<int>(reduction.VariableAxis.size()));
  reduction.B.setFromTriplets(triplets.begin(), triplets.end());
  return reduction;
}

VariableReduction VariableReduction::ShareCoordinates(int vertexCount,
  const std::vector<int>& coordinateGroup,
  int groupCount)
{
  VariableReduction reduction;
  const int n = 3 * vertexCount;
  reduction.Offset.setZero(n);
  std::vector<int> column(static_cast<size_t>(n), -1);
  for (int i = 0; i < n; ++i)
  {
    if (coordinateGroup[static_cast<size_t>(i)] < 0)
    {
      column[static_cast<size_t>(i)] = static_cast<int>(reduction.VariableAxis.size());
      reduction.VariableAxis.push_back(i % 3);
    }
  }
  const int ungrouped = static_cast<int>(reduction.VariableAxis.size());
  reduction.VariableAxis.resize(static_cast<size_t>(ungrouped + groupCount), 0);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < n; ++i)
  {
    const int group = coordinateGroup[static_cast<size_t>(i)];
    if (group >= 0)
    {
      column[static_cast<size_t>(i)] = ungrouped + group;
      reduction.VariableAxis[static_cast<size_t>(ungrouped + group)] = i % 3;
    }
    triplets.emplace_back(i, column[static_cast<size_t>(i)], 1.0);
  }
  reduction.B.resize(n, ungrouped + groupCount);
  reduction.B.setFromTriplets(triplets.begin(), triplets.end());
  return reduction;
}

/// B^T H B for a fixed B and a fixed pattern of H, by a precomputed scatter: each entry of H
/// adds coefficient * value at fixed positions of the result. A general sparse triple product
/// per Newton iteration cost more than the rest of the iteration on a cut mesh (kitten).
class ReducedHessian
{
public:
  void Compute(const SparseMatrix& b,
    const SparseMatrix& bt,
    const SparseMatrix& h,
    SparseMatrix& out)
  {
    if (!this->Ready)
    {
      out = bt * h * b; // the pattern, once
      out.makeCompressed();
      this->Build(bt, h, out);
      return;
    }
    std::fill(out.valuePtr(), out.valuePtr() + out.nonZeros(), 0.0);
    const double* source = h.valuePtr();
    double* target = out.valuePtr();
    for (const Entry& e : this->Entries)
    {
      target[e.Target] += e.Coefficient * source[e.Source];
    }
  }

private:
  struct Entry
  {
    int Source;
    int Target;
    double Coefficient;
  };

  void Build(const SparseMatrix& bt, const SparseMatrix& h, const SparseMatrix& out)
  {
    this->Entries.clear();
    for (int j = 0; j < h.outerSize(); ++j)
    {
      for (auto k = h.outerIndexPtr()[j]; k < h.outerIndexPtr()[j + 1]; ++k)
      {
        const int i = h.innerIndexPtr()[k];
        // Row i of B is column i of B^T.
        for (SparseMatrix::InnerIterator bi(bt, i); bi; ++bi)
        {
          for (SparseMatrix::InnerIterator bj(bt, j); bj; ++bj)
          {
            const int row = static_cast<int>(bi.row());
            const int col = static_cast<int>(bj.row());
            const int* begin = out.innerIndexPtr() + out.outerIndexPtr()[col];
            const int* end = out.innerIndexPtr() + out.outerIndexPtr()[col + 1];
            const int* found = std::lower_bound(begin, end, row);
            if (found == end || *found != row)
            {
              return; // cannot happen; keep the general product
            }
            this->Entries.push_back({ static_cast<int>(k),
              static_cast<int>(found - out.innerIndexPtr()),
              bi.value() * bj.value() });
          }
        }
      }
    }
    this->Ready = true;
  }

  std::vector<Entry> Entries;
  bool Ready = false;
};

struct PolycubeNewtonSolver::Factorizations
{
  SparseMatrix Bt;
  SparseMatrix TrialHessian; ///< the Hessian at the line search's first trial
  SparseMatrix Reduced;      ///< B^T H B when the reduction is not the identity
  ReducedHessian ReducedProduct;
  AxisBlockPreconditioner Preconditioner;
  Eigen::SimplicialLDLT<SparseMatrix> DirectSolver;
  bool DirectAnalyzed = false;
  bool PreconditionerFactorized = false;
};

PolycubeNewtonSolver::PolycubeNewtonSolver(const PolycubeEnergy& energy,
  const VariableReduction& reduction)
  : Energy(energy)
  , Reduction(reduction)
  , Hessian(energy.Pattern().ZeroMatrix())
  , Solvers(new Factorizations)
{
  this->Solvers->TrialHessian = this->Hessian;
  if (!reduction.IsIdentity)
  {
    this->Solvers->Bt = reduction.B.transpose();
  }
}

PolycubeNewtonSolver::~PolycubeNewtonSolver() = default;

Status PolycubeNewtonSolver::Follow(Eigen::VectorXd& x,
  const Eigen::VectorXd& jump,
  const NewtonSettings& settings,
  NewtonStats& stats,
  double& fraction,
  std::vector<int>* blocking,
  double minVolumeRatio)
{
  stats = NewtonStats();
  fraction = 0.0;
  const VariableReduction& reduction = this->Reduction;
  Factorizations& solvers = *this->Solvers;
  const int n = static_cast<int>(x.size());
  Eigen::VectorXd gradient(n);
  Eigen::VectorXd areaGradient(n);
  PolycubeEnergyTerms terms;
  auto evaluateStart = std::chrono::steady_clock::now();
  if (!this->Energy.EvaluateDerivatives(x.data(), terms, gradient, &this->Hessian, &areaGradient))
  {
    return Status::Failure("the polycube solver was started from a mesh with a non-positive tet");
  }
  stats.EvaluateSeconds += SecondsSince(evaluateStart);
  ++stats.Evaluations;
  stats.Terms = terms;

  // The quadratic model at x + jump + B dy: its gradient in y is B^T (g + H jump) + B^T H B dy
  // (plus the rank-one area term's share of the jump).
  const auto solveStart = std::chrono::steady_clock::now();
  Eigen::VectorXd pushed = gradient + this->Hessian * jump;
  const double rankOne = this->Energy.AreaRankOneCoefficient();
  if (rankOne != 0.0)
  {
    pushed += (rankOne * areaGradient.dot(jump)) * areaGradient;
  }
  Eigen::VectorXd gy, ay;
  const SparseMatrix* hy = this->ReduceSystem(pushed, areaGradient, gy, ay);
  Eigen::VectorXd direction;
  // The factorisation of the previous Minimize call (nearly the same Hessian) serves CG here.
  const bool refactor = !settings.ReusePreconditioner || !solvers.PreconditionerFactorized;
  const Status solved = this->SolveNewtonSystem(*hy, -gy, ay, settings, refactor, stats, direction);
  if (!solved)
  {
    return solved;
  }
  stats.SolveSeconds += SecondsSince(solveStart);
  const Eigen::VectorXd dx =
    jump + (reduction.IsIdentity ? direction : Eigen::VectorXd(reduction.B * direction));

  // The largest fraction of the move that keeps the barrier's domain.
  double step = 1.0;
  Eigen::VectorXd rejected;
  for (int attempt = 0; attempt < 30; ++attempt, step *= 0.5)
  {
    Eigen::VectorXd trial = x + step * dx;
    if (this->Energy.IsFeasible(trial.data()) &&
      (minVolumeRatio <= 0.0 || this->Energy.MinVolumeRatio(trial.data()) > minVolumeRatio))
    {
      x.swap(trial);
      fraction = step;
      stats.LastStep = step;
      ++stats.Iterations;
      break;
    }
    ++stats.InfeasibleTrials;
    rejected.swap(trial);
  }
  stats.LineSearchFailed = fraction == 0.0;
  if (blocking)
  {
    blocking->clear();
    if (rejected.size() > 0)
    {
      *blocking = this->Energy.InfeasibleVertices(rejected.data(), minVolumeRatio);
    }
  }
  return Status::Success();
}

const SparseMatrix* PolycubeNewtonSolver::ReduceSystem(const Eigen::VectorXd& gradient,
  const Eigen::VectorXd& areaGradient,
  Eigen::VectorXd& gy,
  Eigen::VectorXd& ay)
{
  if (this->Reduction.IsIdentity)
  {
    gy = gradient;
    ay = areaGradient;
    return &this->Hessian;
  }
  Factorizations& solvers = *this->Solvers;
  solvers.ReducedProduct.Compute(this->Reduction.B, solvers.Bt, this->Hessian, solvers.Reduced);
  gy = solvers.Bt * gradient;
  ay = solvers.Bt * areaGradient;
  return &solvers.Reduced;
}

Status PolycubeNewtonSolver::SolveNewtonSystem(const SparseMatrix& hy,
  const Eigen::VectorXd& rhs,
  const Eigen::VectorXd& ay,
  const NewtonSettings& settings,
  bool refactor,
  NewtonStats& stats,
  Eigen::VectorXd& direction)
{
  const double mu = settings.Regularization * hy.diagonal().mean() + 1e-300;
  const double rankOne = this->Energy.AreaRankOneCoefficient();
  Factorizations& solvers = *this->Solvers;
  direction = Eigen::VectorXd::Zero(rhs.size());

  if (settings.LinearSolver == NewtonSettings::LinearSolverType::Direct)
  {
    SparseMatrix m = hy;
    m.diagonal().array() += mu;
    if (!solvers.DirectAnalyzed)
    {
      solvers.DirectSolver.analyzePattern(m);
      solvers.DirectAnalyzed = true;
    }
    solvers.DirectSolver.factorize(m);
    direction = solvers.DirectSolver.solve(rhs);
    if (rankOne != 0.0)
    {
      // Sherman-Morrison for the rank-one area term c a a^T.
      const Eigen::VectorXd z = solvers.DirectSolver.solve(ay);
      direction -= z * (rankOne * ay.dot(direction) / (1.0 + rankOne * ay.dot(z)));
    }
  }
  else
  {
    const auto factorStart = std::chrono::steady_clock::now();
    if (refactor)
    {
      solvers.PreconditionerFactorized = false;
      if (!solvers.Preconditioner.Factorize(hy, this->Reduction.VariableAxis, mu))
      {
        return Status::Failure("the polycube solver's preconditioner is not positive definite");
      }
      solvers.PreconditionerFactorized = true;
    }
    stats.FactorSeconds += SecondsSince(factorStart);
    auto apply = [&](const Eigen::VectorXd& v)
    {
      Eigen::VectorXd out;
      SymmetricProduct(hy, v, out);
      out += mu * v;
      if (rankOne != 0.0)
      {
        out += (rankOne * ay.dot(v)) * ay;
      }
      return out;
    };
    Eigen::VectorXd r = rhs;
    const double stop = settings.CgTolerance * r.norm();
    Eigen::VectorXd z = solvers.Preconditioner.Solve(r);
    Eigen::VectorXd p = z;
    double rz = r.dot(z);
    for (int k = 0; k < settings.MaxCgIterations; ++k)
    {
      const Eigen::VectorXd q = apply(p);
      const double pq = p.dot(q);
      if (!(pq > 0.0))
      {
        if (k == 0)
        {
          direction = z;
        }
        break;
      }
      const double alpha = rz / pq;
      direction += alpha * p;
      r -= alpha * q;
      ++stats.CgIterations;
      if (r.norm() <= stop)
      {
        break;
      }
      z = solvers.Preconditioner.Solve(r);
      const double rzNext = r.dot(z);
      p = z + (rzNext / rz) * p;
      rz = rzNext;
    }
  }
  return Status::Success();
}

Status PolycubeNewtonSolver::Minimize(Eigen::VectorXd& x,
  const NewtonSettings& settings,
  NewtonStats& stats,
  const Progress& progress)
{
  stats = NewtonStats();
  const VariableReduction& reduction = this->Reduction;
  Factorizations& solvers = *this->Solvers;
  const int n = static_cast<int>(x.size());
  Eigen::VectorXd gradient(n);
  Eigen::VectorXd areaGradient(n);
  Eigen::VectorXd trialGradient(n);
  Eigen::VectorXd trialAreaGradient(n);
  PolycubeEnergyTerms terms;

  auto evaluateStart = std::chrono::steady_clock::now();
  bool ok =
    this->Energy.EvaluateDerivatives(x.data(), terms, gradient, &this->Hessian, &areaGradient);
  stats.EvaluateSeconds += SecondsSince(evaluateStart);
  ++stats.Evaluations;
  if (!ok)
  {
    return Status::Failure("the polycube solver was started from a mesh with a non-positive tet");
  }
  stats.Terms = terms;

  for (int iteration = 0; iteration < settings.MaxIterations; ++iteration)
  {
    const auto solveStart = std::chrono::steady_clock::now();
    Eigen::VectorXd gy, ay;
    const SparseMatrix* hy = this->ReduceSystem(gradient, areaGradient, gy, ay);
    if (gy.lpNorm<Eigen::Infinity>() < settings.GradientTolerance)
    {
      break;
    }
    Eigen::VectorXd direction;
    const Status solved = this->SolveNewtonSystem(
      *hy, -gy, ay, settings, iteration == 0 || !settings.ReusePreconditioner, stats, direction);
    if (!solved)
    {
      return solved;
    }
    stats.SolveSeconds += SecondsSince(solveStart);

    const double slope = gy.dot(direction);
    if (!(slope < 0.0))
    {
      direction = -gy;
    }
    const Eigen::VectorXd dx =
      reduction.IsIdentity ? direction : Eigen::VectorXd(reduction.B * direction);
    const double descent = gradient.dot(dx);
    const int evaluationsBefore = stats.Evaluations;

    // Backtracking: first stay positive, then Armijo. The first trial is evaluated with its
    // derivatives (it is nearly always accepted, and the next iteration needs them), except
    // after the last iteration, which needs only the energy.
    evaluateStart = std::chrono::steady_clock::now();
    const bool another = iteration + 1 < settings.MaxIterations;
    double step = 1.0;
    bool accepted = false;
    bool derivativesAtTrial = false;
    Eigen::VectorXd trial(n);
    PolycubeEnergyTerms trialTerms;
    for (int attempt = 0; attempt < 40; ++attempt, step *= 0.5)
    {
      trial = x + step * dx;
      if (!this->Energy.IsFeasible(trial.data()))
      {
        ++stats.InfeasibleTrials;
        continue;
      }
      ++stats.Evaluations;
      derivativesAtTrial = another && stats.Evaluations == evaluationsBefore + 1;
      const bool evaluated = derivativesAtTrial
        ? this->Energy.EvaluateDerivatives(
            trial.data(), trialTerms, trialGradient, &solvers.TrialHessian, &trialAreaGradient)
        : this->Energy.Evaluate(trial.data(), trialTerms);
      if (!evaluated)
      {
        continue;
      }
      if (trialTerms.Total <= terms.Total + 1e-4 * step * descent)
      {
        accepted = true;
        break;
      }
      ++stats.ArmijoTrials;
    }
    if (!accepted)
    {
      stats.EvaluateSeconds += SecondsSince(evaluateStart);
      stats.LineSearchFailed = true;
      break;
    }
    const double previous = terms.Total;
    x.swap(trial);
    ++stats.Iterations;
    stats.LastStep = step;
    terms = trialTerms;
    if (derivativesAtTrial)
    {
      gradient.swap(trialGradient);
      areaGradient.swap(trialAreaGradient);
      this->Hessian.swap(solvers.TrialHessian);
    }
    else if (another)
    {
      this->Energy.EvaluateDerivatives(x.data(), terms, gradient, &this->Hessian, &areaGradient);
      ++stats.Evaluations;
    }
    stats.EvaluateSeconds += SecondsSince(evaluateStart);
    stats.Terms = terms;
    if (!ReportProgress(progress, static_cast<double>(iteration + 1) / settings.MaxIterations))
    {
      return Status::Failure("aborted");
    }
    if (previous - terms.Total < settings.RelativeDecrease * std::abs(previous) ||
      step * dx.lpNorm<Eigen::Infinity>() < settings.StepTolerance)
    {
      break;
    }
  }
  return Status::Success();
}

} // namespace polycubehex
