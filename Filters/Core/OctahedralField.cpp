// SPDX-License-Identifier: BSD-3-Clause
#include "OctahedralField.h"

#include "OctahedralHarmonics.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <sstream>

namespace polycubehex
{

namespace
{

// 9 coefficients per tet, row t holding tet t's: one pass over the factor serves all 9.
using Blocks = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>;
using Factor =
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>>;

// x = A^-1 b for the 9 columns of b at once, with P A P^T = L L^T.
void SolveBlocks(const Factor& factor, const Blocks& b, Blocks& x)
{
  const Eigen::SparseMatrix<double>& l = factor.matrixL().nestedExpression();
  const int* indices = factor.permutationP().indices().data();
  const int n = static_cast<int>(b.rows());
  Blocks y(n, 9);
  for (int i = 0; i < n; ++i)
  {
    y.row(indices[i]) = b.row(i);
  }
  const int* start = l.outerIndexPtr();
  const int* row = l.innerIndexPtr();
  const double* value = l.valuePtr();
  // Forward: L is stored by columns with the diagonal first.
  for (int j = 0; j < n; ++j)
  {
    y.row(j) /= value[start[j]];
    for (int k = start[j] + 1; k < start[j + 1]; ++k)
    {
      y.row(row[k]) -= value[k] * y.row(j);
    }
  }
  // Backward with L^T: column j of L is row j of L^T.
  for (int j = n - 1; j >= 0; --j)
  {
    Eigen::Matrix<double, 1, 9> sum = y.row(j);
    for (int k = start[j] + 1; k < start[j + 1]; ++k)
    {
      sum -= value[k] * y.row(row[k]);
    }
    y.row(j) = sum / value[start[j]];
  }
  x.resize(n, 9);
  for (int i = 0; i < n; ++i)
  {
    x.row(i) = y.row(indices[i]);
  }
}

// SolveBlocks relies on Eigen storing each column of L with its diagonal entry first.
bool DiagonalFirst(const Factor& factor)
{
  const Eigen::SparseMatrix<double>& l = factor.matrixL().nestedExpression();
  for (int j = 0; j < l.outerSize(); ++j)
  {
    const int first = l.outerIndexPtr()[j];
    if (first >= l.outerIndexPtr()[j + 1] || l.innerIndexPtr()[first] != j ||
      !(l.valuePtr()[first] > 0.0))
    {
      return false;
    }
  }
  return true;
}

} // namespace

Status ComputeOctahedralField(const TetMesh& mesh,
  const TetTopology& topology,
  const OctahedralFieldParameters& parameters,
  std::vector<Eigen::Matrix3d>& frames,
  std::vector<double>* fits,
  const Progress& progress)
{
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  if (tetCount == 0)
  {
    return Status::Failure("The octahedral field needs at least one tet.");
  }
  if (!(parameters.BoundaryAlignmentWeight > 0.0))
  {
    return Status::Failure("BoundaryAlignmentWeight must be positive.");
  }

  std::vector<double> volume(static_cast<size_t>(tetCount));
  std::vector<Eigen::Vector3d> centre(static_cast<size_t>(tetCount));
  double totalVolume = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    volume[t] = TetSignedVolume(mesh.Vertices, mesh.Cells, t);
    totalVolume += volume[t];
    centre[t] = 0.25 *
      (mesh.Vertices.row(mesh.Cells(t, 0)) + mesh.Vertices.row(mesh.Cells(t, 1)) +
        mesh.Vertices.row(mesh.Cells(t, 2)) + mesh.Vertices.row(mesh.Cells(t, 3)))
        .transpose();
  }
  const Eigen::RowVector3d lo = mesh.Vertices.colwise().minCoeff();
  const Eigen::RowVector3d hi = mesh.Vertices.colwise().maxCoeff();
  const double diagonal2 = (hi - lo).squaredNorm();

  const int faceCount = static_cast<int>(topology.BoundaryFaces.rows());
  std::vector<double> area;
  std::vector<Eigen::Vector3d> normal;
  const double totalArea = ComputeFaceAreasAndNormals(
    mesh.Vertices, topology.BoundaryFaces, Eigen::Vector3d::UnitZ(), area, normal);
  if (!(totalVolume > 0.0) || !(totalArea > 0.0))
  {
    return Status::Failure("The octahedral field needs a mesh of positive volume with a boundary.");
  }

