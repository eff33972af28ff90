// SPDX-License-Identifier: BSD-3-Clause
#include "FrameFieldEnergy.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace polycubehex
{

FrameFieldEnergy::FrameFieldEnergy(const TetMesh& mesh,
  const TetTopology& topology,
  const Tets& faceCut,
  const Tets& faceSide,
  const FrameFieldEnergyWeights& weights)
{
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  this->NumberOfTets = tetCount;
  this->Epsilon = weights.L1Epsilon;
  const bool hasCuts = faceCut.rows() == mesh.Cells.rows() && faceSide.rows() == mesh.Cells.rows();

  std::vector<double> volume(static_cast<size_t>(tetCount));
  std::vector<Eigen::Vector3d> centre(static_cast<size_t>(tetCount));
  double totalVolume = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    volume[t] = TetSignedVolume(mesh.Vertices, mesh.Cells, t);
    totalVolume += volume[t];
    centre[t] = Eigen::Vector3d::Zero();
    for (int c = 0; c < 4; ++c)
    {
      centre[t] += 0.25 * mesh.Vertices.row(mesh.Cells(t, c)).transpose();
    }
  }

  // (2) and (3): weight (V_i + V_j) / d_ij^2, normalised by V_F + V_C (w_f / V_F = w_c / V_C).
  double faceTotal = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int s = topology.Neighbors(t, k);
      if (s <= t)
      {
        continue;
      }
      const double w =
        (volume[t] + volume[s]) / std::max((centre[t] - centre[s]).squaredNorm(), 1e-300);
      faceTotal += w;
      if (hasCuts && faceCut(t, k) >= 0)
      {
        const bool tIsMinus = faceSide(t, k) < 0;
        this->CutFaces.push_back({ tIsMinus ? t : s, tIsMinus ? s : t, w });
      }
      else
      {
        this->SmoothFaces.push_back({ t, s, w });
      }
    }
  }
  for (FacePair& pair : this->SmoothFaces)
  {
    pair.Weight /= faceTotal;
  }
  for (FacePair& pair : this->CutFaces)
  {
    pair.Weight /= faceTotal;
  }

  // (4): A_f / A per boundary face.
  const int faceCount = static_cast<int>(topology.BoundaryFaces.rows());
  std::vector<double> area;
  std::vector<Eigen::Vector3d> normal;
  double totalArea = ComputeFaceAreasAndNormals(
    mesh.Vertices, topology.BoundaryFaces, Eigen::Vector3d::Zero(), area, normal);
  if (!(totalArea > 0.0))
  {
    totalArea = 1.0;
  }
  for (int f = 0; f < faceCount; ++f)
  {
    BoundaryTerm term;
    term.Tet = topology.BoundaryFaceTet[f];
    for (int c = 0; c < 3; ++c)
    {
      term.Normal[c] = normal[f](c);
    }
    term.Weight = weights.Alignment * area[f] / totalArea;
    this->BoundaryTerms.push_back(term);
  }

  // (5): pairs of boundary faces sharing an edge that is not an edge of a cut face, nor sharp.
  std::vector<std::array<int, 2>> cutEdges;
  if (hasCuts)
  {
    for (int t = 0; t < tetCount; ++t)
    {
      for (int k = 0; k < 4; ++k)
      {
        if (faceCut(t, k) < 0)
        {
          continue;
        }
        for (int e = 0; e < 3; ++e)
        {
          const int a = mesh.Cells(t, TetFaceTable[k][e]);
          const int b = mesh.Cells(t, TetFaceTable[k][(e + 1) % 3]);
          cutEdges.push_back({ std::min(a, b), std::max(a, b) });
        }
      }
    }
    std::sort(cutEdges.begin(), cutEdges.end());
    cutEdges.erase(std::unique(cutEdges.begin(), cutEdges.end()), cutEdges.end());
  }
  const Triangles adjacency =
    ComputeFaceAdjacency(static_cast<int>(mesh.Vertices.rows()), topology.BoundaryFaces);
  const double cosMaxAngle = std::cos(weights.NormalDifferenceMaxAngle * 3.14159265358979323846 / 180.0);
  for (int f = 0; f < faceCount; ++f)
  {
    for (int e = 0; e < 3; ++e)
    {
      const int g = adjacency(f, e);
      if (g <= f)
      {
        continue;
      }
      const int a = topology.BoundaryFaces(f, e);
      const int b = topology.BoundaryFaces(f, (e + 1) % 3);
      const std::array<int, 2> edge = { std::min(a, b), std::max(a, b) };
      if (std::binary_search(cutEdges.begin(), cutEdges.end(), edge))
      {
        continue;
      }
      // Beyond the threshold the two faces are meant for different axes (past 45 degrees a
      // frame fits them better on two perpendicular axes than on one): (5) would only pull
      // both frames off their faces there, e.g. 0.1 degree at the edges of a cube.
      if (normal[f].dot(normal[g]) < cosMaxAngle)
      {
        continue;
      }
      NormalPair pair;
      pair.TetA = topology.BoundaryFaceTet[f];
      pair.TetB = topology.BoundaryFaceTet[g];
      for (int c = 0; c < 3; ++c)
      {
        pair.NormalA[c] = normal[f](c);
        pair.NormalB[c] = normal[g](c);
      }
      pair.Weight = weights.NormalDifference * (area[f] + area[g]) / (3.0 * totalArea);
      this->NormalPairs.push_back(pair);
    }
  }

  this->OrthogonalityWeights.resize(static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    this->OrthogonalityWeights[t] = weights.Orthogonality * volume[t] / totalVolume;
  }
}

