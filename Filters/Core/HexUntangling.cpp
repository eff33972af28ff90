// SPDX-License-Identifier: BSD-3-Clause
#include "HexUntangling.h"

#include "FoldoverFreeEnergy.h"
#include "HexScaledJacobian.h"
#include "ThreadCount.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

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

} // namespace

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
  const Progress& progress)
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
  result = HexUntanglingResult();
  const HexQualitySummary before = Measure(mesh);
  result.MinBefore = result.MinAfter = before.Min;
  result.MeanBefore = result.MeanAfter = before.Mean;
  result.InvertedBefore = result.InvertedAfter = before.Inverted;
  const int releasedBefore = projection.ReleasedCount();
  result.ReleasedVertices = releasedBefore;
  if (hexCount == 0 || params.MaxRounds <= 0)
  {
    return Status::Success();
  }

  // Incidence: 8 h + k for corner k of hex h, per vertex in hex order.
  std::vector<int> incidenceStart(static_cast<size_t>(vertexCount) + 1, 0);
  for (int h = 0; h < hexCount; ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      ++incidenceStart[static_cast<size_t>(mesh.Cells(h, k)) + 1];
    }
  }
  for (int v = 0; v < vertexCount; ++v)
  {
    incidenceStart[static_cast<size_t>(v) + 1] += incidenceStart[static_cast<size_t>(v)];
  }
  std::vector<int> incidence(static_cast<size_t>(incidenceStart.back()));
  {
    std::vector<int> fill(incidenceStart.begin(), incidenceStart.end() - 1);
    for (int h = 0; h < hexCount; ++h)
    {
      for (int k = 0; k < 8; ++k)
      {
        incidence[static_cast<size_t>(fill[static_cast<size_t>(mesh.Cells(h, k))]++)] = 8 * h + k;
      }
    }
  }

  // Each hex's Jacobians are measured against a cube of its own mean edge length, which an
  // inverted hex still has.
  std::vector<double> inverseSize(static_cast<size_t>(hexCount));
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
    inverseSize[static_cast<size_t>(h)] = length > 0.0 ? 1.0 / length : 1.0;
  }
  const double edge = MeanHexEdgeLength(mesh);

  RoundEnergy energy(mesh.Cells, inverseSize, incidenceStart, incidence, params.VolumeWeight);
  const Points start = mesh.Vertices;
  Points x = mesh.Vertices;
  std::vector<int> dofs(static_cast<size_t>(vertexCount), 0);
  std::vector<Eigen::Matrix3d> bases(static_cast<size_t>(vertexCount), Eigen::Matrix3d::Identity());
  // The free coordinates at x: 3 inside, 2 in a Surface vertex's tangent plane, 1 along a
  // Feature vertex's curve, none for a fixed vertex.
  auto setFrames = [&]()
  {
    for (int v = 0; v < vertexCount; ++v)
    {
      const size_t i = static_cast<size_t>(v);
      const HexVertexKind kind = projection.Kind(v);
      dofs[i] = kind == HexVertexKind::Interior ? 3 : 0;
      if (kind != HexVertexKind::Surface && kind != HexVertexKind::Feature)
      {
        continue;
      }
      Eigen::Vector3d direction;
      projection.Project(v, x.row(v).transpose(), &direction);
      if (direction.squaredNorm() == 0.0)
      {
        continue;
      }
      if (kind == HexVertexKind::Feature)
      {
        bases[i].col(0) = direction;
        dofs[i] = 1;
        continue;
      }
      // Any orthonormal pair across the normal spans the tangent plane.
      int axis = 0;
      direction.cwiseAbs().minCoeff(&axis);
      const Eigen::Vector3d u = direction.cross(Eigen::Vector3d::Unit(axis)).normalized();
      bases[i].col(0) = u;
      bases[i].col(1) = direction.cross(u);
      dofs[i] = 2;
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
        const int v = mesh.Cells(h, k);
        if ((projection.Kind(v) == HexVertexKind::Fixed && quality[h] < params.ReleaseBelow) ||
          (projection.Kind(v) == HexVertexKind::Feature && curves))
        {
          count += projection.Release(v, x.row(v).transpose()) ? 1 : 0;
        }
      }
    }
    return count;
  };

  std::vector<double> y;
  double minDet = 0.0;
  energy.Start(x, dofs, bases, 1.0);
  energy.Evaluate(y.data(), nullptr, minDet);
  // The initial eps of Garanzha et al.'s code: a fifth of the worst inversion.
  double eps = std::sqrt(1e-12 + 0.04 * std::pow(std::min(minDet, 0.0), 2));
  double previousFinal = 0.0;
  HexQualitySummary plateau; // the best minimum and mean of the valid rounds so far
  int validRounds = 0;
  Points best;
  HexQualitySummary bestQuality = before;
  HexQualitySummary last = before;
  // The main rounds, then a few with the boundary held where the last projection put it, so
  // that the interior settles on the boundary as it finally is.
  int mainRounds =
    before.Inverted == 0 ? std::min(params.MaxRounds, params.MaxRoundsValid) : params.MaxRounds;
  int totalRounds = mainRounds + std::max(0, params.FinalRounds);
  bool curvesReleased = false;
  int fewestInverted = std::numeric_limits<int>::max();
  int roundsWithoutFewer = 0;
  for (int round = 0; round < totalRounds; ++round)
  {
    const bool polish = round >= mainRounds;
    setFrames();
    if (polish)
    {
      for (int v = 0; v < vertexCount; ++v)
      {
        if (projection.Kind(v) != HexVertexKind::Interior)
        {
          dofs[static_cast<size_t>(v)] = 0;
        }
      }
    }
    energy.Start(x, dofs, bases, eps);
    y.assign(static_cast<size_t>(energy.Parameters()), 0.0);
    const SolveSummary summary = MinimiseRound(energy,
      y,
      std::max(1, params.IterationsPerRound),
      0.25 * edge,
      progress,
      static_cast<double>(round) / totalRounds);
    if (summary.Aborted)
    {
      mesh.Vertices = start;
      return Status::Failure("hex untangling aborted");
    }
    result.Iterations += summary.Iterations;
    ++result.Rounds;

    // Back onto the surface, then measured.
    energy.Positions(y.data(), x);
    for (int v = 0; v < vertexCount; ++v)
    {
      const HexVertexKind kind = projection.Kind(v);
      if (kind == HexVertexKind::Surface || kind == HexVertexKind::Feature)
      {
        x.row(v) = projection.Project(v, x.row(v).transpose()).transpose();
      }
    }
    mesh.Vertices = x;
    const Eigen::VectorXd quality = ComputeHexScaledJacobians(mesh);
    last = SummarizeHexQuality(quality);
    if (NoWorse(last, before) && (best.rows() == 0 || BetterHexQuality(last, bestQuality)))
    {
      best = x;
      bestQuality = last;
    }
    // The last main round leaving hexes inverted: their curve vertices give way too, and a
    // few more rounds follow (once).
    // Or a main round when the count of inverted hexes has set no new low for StallRounds.
    if (!polish)
    {
      roundsWithoutFewer = last.Inverted < fewestInverted ? 0 : roundsWithoutFewer + 1;
      fewestInverted = std::min(fewestInverted, last.Inverted);
    }
    const bool invertedStalled = !polish && last.Inverted > 0 && params.StallRounds > 0 &&
      roundsWithoutFewer >= params.StallRounds;
    const bool lastChance = !polish && !curvesReleased && last.Inverted > 0 &&
      (round + 1 >= mainRounds || invertedStalled) && params.ReleaseCurvesBelow > -1.0 &&
      params.CurveRounds > 0;
    const int released = polish ? 0 : release(quality, lastChance);
    if (lastChance)
    {
      curvesReleased = true;
      mainRounds = round + 1 + params.CurveRounds;
      totalRounds = mainRounds + std::max(0, params.FinalRounds);
      fewestInverted = std::numeric_limits<int>::max();
      roundsWithoutFewer = 0;
    }
    else if (invertedStalled)
    {
      mainRounds = round + 1; // the final rounds next
      totalRounds = mainRounds + std::max(0, params.FinalRounds);
    }

    // Converged once nothing is inverted, nothing was released and neither this round nor the
    // projection after the last one changed much (the projection undoes a little of every
    // round's sliding).
    energy.Start(x, dofs, bases, eps);
    y.assign(static_cast<size_t>(energy.Parameters()), 0.0);
    energy.Evaluate(y.data(), nullptr, minDet);
    const double final = summary.Final;
    const double decrease =
      summary.Initial > 0.0 ? (summary.Initial - final) / summary.Initial : 0.0;
    const bool settled = round > 0 && previousFinal - final < params.Tolerance * std::fabs(final);
    previousFinal = final;
    // Or once a valid mesh stops getting better: a minimum held by the structure (a padded
    // concave corner) does not move, and the mean creeps.
    bool stalled = false;
    if (last.Inverted == 0)
    {
      stalled =
        validRounds > 0 && last.Min < plateau.Min + 0.01 && last.Mean < plateau.Mean + 0.001;
      if (validRounds == 0 || last.Min > plateau.Min)
      {
        plateau.Min = last.Min;
      }
      plateau.Mean = std::max(plateau.Mean, last.Mean);
      ++validRounds;
    }
    if (minDet > 0.0 && released == 0 && (decrease < params.Tolerance || settled || stalled))
    {
      if (polish || params.FinalRounds <= 0)
      {
        break;
      }
      // Converged with the boundary free: go on to the final rounds.
      mainRounds = round + 1;
      totalRounds = mainRounds + params.FinalRounds;
    }
    // The next eps (Garanzha et al. 2021): from the energy decrease and the smallest
    // determinant after the projection.
    const double sigma = std::max(decrease, 0.1);
    double chi = 0.0;
    double chiPrime = 0.0;
    Chi(minDet, eps, chi, chiPrime);
    const double mu = (1.0 - sigma) * chi;
    eps = minDet < mu ? 2.0 * std::sqrt(mu * (mu - minDet)) : 1e-10;
  }

  // Keep the last round when it is no worse than the input, else the best round that is
  // (fewest inverted, then the largest minimum), else the input. (Keeping the best round over
  // a last one with more inverted hexes cost bunny 0.1 of minimum and 4e-3 of Hausdorff
  // distance after the smoothing, which mends the few the last round leaves.)
  if (NoWorse(last, before))
  {
    mesh.Vertices = x;
    result.Kept = true;
  }
  else if (best.rows() > 0)
  {
    mesh.Vertices = best;
    last = bestQuality;
    result.Kept = true;
  }
  else
  {
    mesh.Vertices = start;
    last = before;
  }
  result.MinAfter = last.Min;
  result.MeanAfter = last.Mean;
  result.InvertedAfter = last.Inverted;
  result.ReleasedVertices = projection.ReleasedCount();
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
