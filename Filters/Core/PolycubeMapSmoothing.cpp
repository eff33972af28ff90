// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeMapSmoothing.h"

#include "FoldoverFreeEnergy.h"
#include "TetGeometry.h"
#include "ThreadCount.h"

#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace polycubehex
{
namespace
{
/// The map's energy over the free variables y: positions x = Basis y + Constant, per tet the
/// Jacobian J = (sum_i x_i g_i^T) / Scale with g_i the gradients of the rest tet's barycentric
/// coordinates, and E = sum_t (V_t / V) f(J_t).
class MapEnergy : public ceres::FirstOrderFunction
{
public:
  MapEnergy(const Tets& cells,
    const Eigen::SparseMatrix<double>& basis,
    const Eigen::VectorXd& constant,
    const std::vector<Eigen::Matrix<double, 4, 3>>& gradients,
    const std::vector<double>& weights,
    double scale,
    double volumeWeight)
    : Cells(cells)
    , Basis(basis)
    , BasisTransposed(basis.transpose())
    , Constant(constant)
    , Gradients(gradients)
    , Weights(weights)
    , InverseScale(1.0 / scale)
    , VolumeWeight(volumeWeight)
    , X(Eigen::VectorXd::Zero(constant.size()))
    , TetEnergy(static_cast<size_t>(cells.rows()))
    , TetDet(static_cast<size_t>(cells.rows()))
    , TetGradient(static_cast<size_t>(cells.rows()))
  {
  }

  int NumParameters() const override { return static_cast<int>(this->Basis.cols()); }

  /// eps of chi; with Barrier, an evaluation where a tet is inverted fails, so that the line
  /// search stays in the valid region (once the map is untangled).
  void SetEps(double eps, bool barrier)
  {
    this->Eps = eps;
    this->Barrier = barrier;
  }

  void Positions(const double* y, Points& positions) const
  {
    const Eigen::Map<const Eigen::VectorXd> free(y, this->Basis.cols());
    Eigen::Map<Eigen::VectorXd>(positions.data(), positions.size()) =
      this->Basis * free + this->Constant;
  }

  /// The energy (and its gradient) at y; minDet receives the smallest det J.
  double Compute(const double* y, double* gradient, double& minDet) const
  {
    const Eigen::Map<const Eigen::VectorXd> free(y, this->Basis.cols());
    this->X = this->Basis * free + this->Constant;
    const int tetCount = static_cast<int>(this->Cells.rows());
    ParallelChunks(tetCount,
      2048,
      [&](int begin, int end)
      {
        Eigen::Vector3d columns[3];
        Eigen::Vector3d derivative[3];
        for (int t = begin; t < end; ++t)
        {
          Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
          for (int i = 0; i < 4; ++i)
          {
            const int v = this->Cells(t, i);
            jacobian += Eigen::Vector3d(this->X[3 * v], this->X[3 * v + 1], this->X[3 * v + 2]) *
              this->Gradients[static_cast<size_t>(t)].row(i);
          }
          jacobian *= this->InverseScale;
          for (int a = 0; a < 3; ++a)
          {
            columns[a] = jacobian.col(a);
          }
          double det = 0.0;
          const double w = this->Weights[static_cast<size_t>(t)];
          this->TetEnergy[static_cast<size_t>(t)] = w *
            JacobianEnergy(columns[0],
              columns[1],
              columns[2],
              this->Eps,
              this->VolumeWeight,
              derivative[0],
              derivative[1],
              derivative[2],
              det);
          this->TetDet[static_cast<size_t>(t)] = det;
          // dE/dx_i = w / Scale * (dE/dJ) g_i.
          Eigen::Matrix3d dJ;
          dJ << derivative[0], derivative[1], derivative[2];
          this->TetGradient[static_cast<size_t>(t)] =
            (w * this->InverseScale) * this->Gradients[static_cast<size_t>(t)] * dJ.transpose();
        }
      });
    // Sums in tet order, so that every thread count gives the same bits.
    double energy = 0.0;
    minDet = std::numeric_limits<double>::max();
    for (int t = 0; t < tetCount; ++t)
    {
      energy += this->TetEnergy[static_cast<size_t>(t)];
      minDet = std::min(minDet, this->TetDet[static_cast<size_t>(t)]);
    }
    if (gradient)
    {
      Eigen::VectorXd g = Eigen::VectorXd::Zero(this->X.size());
      for (int t = 0; t < tetCount; ++t)
      {
        for (int i = 0; i < 4; ++i)
        {
          g.segment<3>(3 * this->Cells(t, i)) +=
            this->TetGradient[static_cast<size_t>(t)].row(i).transpose();
        }
      }
      Eigen::Map<Eigen::VectorXd>(gradient, this->Basis.cols()) = this->BasisTransposed * g;
    }
    return energy;
  }

  bool Evaluate(const double* y, double* cost, double* gradient) const override
  {
    double minDet = 0.0;
    *cost = this->Compute(y, gradient, minDet);
    return std::isfinite(*cost) && !(this->Barrier && minDet <= 0.0);
  }

private:
  const Tets& Cells;
  const Eigen::SparseMatrix<double>& Basis;
  const Eigen::SparseMatrix<double> BasisTransposed;
  const Eigen::VectorXd& Constant;
  const std::vector<Eigen::Matrix<double, 4, 3>>& Gradients;
  const std::vector<double>& Weights;
  double InverseScale;
  double VolumeWeight;
  double Eps = 1e-10;
  bool Barrier = false;
  mutable Eigen::VectorXd X;
  mutable std::vector<double> TetEnergy;
  mutable std::vector<double> TetDet;
  mutable std::vector<Eigen::Matrix<double, 4, 3>> TetGradient;
};

int CountInverted(const Points& x, const Tets& cells)
{
  int count = 0;
  for (int t = 0; t < static_cast<int>(cells.rows()); ++t)
  {
    count += TetSignedVolume(x, cells, t) > 0.0 ? 0 : 1;
  }
  return count;
}

/// Cancels Ceres's solve when the caller aborts.
class AbortCallback : public ceres::IterationCallback
{
public:
  explicit AbortCallback(const Progress& progress, double fraction)
    : Report(progress)
    , Fraction(fraction)
  {
  }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override
  {
    if (!ReportProgress(this->Report, this->Fraction))
    {
      this->Aborted = true;
      return ceres::SOLVER_ABORT;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool Aborted = false;

private:
  const Progress& Report;
  double Fraction;
};
} // namespace

Status smoothPolycubeMap(const Points& rest,
  const Tets& cells,
  const Eigen::SparseMatrix<double>& freeBasis,
  const PolycubeMapSmoothingParameters& params,
  Points& positions,
  PolycubeMapSmoothingResult& result,
  const Progress& progress)
{
  result = PolycubeMapSmoothingResult();
  const Eigen::Index coordinateCount = positions.size();
  if (rest.rows() != positions.rows() || freeBasis.rows() != coordinateCount)
  {
    return Status::Failure("map smoothing: the positions, the rest positions and the free "
                           "coordinates disagree in size");
  }
  const int tetCount = static_cast<int>(cells.rows());
  if (tetCount > 0 && (cells.minCoeff() < 0 || cells.maxCoeff() >= positions.rows()))
  {
    return Status::Failure("map smoothing: a tet refers to a vertex that does not exist");
  }
  result.InvertedTetsBefore = result.InvertedTetsAfter = CountInverted(positions, cells);
  if (params.MaxRounds <= 0 || freeBasis.cols() == 0 || tetCount == 0)
  {
    return Status::Success();
  }

  // The rest tets: barycentric gradients and volume weights; the map's mean scale.
  std::vector<Eigen::Matrix<double, 4, 3>> gradients(static_cast<size_t>(tetCount));
  std::vector<double> weights(static_cast<size_t>(tetCount));
  double restVolume = 0.0;
  double mappedVolume = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    Eigen::Matrix3d edges;
    for (int i = 0; i < 3; ++i)
    {
      edges.col(i) = (rest.row(cells(t, i + 1)) - rest.row(cells(t, 0))).transpose();
    }
    const double volume = edges.determinant() / 6.0;
    if (!(volume > 0.0))
    {
      return Status::Failure("map smoothing: an input tet is flat or inverted");
    }
    const Eigen::Matrix3d inverse = edges.inverse(); // rows: gradients of barycentrics 1..3
    auto& g = gradients[static_cast<size_t>(t)];
    g.row(1) = inverse.row(0);
    g.row(2) = inverse.row(1);
    g.row(3) = inverse.row(2);
    g.row(0) = -(g.row(1) + g.row(2) + g.row(3));
    weights[static_cast<size_t>(t)] = volume;
    restVolume += volume;
    mappedVolume += TetSignedVolume(positions, cells, t);
  }
  if (!(mappedVolume > 0.0))
  {
    return Status::Failure("map smoothing: the polycube has no volume");
  }
  for (double& w : weights)
  {
    w /= restVolume;
  }
  const double scale = std::cbrt(mappedVolume / restVolume);

  // The free variables read from one of their coordinates; the rest of x stays as it is.
  std::vector<double> y(static_cast<size_t>(freeBasis.cols()), 0.0);
  std::vector<bool> seen(static_cast<size_t>(freeBasis.cols()), false);
  for (int f = 0; f < freeBasis.outerSize(); ++f)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(freeBasis, f); it; ++it)
    {
      const int column = static_cast<int>(it.col());
      if (!seen[static_cast<size_t>(column)] && it.value() != 0.0)
      {
        y[static_cast<size_t>(column)] = positions.data()[it.row()] / it.value();
        seen[static_cast<size_t>(column)] = true;
      }
    }
  }
  const Eigen::VectorXd start = Eigen::Map<const Eigen::VectorXd>(positions.data(), coordinateCount);
  const Eigen::VectorXd constant =
    start - freeBasis * Eigen::Map<const Eigen::VectorXd>(y.data(), freeBasis.cols());

  auto* energy =
    new MapEnergy(cells, freeBasis, constant, gradients, weights, scale, params.VolumeWeight);
  ceres::GradientProblem problem(energy); // owns energy
  double minDet = 0.0;
  energy->SetEps(1e-10, false);
  result.EnergyBefore = energy->Compute(y.data(), nullptr, minDet);
  // The initial eps of Garanzha et al.: a fifth of the worst inversion.
  double eps = std::sqrt(1e-12 + 0.04 * std::pow(std::min(minDet, 0.0), 2));
  double previous = std::numeric_limits<double>::max();
  int previousInverted = result.InvertedTetsBefore;
  for (int round = 0; round < params.MaxRounds; ++round)
  {
    const bool barrier = minDet > 0.0;
    energy->SetEps(eps, barrier);
    double minDetBefore = 0.0;
    const double initial = energy->Compute(y.data(), nullptr, minDetBefore);
    ceres::GradientProblemSolver::Options options;
    options.line_search_direction_type = ceres::LBFGS;
    options.max_num_iterations = std::max(1, params.IterationsPerRound);
    options.logging_type = ceres::SILENT;
    options.function_tolerance = 1e-7;
    options.gradient_tolerance = 1e-10;
    AbortCallback abort(progress, static_cast<double>(round) / params.MaxRounds);
    options.callbacks.push_back(&abort);
    ceres::GradientProblemSolver::Summary summary;
    ceres::Solve(options, problem, y.data(), &summary);
    if (abort.Aborted)
    {
      return Status::Failure("polycube map smoothing aborted");
    }
    ++result.Rounds;
    result.Iterations += static_cast<int>(summary.iterations.size());
    const double final = energy->Compute(y.data(), nullptr, minDet);
    const double decrease = initial > 0.0 ? (initial - final) / initial : 0.0;
    const bool settled = previous - final < params.Tolerance * std::fabs(final);
    previous = final;
    if (minDet > 0.0 && (decrease < params.Tolerance || settled))
    {
      break;
    }
    // A map that must come out untangled is given up once a round removes less than half of
    // the inverted tets left: where the planes force them it never reaches 0, and the
    // remaining rounds cost seconds for a result that is discarded (kitten's l1 polycube:
    // 99, 60, 55, 47, 47, 46, 43 inverted over the rounds, 12 s; elephant's hex stage 18 -> 30 s).
    // The maps that came out untangled had none left after the first round (bunny, spot).
    if (params.RequireUntangled)
    {
      Points current(positions.rows(), 3);
      energy->Positions(y.data(), current);
      const int inverted = CountInverted(current, cells);
      const bool stalled = inverted > 0 && inverted > 0.5 * previousInverted;
      previousInverted = inverted;
      if (stalled)
      {
        result.GaveUp = true;
        break;
      }
    }
    // The next eps (Garanzha et al. 2021), from the decrease and the smallest determinant.
    const double sigma = std::max(decrease, 0.1);
    double chi = 0.0;
    double chiPrime = 0.0;
    Chi(minDet, eps, chi, chiPrime);
    const double mu = (1.0 - sigma) * chi;
    eps = minDet < mu ? 2.0 * std::sqrt(mu * (mu - minDet)) : 1e-10;
  }

  Points smoothed(positions.rows(), 3);
  energy->Positions(y.data(), smoothed);
  energy->SetEps(1e-10, false);
  result.EnergyAfter = energy->Compute(y.data(), nullptr, minDet);
  const int inverted = CountInverted(smoothed, cells);
  if (inverted <= result.InvertedTetsBefore && (inverted == 0 || !params.RequireUntangled))
  {
    positions = smoothed;
    result.InvertedTetsAfter = inverted;
    result.Kept = true;
  }
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