double FrameFieldEnergy::Evaluate(const double* x,
  double* gradient,
  FrameFieldEnergyTerms* terms) const
{
  using Mat = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
  using ConstMap = Eigen::Map<const Mat>;
  using Map = Eigen::Map<Mat>;
  if (gradient)
  {
    std::fill(gradient, gradient + this->VariableCount(), 0.0);
  }
  FrameFieldEnergyTerms sum;

  // (2) smoothness.
  for (const FacePair& pair : this->SmoothFaces)
  {
    const double* a = x + 9 * pair.A;
    const double* b = x + 9 * pair.B;
    double value = 0.0;
    for (int c = 0; c < 9; ++c)
    {
      const double d = a[c] - b[c];
      value += d * d;
      if (gradient)
      {
        gradient[9 * pair.A + c] += 2.0 * pair.Weight * d;
        gradient[9 * pair.B + c] -= 2.0 * pair.Weight * d;
      }
    }
    sum.Smoothness += pair.Weight * value;
  }

  // (3) on the columns of M = R_plus R_minus^T: zero exactly when M is a cube symmetry.
  for (const FacePair& pair : this->CutFaces)
  {
    const ConstMap minus(x + 9 * pair.A);
    const ConstMap plus(x + 9 * pair.B);
    const Mat m = plus * minus.transpose();
    Mat dm;
    double value = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double x2 = m(0, k) * m(0, k);
      const double y2 = m(1, k) * m(1, k);
      const double z2 = m(2, k) * m(2, k);
      value += x2 * y2 + y2 * z2 + z2 * x2;
      dm(0, k) = 2.0 * m(0, k) * (y2 + z2);
      dm(1, k) = 2.0 * m(1, k) * (z2 + x2);
      dm(2, k) = 2.0 * m(2, k) * (x2 + y2);
    }
    sum.Cut += pair.Weight * value;
    if (gradient)
    {
      // dE = <G, dM>, dM = dR_plus R_minus^T + R_plus dR_minus^T.
      Map(gradient + 9 * pair.B) += pair.Weight * dm * minus;
      Map(gradient + 9 * pair.A) += pair.Weight * dm.transpose() * plus;
    }
  }

  // (4) smoothed l1 norm of R n.
  for (const BoundaryTerm& term : this->BoundaryTerms)
  {
    const double* r = x + 9 * term.Tet;
    for (int i = 0; i < 3; ++i)
    {
      const double u =
        r[3 * i] * term.Normal[0] + r[3 * i + 1] * term.Normal[1] + r[3 * i + 2] * term.Normal[2];
      const double root = std::sqrt(u * u + this->Epsilon);
      sum.Alignment += term.Weight * root;
      if (gradient)
      {
        const double factor = term.Weight * u / root;
        for (int j = 0; j < 3; ++j)
        {
          gradient[9 * term.Tet + 3 * i + j] += factor * term.Normal[j];
        }
      }
    }
  }

  // (5) normal difference across boundary edges.
  for (const NormalPair& pair : this->NormalPairs)
  {
    const double* a = x + 9 * pair.TetA;
    const double* b = x + 9 * pair.TetB;
    for (int i = 0; i < 3; ++i)
    {
      const double d = a[3 * i] * pair.NormalA[0] + a[3 * i + 1] * pair.NormalA[1] +
        a[3 * i + 2] * pair.NormalA[2] - b[3 * i] * pair.NormalB[0] -
        b[3 * i + 1] * pair.NormalB[1] - b[3 * i + 2] * pair.NormalB[2];
      sum.NormalDifference += pair.Weight * d * d;
      if (gradient)
      {
        const double factor = 2.0 * pair.Weight * d;
        for (int j = 0; j < 3; ++j)
        {
          gradient[9 * pair.TetA + 3 * i + j] += factor * pair.NormalA[j];
          gradient[9 * pair.TetB + 3 * i + j] -= factor * pair.NormalB[j];
        }
      }
    }
  }

  // Orthogonality ||R^T R - I||^2, gradient 4 R (R^T R - I).
  for (int t = 0; t < this->NumberOfTets; ++t)
  {
    const ConstMap r(x + 9 * t);
    const Mat defect = r.transpose() * r - Mat::Identity();
    const double w = this->OrthogonalityWeights[t];
    sum.Orthogonality += w * defect.squaredNorm();
    if (gradient)
    {
      Map(gradient + 9 * t) += (4.0 * w) * r * defect;
    }
  }

  sum.Total = sum.Smoothness + sum.Cut + sum.Alignment + sum.NormalDifference + sum.Orthogonality;
  if (terms)
  {
    *terms = sum;
  }
  return sum.Total;
}