  // Normal equations: (L (x) I_9 + sum_f w_f P_f) q = sum_f w_f c_f with L the weighted dual
  // graph Laplacian and P_f the projection orthogonal to the circle's plane (symmetric,
  // idempotent, P_f c_f = c_f). The components couple only through the boundary blocks.
  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> triplets;
  triplets.reserve(static_cast<size_t>(tetCount) * 5);
  std::vector<double> diagonal(static_cast<size_t>(tetCount), 0.0);
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int s = topology.Neighbors(t, k);
      if (s <= t)
      {
        continue; // each interior face once; boundary faces have s = -1
      }
      const double d2 = (centre[t] - centre[s]).squaredNorm();
      const double w = (volume[t] + volume[s]) / std::max(d2, 1e-300) * diagonal2 / totalVolume;
      diagonal[t] += w;
      diagonal[s] += w;
      triplets.emplace_back(t, s, -w);
      triplets.emplace_back(s, t, -w);
    }
  }
  // Per boundary tet: the sum of w_f P_f (9x9) and of w_f (its isotropic bound).
  std::vector<int> boundarySlot(static_cast<size_t>(tetCount), -1);
  std::vector<int> boundaryTets;
  std::vector<Eigen::Matrix<double, 9, 9>> boundaryBlocks;
  Blocks rhs = Blocks::Zero(tetCount, 9);
  std::vector<double> boundaryWeight(static_cast<size_t>(tetCount), 0.0);
  for (int f = 0; f < faceCount; ++f)
  {
    const int t = topology.BoundaryFaceTet[f];
    const double w = parameters.BoundaryAlignmentWeight * area[f] / totalArea;
    const NormalAlignedCircle circle = ComputeNormalAlignedCircle(normal[f]);
    const double radius2 = circle.U.squaredNorm();
    const Eigen::Matrix<double, 9, 9> projector = Eigen::Matrix<double, 9, 9>::Identity() -
      (circle.U * circle.U.transpose() + circle.V * circle.V.transpose()) / radius2;
    if (boundarySlot[t] < 0)
    {
      boundarySlot[t] = static_cast<int>(boundaryTets.size());
      boundaryTets.push_back(t);
      boundaryBlocks.push_back(Eigen::Matrix<double, 9, 9>::Zero());
    }
    boundaryBlocks[boundarySlot[t]] += w * projector;
    boundaryWeight[t] += w;
    rhs.row(t) += w * circle.Center.transpose();
  }
  for (int t = 0; t < tetCount; ++t)
  {
    triplets.emplace_back(t, t, diagonal[t]);
  }
  Eigen::SparseMatrix<double> laplacian(tetCount, tetCount);
  laplacian.setFromTriplets(triplets.begin(), triplets.end());

  // Preconditioner: the scalar matrix L + diag(sum_f w_f), factorised once and applied to the 9
  // components alike. It bounds the true matrix from above (P_f <= I) and differs from it only at
  // the boundary, so conjugate gradients need few iterations.
  for (int t = 0; t < tetCount; ++t)
  {
    triplets.emplace_back(t, t, boundaryWeight[t]);
  }
  Eigen::SparseMatrix<double> bound(tetCount, tetCount);
  bound.setFromTriplets(triplets.begin(), triplets.end());
  triplets.clear();
  triplets.shrink_to_fit();
  Factor factor;
  factor.compute(bound);
  if (factor.info() != Eigen::Success || !DiagonalFirst(factor))
  {
    return Status::Failure("The octahedral field's preconditioner could not be factorised (is "
                           "every connected component of the mesh touching the boundary?).");
  }
  if (!ReportProgress(progress, 0.2))
  {
    return Status::Failure("Aborted.");
  }

  auto apply = [&](const Blocks& x, Blocks& y)
  {
    y.noalias() = laplacian * x;
    for (size_t b = 0; b < boundaryTets.size(); ++b)
    {
      const int t = boundaryTets[b];
      y.row(t) += (boundaryBlocks[b] * x.row(t).transpose()).transpose();
    }
  };
  auto dot = [](const Blocks& a, const Blocks& b) { return a.cwiseProduct(b).sum(); };

  // Preconditioned conjugate gradients from the solution of the preconditioner itself.
  Blocks q;
  SolveBlocks(factor, rhs, q);
  Blocks r(tetCount, 9);
  apply(q, r);
  r = rhs - r;
  Blocks z;
  SolveBlocks(factor, r, z);
  Blocks d = z;
  Blocks ad(tetCount, 9);
  double rz = dot(r, z);
  const double rhsNorm = rhs.norm();
  double residual = r.norm() / rhsNorm;
  int iteration = 0;
  for (; iteration < parameters.MaxSolverIterations && residual > parameters.SolverTolerance;
       ++iteration)
  {
    apply(d, ad);
    const double alpha = rz / dot(d, ad);
    q += alpha * d;
    r -= alpha * ad;
    SolveBlocks(factor, r, z);
    const double rzNext = dot(r, z);
    d = z + (rzNext / rz) * d;
    rz = rzNext;
    residual = r.norm() / rhsNorm;
    if (!ReportProgress(progress, 0.2 + 0.5 * iteration / parameters.MaxSolverIterations))
    {
      return Status::Failure("Aborted.");
    }
  }
  if (!q.allFinite())
  {
    return Status::Failure("The octahedral field's linear solve diverged.");
  }
  if (residual > 1e3 * parameters.SolverTolerance)
  {
    std::ostringstream message;
    message << "The octahedral field's linear solve did not converge (relative residual "
            << residual << " after " << iteration << " iterations).";
    return Status::Failure(message.str());
  }
  if (!ReportProgress(progress, 0.7))
  {
    return Status::Failure("Aborted.");
  }

  frames.resize(static_cast<size_t>(tetCount));
  if (fits)
  {
    fits->resize(static_cast<size_t>(tetCount));
  }
  for (int t = 0; t < tetCount; ++t)
  {
    double fit = 0.0;
    frames[t] = OctahedralToFrame(q.row(t).transpose(), &fit);
    if (fits)
    {
      (*fits)[t] = fit;
    }
  }
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
