// SPDX-License-Identifier: BSD-3-Clause
#include "HexUntangling.h"

#include "FoldoverFreeEnergy.h"
#include "HexScaledJacobian.h"
#include "ThreadCount.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace polycubehex
{
namespace
{
using HexCorners = Eigen::Matrix<double, 8, 3, Eigen::RowMajor>;

/// The corners whose sum minus the other four's gives the centre's axis a (principal axes of
/// HexScaledJacobian: x, y, z of a box in VTK order).
constexpr int CentrePlus[3][4] = { { 1, 2, 5, 6 }, { 2, 3, 6, 7 }, { 4, 5, 6, 7 } };
constexpr int CentreMinus[3][4] = { { 0, 3, 4, 7 }, { 0, 1, 4, 5 }, { 0, 1, 2, 3 } };

/// The energy of one hex (corners x in VTK order, J scaled by 1 / its size) and its gradient
/// with respect to the corners; `minDet` receives the smallest of its nine determinants.
double HexEnergy(const HexCorners& x,
  double inverseSize,
  double eps,
  double volumeWeight,
  HexCorners& gradient,
  double& minDet)
{
  gradient.setZero();
  minDet = std::numeric_limits<double>::max();
  double energy = 0.0;
  Eigen::Vector3d ga;
  Eigen::Vector3d gb;
  Eigen::Vector3d gc;
  double det = 0.0;
  for (int k = 0; k < 8; ++k)
  {
    const int* n = HexCornerNeighbours[k];
    const Eigen::Vector3d origin = x.row(k).transpose();
    energy += JacobianEnergy((x.row(n[0]).transpose() - origin) * inverseSize,
      (x.row(n[1]).transpose() - origin) * inverseSize,
      (x.row(n[2]).transpose() - origin) * inverseSize,
      eps,
      volumeWeight,
      ga,
      gb,
      gc,
      det);
    minDet = std::min(minDet, det);
    gradient.row(n[0]) += inverseSize * ga.transpose();
    gradient.row(n[1]) += inverseSize * gb.transpose();
    gradient.row(n[2]) += inverseSize * gc.transpose();
    gradient.row(k) -= inverseSize * (ga + gb + gc).transpose();
  }
  // The centre: the principal axes, each the sum of four edges, so a quarter of it per edge.
  const double quarter = 0.25 * inverseSize;
  Eigen::Vector3d axes[3];
  for (int a = 0; a < 3; ++a)
  {
    axes[a].setZero();
    for (int i = 0; i < 4; ++i)
    {
      axes[a] += (x.row(CentrePlus[a][i]) - x.row(CentreMinus[a][i])).transpose();
    }
    axes[a] *= quarter;
  }
  energy += JacobianEnergy(axes[0], axes[1], axes[2], eps, volumeWeight, ga, gb, gc, det);
  minDet = std::min(minDet, det);
  const Eigen::Vector3d* g[3] = { &ga, &gb, &gc };
  for (int a = 0; a < 3; ++a)
  {
    for (int i = 0; i < 4; ++i)
    {
      gradient.row(CentrePlus[a][i]) += quarter * g[a]->transpose();
      gradient.row(CentreMinus[a][i]) -= quarter * g[a]->transpose();
    }
  }
  return energy;
}

/// The energy over the free coordinates y of one round: a free vertex is at Base + Basis y_v,
/// with 3 coordinates inside, 2 in its chart's tangent plane, 1 along its feature curve.
class RoundEnergy
{
public:
  RoundEnergy(const Hexes& cells,
    const std::vector<double>& inverseSize,
    const std::vector<int>& incidenceStart,
    const std::vector<int>& incidence,
    double volumeWeight)
    : Cells(cells)
    , InverseSize(inverseSize)
    , IncidenceStart(incidenceStart)
    , Incidence(incidence)
    , VolumeWeight(volumeWeight)
    , HexValue(static_cast<size_t>(cells.rows()))
    , HexMinDet(static_cast<size_t>(cells.rows()))
    , HexGradient(static_cast<size_t>(cells.rows()))
  {
  }

  /// Starts a round at `positions`: vertex v gets dofs[v] coordinates along the first columns
  /// of bases[v].
  void Start(const Points& positions,
    const std::vector<int>& dofs,
    const std::vector<Eigen::Matrix3d>& bases,
    double eps)
  {
    this->Base = positions;
    this->X = positions;
    this->Bases = bases;
    this->Eps = eps;
    this->Offset.assign(dofs.size(), -1);
    this->Count = 0;
    this->Free.clear();
    for (size_t v = 0; v < dofs.size(); ++v)
    {
      if (dofs[v] > 0)
      {
        this->Offset[v] = this->Count;
        this->Free.push_back(static_cast<int>(v));
        this->Count += dofs[v];
      }
    }
    this->Dofs = dofs;
  }

  int Parameters() const { return this->Count; }
  double Epsilon() const { return this->Eps; }

  /// The positions at y.
  void Positions(const double* y, Points& x) const
  {
    x = this->Base;
    for (int v : this->Free)
    {
      const double* t = y + this->Offset[static_cast<size_t>(v)];
      for (int d = 0; d < this->Dofs[static_cast<size_t>(v)]; ++d)
      {
        x.row(v) += t[d] * this->Bases[static_cast<size_t>(v)].col(d).transpose();
      }
    }
  }

  /// The energy at y, its gradient (if set) and the smallest determinant of any Jacobian.
  double Evaluate(const double* y, double* gradient, double& minDet) const
  {
    this->Positions(y, this->X);
    const int hexCount = static_cast<int>(this->Cells.rows());
    ParallelChunks(hexCount,
      2048,
      [this](int begin, int end)
      {
        HexCorners corners;
        for (int h = begin; h < end; ++h)
        {
          for (int k = 0; k < 8; ++k)
          {
            corners.row(k) = this->X.row(this->Cells(h, k));
          }
          this->HexValue[static_cast<size_t>(h)] = HexEnergy(corners,
            this->InverseSize[static_cast<size_t>(h)],
            this->Eps,
            this->VolumeWeight,
            this->HexGradient[static_cast<size_t>(h)],
            this->HexMinDet[static_cast<size_t>(h)]);
        }
      });
    // Sums in hex order, whatever the threads did.
    double energy = 0.0;
    minDet = std::numeric_limits<double>::max();
    for (int h = 0; h < hexCount; ++h)
    {
      energy += this->HexValue[static_cast<size_t>(h)];
      minDet = std::min(minDet, this->HexMinDet[static_cast<size_t>(h)]);
    }
    if (gradient)
    {
      const int freeCount = static_cast<int>(this->Free.size());
      ParallelChunks(freeCount,
        4096,
        [this, gradient](int begin, int end)
        {
          for (int i = begin; i < end; ++i)
          {
            const size_t v = static_cast<size_t>(this->Free[static_cast<size_t>(i)]);
            Eigen::Vector3d g = Eigen::Vector3d::Zero();
            for (int e = this->IncidenceStart[v]; e < this->IncidenceStart[v + 1]; ++e)
            {
              const int entry = this->Incidence[static_cast<size_t>(e)];
              g += this->HexGradient[static_cast<size_t>(entry / 8)].row(entry % 8).transpose();
            }
            for (int d = 0; d < this->Dofs[v]; ++d)
            {
              gradient[this->Offset[v] + d] = this->Bases[v].col(d).dot(g);
            }
          }
        });
    }
    return energy;
  }

private:
  const Hexes& Cells;
  const std::vector<double>& InverseSize;
  const std::vector<int>& IncidenceStart;
  const std::vector<int>& Incidence; ///< per vertex: 8 h + k for corner k of hex h
  double VolumeWeight;
  double Eps = 1e-10;
  Points Base;
  std::vector<Eigen::Matrix3d> Bases;
  std::vector<int> Dofs;
  std::vector<int> Offset;
  std::vector<int> Free;
  int Count = 0;
  mutable Points X;
  mutable std::vector<double> HexValue;
  mutable std::vector<double> HexMinDet;
  mutable std::vector<HexCorners> HexGradient;
};

/// What one L-BFGS solve did.
struct SolveSummary
{
  double Initial = 0.0;
  double Final = 0.0;
  int Iterations = 0;
  int Evaluations = 0;
  bool Aborted = false;
};

/// Minimises the round's energy from y with L-BFGS (Nocedal and Wright, algorithm 7.5) and a
/// backtracking (Armijo) line search. Every step moves no coordinate by more than maxStep, so
/// that a boundary vertex slides a bounded distance in its tangent plane, and a step into
/// inverted territory, where the energy of a small eps is huge but finite, is simply shortened.
SolveSummary MinimiseRound(const RoundEnergy& energy,
  std::vector<double>& y,
  int maxIterations,
  double maxStep,
  const Progress& progress,
  double progressFraction)
{
  constexpr int Memory = 8;
  constexpr double Armijo = 1e-4;
  const Eigen::Index n = static_cast<Eigen::Index>(y.size());
  SolveSummary summary;
  Eigen::Map<Eigen::VectorXd> x(y.data(), n);
  Eigen::VectorXd g(n);
  double minDet = 0.0;
  double f = energy.Evaluate(y.data(), g.data(), minDet);
  ++summary.Evaluations;
  summary.Initial = summary.Final = f;
  if (n == 0)
  {
    return summary;
  }
  std::vector<Eigen::VectorXd> s;
  std::vector<Eigen::VectorXd> t; // gradient differences (y_k in the book)
  std::vector<double> rho;
  Eigen::VectorXd trial(n);
  Eigen::VectorXd trialGradient(n);
  Eigen::VectorXd direction(n);
  std::vector<double> alpha(Memory);
  for (int iteration = 0; iteration < maxIterations; ++iteration)
  {
    if (!ReportProgress(progress, progressFraction))
    {
      summary.Aborted = true;
      return summary;
    }
    // The two-loop recursion, oldest pair first in the vectors.
    direction = -g;
    const int m = static_cast<int>(s.size());
    for (int i = m - 1; i >= 0; --i)
    {
      alpha[static_cast<size_t>(i)] =
        rho[static_cast<size_t>(i)] * s[static_cast<size_t>(i)].dot(direction);
      direction -= alpha[static_cast<size_t>(i)] * t[static_cast<size_t>(i)];
    }
    if (m > 0)
    {
      direction *= s.back().dot(t.back()) / t.back().squaredNorm();
    }
    for (int i = 0; i < m; ++i)
    {
      const double beta = rho[static_cast<size_t>(i)] * t[static_cast<size_t>(i)].dot(direction);
      direction += (alpha[static_cast<size_t>(i)] - beta) * s[static_cast<size_t>(i)];
    }
    double slope = g.dot(direction);
    if (!(slope < 0.0))
    {
      // Not a descent direction: forget the curvature pairs.
      s.clear();
      t.clear();
      rho.clear();
      direction = -g;
      slope = -g.squaredNorm();
      if (!(slope < 0.0))
      {
        break; // stationary
      }
    }
    const double longest = direction.cwiseAbs().maxCoeff();
    double step = longest > maxStep ? maxStep / longest : 1.0;
    bool accepted = false;
    double trialValue = 0.0;
    for (int backtrack = 0; backtrack < 40; ++backtrack)
    {
      trial = x + step * direction;
      trialValue = energy.Evaluate(trial.data(), trialGradient.data(), minDet);
      ++summary.Evaluations;
      if (trialValue <= f + Armijo * step * slope)
      {
        accepted = true;
        break;
      }
      step *= 0.5;
    }
    if (!accepted)
    {
      break;
    }
    ++summary.Iterations;
    Eigen::VectorXd sk = trial - x;
    Eigen::VectorXd tk = trialGradient - g;
    const double curvature = sk.dot(tk);
    x = trial;
    g = trialGradient;
    const double decrease = f - trialValue;
    f = trialValue;
    if (curvature > 1e-12 * sk.norm() * tk.norm())
    {
      if (static_cast<int>(s.size()) == Memory)
      {
        s.erase(s.begin());
        t.erase(t.begin());
        rho.erase(rho.begin());
      }
      s.push_back(std::move(sk));
      t.push_back(std::move(tk));
      rho.push_back(1.0 / curvature);
    }
    if (decrease <= 1e-10 * std::fabs(f))
    {
      break;
    }
  }
  summary.Final = f;
  return summary;
}

HexQualitySummary Measure(const HexMesh& mesh)
{
  return SummarizeHexQuality(ComputeHexScaledJacobians(mesh));
}

/// Not worse than `reference`: no more inverted hexes and no smaller minimum; or, when the
/// reference has inverted hexes, fewer of them whatever the minimum (validity first: fertility's
/// untangling took 143 inverted hexes to 7 and was thrown away for a minimum 0.2 lower).
bool NoWorse(const HexQualitySummary& quality, const HexQualitySummary& reference)
{
  return (quality.Inverted <= reference.Inverted && quality.Min >= reference.Min) ||
    quality.Inverted < reference.Inverted;
}

/// What every path of one untangling shares and never changes.
struct UntanglingSetup
{
  Hexes Cells;
  std::vector<int> IncidenceStart; ///< per vertex, into Incidence
  std::vector<int> Incidence;      ///< 8 h + k for corner k of hex h, per vertex in hex order
  std::vector<double> InverseSize; ///< per hex: 1 / its mean edge length
  double Edge = 0.0;               ///< mean hex edge length
  Points Start;                    ///< the input positions
  HexQualitySummary Before;        ///< the input's quality
};

/// Where one path of rounds stands; a fork copies it.
struct RoundState
{
  Points X;
  std::vector<int> Dofs;
  std::vector<Eigen::Matrix3d> Bases;
  double Eps = 0.0;
  double PreviousFinal = 0.0;
  HexQualitySummary Plateau; // the best minimum and mean of the valid rounds so far
  int ValidRounds = 0;
  Points Best;
  HexQualitySummary BestQuality;
  HexQualitySummary Last;
  int Round = 0;
  int MainRounds = 0;
  int TotalRounds = 0;
  bool CurvesReleased = false;
  int FewestInverted = std::numeric_limits<int>::max();
  int RoundsWithoutFewer = 0;
  int Iterations = 0;
  int RoundsRun = 0;
  /// A fork happens between a round's solve and the decisions after it: the resumed path
  /// starts with those decisions, on this round's quality and solve.
  bool MidRound = false;
  Eigen::VectorXd Quality;
  SolveSummary Summary;
};

} // namespace

/// A path's rounds as they stood at the fork, with their own projection.
struct UntanglingFork::Data
{
  std::shared_ptr<const UntanglingSetup> Setup;
  RoundState State;
  std::unique_ptr<HexSurfaceProjection> Projection;
  HexUntanglingParameters Params;
};

namespace
{

/// Runs the rounds of one path from `state` to the end.
Status RunRounds(const std::shared_ptr<const UntanglingSetup>& shared,
  HexSurfaceProjection& projection,
  const HexUntanglingParameters& params,
  RoundState& s,
  const Progress& progress,
  const std::function<void(UntanglingFork&&)>& onStall)
{
  const UntanglingSetup& setup = *shared;
  const int vertexCount = static_cast<int>(setup.Start.rows());
  const int hexCount = static_cast<int>(setup.Cells.rows());
  RoundEnergy energy(
    setup.Cells, setup.InverseSize, setup.IncidenceStart, setup.Incidence, params.VolumeWeight);
  // The free coordinates at X: 3 inside, 2 in a Surface vertex's tangent plane, 1 along a
  // Feature vertex's curve, none for a fixed vertex.
  auto setFrames = [&]()
  {
    for (int v = 0; v < vertexCount; ++v)
    {
      const size_t i = static_cast<size_t>(v);
      const HexVertexKind kind = projection.Kind(v);
      s.Dofs[i] = kind == HexVertexKind::Interior ? 3 : 0;
      if (kind != HexVertexKind::Surface && kind != HexVertexKind::Feature)
      {
        continue;
      }
      Eigen::Vector3d direction;
      projection.Project(v, s.X.row(v).transpose(), &direction);
      if (direction.squaredNorm() == 0.0)
      {
        continue;
      }
      if (kind == HexVertexKind::Feature)
      {
        s.Bases[i].col(0) = direction;
        s.Dofs[i] = 1;
        continue;
      }
      // Any orthonormal pair across the normal spans the tangent plane.
      int axis = 0;
      direction.cwiseAbs().minCoeff(&axis);
      const Eigen::Vector3d u = direction.cross(Eigen::Vector3d::Unit(axis)).normalized();
      s.Bases[i].col(0) = u;
      s.Bases[i].col(1) = direction.cross(u);
      s.Dofs[i] = 2;
    }
  };
  // Releases the corner vertices of the hexes below ReleaseBelow: where the charts force a flat
  // or inverted corner, quality wins over the corner. Curve vertices stay on their curves (one
  // released from a crease lets the padding layer pull away from it: bunny's base, 3x the
  // Hausdorff distance).
  auto release = [&](const Eigen::VectorXd& quality, bool releaseCurves)
  {
    int count = 0;
    for (int h = 0; h < hexCount; ++h)
    {
      const bool curves = releaseCurves && quality[h] < params.ReleaseCurvesBelow;
      if (quality[h] >= params.ReleaseBelow && !curves)
      {
        continue;
      }
      for (int k = 0; k < 8; ++k)
      {
        const int v = setup.Cells(h, k);
        if ((projection.Kind(v) == HexVertexKind::Fixed && quality[h] < params.ReleaseBelow) ||
          (projection.Kind(v) == HexVertexKind::Feature && curves))
        {
          count += projection.Release(v, s.X.row(v).transpose()) ? 1 : 0;
        }
      }
    }
    return count;
  };

  HexMesh measured;
  measured.Cells = setup.Cells;
  std::vector<double> y;
  double minDet = 0.0;
  bool forked = false;
  for (; s.Round < s.TotalRounds; ++s.Round)
  {
    const int round = s.Round;
    const bool polish = round >= s.MainRounds;
    if (!s.MidRound)
    {
      setFrames();
      if (polish)
      {
        for (int v = 0; v < vertexCount; ++v)
        {
          if (projection.Kind(v) != HexVertexKind::Interior)
          {
            s.Dofs[static_cast<size_t>(v)] = 0;
          }
        }
      }
      energy.Start(s.X, s.Dofs, s.Bases, s.Eps);
      y.assign(static_cast<size_t>(energy.Parameters()), 0.0);
      s.Summary = MinimiseRound(energy,
        y,
        std::max(1, params.IterationsPerRound),
        0.25 * setup.Edge,
        progress,
        static_cast<double>(round) / s.TotalRounds);
      if (s.Summary.Aborted)
      {
        return Status::Failure("hex untangling aborted");
      }
      s.Iterations += s.Summary.Iterations;
      ++s.RoundsRun;

      // Back onto the surface, then measured.
      energy.Positions(y.data(), s.X);
      for (int v = 0; v < vertexCount; ++v)
      {
        const HexVertexKind kind = projection.Kind(v);
        if (kind == HexVertexKind::Surface || kind == HexVertexKind::Feature)
        {
          s.X.row(v) = projection.Project(v, s.X.row(v).transpose()).transpose();
        }
      }
      measured.Vertices = s.X;
      s.Quality = ComputeHexScaledJacobians(measured);
      s.Last = SummarizeHexQuality(s.Quality);
      if (NoWorse(s.Last, setup.Before) &&
        (s.Best.rows() == 0 || BetterHexQuality(s.Last, s.BestQuality)))
      {
        s.Best = s.X;
        s.BestQuality = s.Last;
      }
      if (!polish)
      {
        s.RoundsWithoutFewer = s.Last.Inverted < s.FewestInverted ? 0 : s.RoundsWithoutFewer + 1;
        s.FewestInverted = std::min(s.FewestInverted, s.Last.Inverted);
      }
      // The first main round at which the inverted count has set no new low for
      // ForkStallRounds: a second path that ends its main rounds here goes its own way.
      if (onStall && !forked && !polish && s.Last.Inverted > 0 && params.ForkStallRounds > 0 &&
        s.RoundsWithoutFewer >= params.ForkStallRounds)
      {
        forked = true;
        UntanglingFork fork;
        fork.Impl = std::make_unique<UntanglingFork::Data>();
        fork.Impl->Setup = shared;
        fork.Impl->State = s;
        fork.Impl->State.MidRound = true;
        fork.Impl->Projection = std::make_unique<HexSurfaceProjection>(projection);
        fork.Impl->Params = params;
        fork.Impl->Params.StallRounds = params.ForkStallRounds;
        onStall(std::move(fork));
      }
    }
    s.MidRound = false;

    // The last main round leaving hexes inverted: their curve vertices give way too, and a
    // few more rounds follow (once).
    // Or a main round when the count of inverted hexes has set no new low for StallRounds.
    const bool invertedStalled = !polish && s.Last.Inverted > 0 && params.StallRounds > 0 &&
      s.RoundsWithoutFewer >= params.StallRounds;
    const bool lastChance = !polish && !s.CurvesReleased && s.Last.Inverted > 0 &&
      (round + 1 >= s.MainRounds || invertedStalled) && params.ReleaseCurvesBelow > -1.0 &&
      params.CurveRounds > 0;
    const int released = polish ? 0 : release(s.Quality, lastChance);
    if (lastChance)
    {
      s.CurvesReleased = true;
      s.MainRounds = round + 1 + params.CurveRounds;
      s.TotalRounds = s.MainRounds + std::max(0, params.FinalRounds);
      s.FewestInverted = std::numeric_limits<int>::max();
      s.RoundsWithoutFewer = 0;
    }
    else if (invertedStalled)
    {
      s.MainRounds = round + 1; // the final rounds next
      s.TotalRounds = s.MainRounds + std::max(0, params.FinalRounds);
    }

    // Converged once nothing is inverted, nothing was released and neither this round nor the
    // projection after the last one changed much (the projection undoes a little of every
    // round's sliding).
    energy.Start(s.X, s.Dofs, s.Bases, s.Eps);
    y.assign(static_cast<size_t>(energy.Parameters()), 0.0);
    energy.Evaluate(y.data(), nullptr, minDet);
    const double final = s.Summary.Final;
    const double decrease =
      s.Summary.Initial > 0.0 ? (s.Summary.Initial - final) / s.Summary.Initial : 0.0;
    const bool settled = round > 0 && s.PreviousFinal - final < params.Tolerance * std::fabs(final);
    s.PreviousFinal = final;
    // Or once a valid mesh stops getting better: a minimum held by the structure (a padded
    // concave corner) does not move, and the mean creeps.
    bool stalled = false;
    if (s.Last.Inverted == 0)
    {
      stalled = s.ValidRounds > 0 && s.Last.Min < s.Plateau.Min + 0.01 &&
        s.Last.Mean < s.Plateau.Mean + 0.001;
      if (s.ValidRounds == 0 || s.Last.Min > s.Plateau.Min)
      {
        s.Plateau.Min = s.Last.Min;
      }
      s.Plateau.Mean = std::max(s.Plateau.Mean, s.Last.Mean);
      ++s.ValidRounds;
    }
    if (minDet > 0.0 && released == 0 && (decrease < params.Tolerance || settled || stalled))
    {
      if (polish || params.FinalRounds <= 0)
      {
        break;
      }
      // Converged with the boundary free: go on to the final rounds.
      s.MainRounds = round + 1;
      s.TotalRounds = s.MainRounds + params.FinalRounds;
    }
    // The next eps (Garanzha et al. 2021): from the energy decrease and the smallest
    // determinant after the projection.
    const double sigma = std::max(decrease, 0.1);
    double chi = 0.0;
    double chiPrime = 0.0;
    Chi(minDet, s.Eps, chi, chiPrime);
    const double mu = (1.0 - sigma) * chi;
    s.Eps = minDet < mu ? 2.0 * std::sqrt(mu * (mu - minDet)) : 1e-10;
  }
  return Status::Success();
}

/// Keeps the last round when it is no worse than the input, else the best round that is
/// (fewest inverted, then the largest minimum), else the input. (Keeping the best round over
/// a last one with more inverted hexes cost bunny 0.1 of minimum and 4e-3 of Hausdorff
/// distance after the smoothing, which mends the few the last round leaves.)
void KeepBest(const UntanglingSetup& setup,
  const RoundState& s,
  const HexSurfaceProjection& projection,
  HexMesh& mesh,
  HexUntanglingResult& result)
{
  HexQualitySummary kept = s.Last;
  if (NoWorse(s.Last, setup.Before))
  {
    mesh.Vertices = s.X;
    result.Kept = true;
  }
  else if (s.Best.rows() > 0)
  {
    mesh.Vertices = s.Best;
    kept = s.BestQuality;
    result.Kept = true;
  }
  else
  {
    mesh.Vertices = setup.Start;
    kept = setup.Before;
  }
  result.MinAfter = kept.Min;
  result.MeanAfter = kept.Mean;
  result.InvertedAfter = kept.Inverted;
  result.Rounds = s.RoundsRun;
  result.Iterations = s.Iterations;
  result.ReleasedVertices = projection.ReleasedCount();
}

/// Runs the rounds from `state` and fills `mesh` and `result` with what is kept; on failure
/// (an abort) `mesh` gets the input positions back.
Status RunAndKeep(const std::shared_ptr<const UntanglingSetup>& shared,
  HexSurfaceProjection& projection,
  const HexUntanglingParameters& params,
  RoundState& state,
  const Progress& progress,
  const std::function<void(UntanglingFork&&)>& onStall,
  HexMesh& mesh,
  HexUntanglingResult& result)
{
  const Status status = RunRounds(shared, projection, params, state, progress, onStall);
  if (!status)
  {
    mesh.Vertices = shared->Start;
    return status;
  }
  KeepBest(*shared, state, projection, mesh, result);
  ReportProgress(progress, 1.0);
  return Status::Success();
}

void StartResult(const HexQualitySummary& before, HexUntanglingResult& result)
{
  result = HexUntanglingResult();
  result.MinBefore = result.MinAfter = before.Min;
  result.MeanBefore = result.MeanAfter = before.Mean;
  result.InvertedBefore = result.InvertedAfter = before.Inverted;
}

} // namespace

UntanglingFork::UntanglingFork() = default;
UntanglingFork::~UntanglingFork() = default;
UntanglingFork::UntanglingFork(UntanglingFork&&) noexcept = default;
UntanglingFork& UntanglingFork::operator=(UntanglingFork&&) noexcept = default;

HexSurfaceProjection* UntanglingFork::Projection() const
{
  return this->Impl ? this->Impl->Projection.get() : nullptr;
}

Status untangleHexMesh(HexMesh& mesh,
  const std::vector<std::vector<int>>& vertexCharts,
  const HexSmoothingSurface& surface,
  const HexUntanglingParameters& params,
  HexUntanglingResult& result,
  const Progress& progress)
{
  if (static_cast<Eigen::Index>(vertexCharts.size()) != mesh.Vertices.rows())
  {
    return Status::Failure("untangling needs the charts of every hex vertex");
  }
  if (surface.FaceChart.size() != static_cast<size_t>(surface.Faces.rows()))
  {
    return Status::Failure("untangling needs the chart of every surface triangle");
  }
  HexSurfaceProjection projection(surface, vertexCharts, mesh, params.SoftFeatureAngle);
  return untangleHexMesh(mesh, projection, params, result, progress);
}

Status untangleHexMesh(HexMesh& mesh,
  HexSurfaceProjection& projection,
  const HexUntanglingParameters& params,
  HexUntanglingResult& result,
  const Progress& progress,
  const std::function<void(UntanglingFork&&)>& onStall)
{
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  if (projection.VertexCount() != vertexCount)
  {
    return Status::Failure("untangling needs the kind of every hex vertex");
  }
  if (!(params.VolumeWeight >= 0.0 && params.VolumeWeight < 1.0))
  {
    return Status::Failure("the untangling's VolumeWeight must lie in [0, 1)");
  }
  auto shared = std::make_shared<UntanglingSetup>();
  UntanglingSetup& setup = *shared;
  setup.Before = Measure(mesh);
  StartResult(setup.Before, result);
  result.ReleasedVertices = projection.ReleasedCount();
  if (hexCount == 0 || params.MaxRounds <= 0)
  {
    return Status::Success();
  }
  setup.Cells = mesh.Cells;
  setup.Start = mesh.Vertices;

  // Incidence: 8 h + k for corner k of hex h, per vertex in hex order.
  setup.IncidenceStart.assign(static_cast<size_t>(vertexCount) + 1, 0);
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      ++setup.IncidenceStart[static_cast<size_t>(mesh.Cells(h, k)) + 1];
    }
  }
  for (int v = 0; v < vertexCount; ++v)
  {
    setup.IncidenceStart[static_cast<size_t>(v) + 1] +=
      setup.IncidenceStart[static_cast<size_t>(v)];
  }
  setup.Incidence.resize(static_cast<size_t>(setup.IncidenceStart.back()));
  {
    std::vector<int> fill(setup.IncidenceStart.begin(), setup.IncidenceStart.end() - 1);
    for (int h = 0; h < hexCount; ++h)
    {
      for (int k = 0; k < 8; ++k)
      {
        setup.Incidence[static_cast<size_t>(fill[static_cast<size_t>(mesh.Cells(h, k))]++)] =
          8 * h + k;
      }
    }
  }

  // Each hex's Jacobians are measured against a cube of its own mean edge length, which an
  // inverted hex still has.
  setup.InverseSize.resize(static_cast<size_t>(hexCount));
  for (int h = 0; h < hexCount; ++h)
  {
    double length = 0.0;
    for (const auto& edge : HexEdges)
    {
      length +=
        (mesh.Vertices.row(mesh.Cells(h, edge[0])) - mesh.Vertices.row(mesh.Cells(h, edge[1])))
          .norm() /
        12.0;
    }
    setup.InverseSize[static_cast<size_t>(h)] = length > 0.0 ? 1.0 / length : 1.0;
  }
  setup.Edge = MeanHexEdgeLength(mesh);

  RoundState state;
  state.X = mesh.Vertices;
  state.Dofs.assign(static_cast<size_t>(vertexCount), 0);
  state.Bases.assign(static_cast<size_t>(vertexCount), Eigen::Matrix3d::Identity());
  {
    // The initial eps of Garanzha et al.'s code: a fifth of the worst inversion.
    RoundEnergy energy(
      setup.Cells, setup.InverseSize, setup.IncidenceStart, setup.Incidence, params.VolumeWeight);
    energy.Start(state.X, state.Dofs, state.Bases, 1.0);
    double minDet = 0.0;
    energy.Evaluate(nullptr, nullptr, minDet);
    state.Eps = std::sqrt(1e-12 + 0.04 * std::pow(std::min(minDet, 0.0), 2));
  }
  state.BestQuality = setup.Before;
  state.Last = setup.Before;
  // The main rounds, then a few with the boundary held where the last projection put it, so
  // that the interior settles on the boundary as it finally is.
  state.MainRounds = setup.Before.Inverted == 0 ? std::min(params.MaxRounds, params.MaxRoundsValid)
                                                : params.MaxRounds;
  state.TotalRounds = state.MainRounds + std::max(0, params.FinalRounds);
  return RunAndKeep(shared, projection, params, state, progress, onStall, mesh, result);
}

Status resumeUntangling(UntanglingFork& fork,
  HexMesh& mesh,
  HexUntanglingResult& result,
  const Progress& progress)
{
  if (!fork.Impl)
  {
    return Status::Failure("resumeUntangling needs a fork");
  }
  UntanglingFork::Data& data = *fork.Impl;
  StartResult(data.Setup->Before, result);
  mesh.Cells = data.Setup->Cells;
  return RunAndKeep(
    data.Setup, *data.Projection, data.Params, data.State, progress, {}, mesh, result);
}

} // namespace polycubehex