std::vector<double> FrameFieldEnergy::DiagonalEstimate() const
{
  std::vector<double> diagonal(static_cast<size_t>(this->NumberOfTets), 0.0);
  for (const FacePair& pair : this->SmoothFaces)
  {
    diagonal[pair.A] += 2.0 * pair.Weight;
    diagonal[pair.B] += 2.0 * pair.Weight;
  }
  // h is ~ the squared off-axis components of each column near a cube symmetry.
  for (const FacePair& pair : this->CutFaces)
  {
    diagonal[pair.A] += 2.0 * pair.Weight;
    diagonal[pair.B] += 2.0 * pair.Weight;
  }
  // The smoothed l1 has curvature 1/sqrt(eps) in the two components that are near zero.
  for (const BoundaryTerm& term : this->BoundaryTerms)
  {
    diagonal[term.Tet] += term.Weight * 2.0 / (9.0 * std::sqrt(this->Epsilon));
  }
  for (const NormalPair& pair : this->NormalPairs)
  {
    diagonal[pair.TetA] += 2.0 * pair.Weight / 3.0;
    diagonal[pair.TetB] += 2.0 * pair.Weight / 3.0;
  }
  // ||R^T R - I||^2 at a rotation: 8 on the 3 stretches, 4 on the 6 shears, 0 on rotations.
  for (int t = 0; t < this->NumberOfTets; ++t)
  {
    diagonal[t] += 16.0 / 3.0 * this->OrthogonalityWeights[t];
  }
  return diagonal;
}

namespace
{

// The energy in scaled variables y = s x (one s per tet), so that L-BFGS sees a better
// conditioned problem; dE/dy = dE/dx / s.
class CeresEnergy : public ceres::FirstOrderFunction
{
public:
  CeresEnergy(const FrameFieldEnergy& energy, const std::vector<double>& scale)
    : Energy(energy)
    , Scale(scale)
    , X(static_cast<size_t>(energy.VariableCount()))
  {
  }
  bool Evaluate(const double* parameters, double* cost, double* gradient) const override
  {
    const int tetCount = this->Energy.TetCount();
    for (int t = 0; t < tetCount; ++t)
    {
      const double inverse = 1.0 / this->Scale[t];
      for (int c = 0; c < 9; ++c)
      {
        this->X[9 * t + c] = parameters[9 * t + c] * inverse;
      }
    }
    *cost = this->Energy.Evaluate(this->X.data(), gradient);
    if (gradient)
    {
      for (int t = 0; t < tetCount; ++t)
      {
        const double inverse = 1.0 / this->Scale[t];
        for (int c = 0; c < 9; ++c)
        {
          gradient[9 * t + c] *= inverse;
        }
      }
    }
    return std::isfinite(*cost);
  }
  int NumParameters() const override { return this->Energy.VariableCount(); }

private:
  const FrameFieldEnergy& Energy;
  const std::vector<double>& Scale;
  mutable std::vector<double> X;
};

// The paper's stopping rule (L2 norm of the gradient) and the caller's progress and abort.
class StopRule : public ceres::IterationCallback
{
public:
  StopRule(double tolerance,
    int maxIterations,
    const Progress& progress,
    const FrameFieldEnergy& energy,
    const std::vector<double>& scale,
    const double* y)
    : Tolerance(tolerance)
    , MaxIterations(maxIterations)
    , Report(progress)
    , Energy(energy)
    , Scale(scale)
    , Y(y)
  {
    this->MinScale = *std::min_element(scale.begin(), scale.end());
    this->MaxScale = *std::max_element(scale.begin(), scale.end());
  }

  // ||dE/dx|| from the scaled gradient's norm when the bounds decide, else exactly at the current
  // point (Ceres writes it to the parameters every iteration).
  bool Converged(double scaledGradientNorm)
  {
    if (this->MaxScale * scaledGradientNorm <= this->Tolerance)
    {
      return true;
    }
    if (this->MinScale * scaledGradientNorm > this->Tolerance)
    {
      return false;
    }
    const int tetCount = this->Energy.TetCount();
    this->X.resize(static_cast<size_t>(9 * tetCount));
    this->G.resize(this->X.size());
    for (int t = 0; t < tetCount; ++t)
    {
      for (int c = 0; c < 9; ++c)
      {
        this->X[9 * t + c] = this->Y[9 * t + c] / this->Scale[t];
      }
    }
    this->Energy.Evaluate(this->X.data(), this->G.data());
    double norm2 = 0.0;
    for (double g : this->G)
    {
      norm2 += g * g;
    }
    return std::sqrt(norm2) <= this->Tolerance;
  }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
  {
    this->LastGradientNorm = summary.gradient_norm;
    this->LastCost = summary.cost;
    // Progress: the larger of the iteration fraction and the fraction of the way, in orders of
    // magnitude, from the first gradient norm down to the tolerance.
    if (summary.iteration == 0)
    {
      this->FirstGradientNorm = summary.gradient_norm;
    }
    double fraction = static_cast<double>(summary.iteration) / std::max(1, this->MaxIterations);
    if (this->FirstGradientNorm > this->Tolerance && summary.gradient_norm > 0.0 &&
      this->Tolerance > 0.0)
    {
      fraction = std::max(fraction,
        std::log(this->FirstGradientNorm / summary.gradient_norm) /
          std::log(this->FirstGradientNorm / (this->Tolerance / this->MinScale)));
    }
    if (!ReportProgress(this->Report, std::min(1.0, std::max(0.0, fraction))))
    {
      this->Aborted = true;
      return ceres::SOLVER_ABORT;
    }
    if (this->Converged(summary.gradient_norm))
    {
      this->HasConverged = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

  double Tolerance;
  int MaxIterations;
  const Progress& Report;
  const FrameFieldEnergy& Energy;
  const std::vector<double>& Scale;
  const double* Y;
  double MinScale = 1.0;
  double MaxScale = 1.0;
  double FirstGradientNorm = 0.0;
  std::vector<double> X;
  std::vector<double> G;
  bool Aborted = false;
  bool HasConverged = false;
  double LastGradientNorm = 0.0;
  double LastCost = 0.0;
};

} // namespace

Status MinimizeFrameFieldEnergy(const FrameFieldEnergy& energy,
  std::vector<double>& x,
  double gradientTolerance,
  int maxIterations,
  FrameFieldMinimization& summary,
  const Progress& progress)
{
  if (static_cast<int>(x.size()) != energy.VariableCount())
  {
    return Status::Failure("MinimizeFrameFieldEnergy: x has the wrong size.");
  }
  summary = FrameFieldMinimization();
  std::vector<double> gradient(x.size());
  summary.InitialEnergy = energy.Evaluate(x.data(), gradient.data());
  if (!std::isfinite(summary.InitialEnergy))
  {
    return Status::Failure("The frame field energy is not finite at the initial field.");
  }

  std::vector<double> start = x;
  if (maxIterations > 0)
  {
    std::vector<double> scale = energy.DiagonalEstimate();
    for (double& s : scale)
    {
      s = std::sqrt(std::max(s, 1e-300));
    }
    std::vector<double> y(x.size());
    const int tetCount = energy.TetCount();
    for (int t = 0; t < tetCount; ++t)
    {
      for (int c = 0; c < 9; ++c)
      {
        y[9 * t + c] = x[9 * t + c] * scale[t];
      }
    }
    ceres::GradientProblem problem(new CeresEnergy(energy, scale));
    ceres::GradientProblemSolver::Options options;
    options.line_search_direction_type = ceres::LBFGS;
    options.line_search_type = ceres::WOLFE;
    options.max_num_iterations = maxIterations;
    // Only our rule decides convergence: Ceres' own tests use the max norm and cost changes.
    options.gradient_tolerance = 1e-6 * gradientTolerance;
    options.function_tolerance = 1e-15;
    options.parameter_tolerance = 1e-15;
    options.logging_type = ceres::SILENT;
    // Measured on rockerarm (30.8k tets): the iteration count hardly depends on the rank between
    // 5 and 20, but each iteration's vector work grows with it; Oren's eigenvalue scaling of the
    // initial inverse Hessian halves the iterations and the line-search evaluations.
    options.max_lbfgs_rank = 5;
    options.use_approximate_eigenvalue_bfgs_scaling = true;
    options.update_state_every_iteration = true;
    StopRule rule(gradientTolerance, maxIterations, progress, energy, scale, y.data());
    options.callbacks.push_back(&rule);
    ceres::GradientProblemSolver::Summary ceresSummary;
    ceres::Solve(options, problem, y.data(), &ceresSummary);
    for (int t = 0; t < tetCount; ++t)
    {
      for (int c = 0; c < 9; ++c)
      {
        x[9 * t + c] = y[9 * t + c] / scale[t];
      }
    }
    if (rule.Aborted)
    {
      x = start;
      return Status::Failure("Aborted.");
    }
    summary.Iterations = std::max(0, static_cast<int>(ceresSummary.iterations.size()) - 1);
    summary.Report = ceresSummary.BriefReport();

    summary.Converged = rule.HasConverged;
  }
  summary.FinalEnergy = energy.Evaluate(x.data(), gradient.data());
  if (!std::isfinite(summary.FinalEnergy) || summary.FinalEnergy > summary.InitialEnergy)
  {
    // Never worse than the start (Ceres keeps its best point, this guards the contract).
    x = start;
    summary.FinalEnergy = energy.Evaluate(x.data(), gradient.data());
  }
  double norm2 = 0.0;
  for (double g : gradient)
  {
    norm2 += g * g;
  }
  summary.FinalGradientNorm = std::sqrt(norm2);
  summary.Converged = summary.Converged || summary.FinalGradientNorm <= gradientTolerance;
  return Status::Success();
}

} // namespace polycubehex
