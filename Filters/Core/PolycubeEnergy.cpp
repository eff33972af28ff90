// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeEnergy.h"

#include "TetGeometry.h"
#include "ThreadCount.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polycubehex
{

namespace
{
/// The axis a face's alignment term leaves out (AlignmentLabel), or -1.
int AlignmentAxis(const std::vector<int>& labels, int face)
{
  if (labels.empty())
  {
    return -1;
  }
  const int label = labels[static_cast<size_t>(face)];
  return label >= 0 ? label / 2 : -1;
}

Eigen::Matrix3d Cross(const Eigen::Vector3d& v)
{
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

void AddBlock(double* values, const BlockPattern& pattern, int p, const Eigen::Matrix3d& m)
{
  double* base = values + pattern.Base[p];
  const int stride = pattern.Stride[p];
  for (int b = 0; b < 3; ++b)
  {
    for (int a = 0; a < 3; ++a)
    {
      base[b * stride + a] += m(a, b);
    }
  }
}

Eigen::Vector3d Row(const double* x, int v)
{
  return Eigen::Vector3d(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
}

/// Clamps the negative eigenvalues of a symmetric 3x3 matrix to zero.
Eigen::Matrix3d ProjectPsd(const Eigen::Matrix3d& m)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(m);
  const Eigen::Vector3d lambda = eigen.eigenvalues().cwiseMax(0.0);
  return eigen.eigenvectors() * lambda.asDiagonal() * eigen.eigenvectors().transpose();
}

} // namespace

void BlockPattern::Build(int vertexCount, const std::vector<std::array<int, 2>>& pairs)
{
  this->VertexCount = vertexCount;
  std::vector<int> degree(static_cast<size_t>(vertexCount), 1);
  for (const auto& pair : pairs)
  {
    if (pair[0] != pair[1])
    {
      ++degree[static_cast<size_t>(pair[0])];
      ++degree[static_cast<size_t>(pair[1])];
    }
  }
  std::vector<int> start(static_cast<size_t>(vertexCount) + 1, 0);
  for (int v = 0; v < vertexCount; ++v)
  {
    start[static_cast<size_t>(v) + 1] =
      start[static_cast<size_t>(v)] + degree[static_cast<size_t>(v)];
  }
  std::vector<int> rows(static_cast<size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int v = 0; v < vertexCount; ++v)
  {
    rows[static_cast<size_t>(fill[static_cast<size_t>(v)]++)] = v;
  }
  for (const auto& pair : pairs)
  {
    if (pair[0] != pair[1])
    {
      rows[static_cast<size_t>(fill[static_cast<size_t>(pair[1])]++)] = pair[0];
      rows[static_cast<size_t>(fill[static_cast<size_t>(pair[0])]++)] = pair[1];
    }
  }
  this->Offset.assign(1, 0);
  this->Rows.clear();
  for (int w = 0; w < vertexCount; ++w)
  {
    auto first = rows.begin() + start[static_cast<size_t>(w)];
    auto last = rows.begin() + start[static_cast<size_t>(w) + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    this->Rows.insert(this->Rows.end(), first, last);
    this->Offset.push_back(static_cast<int>(this->Rows.size()));
  }
  this->Base.resize(this->Rows.size());
  this->Stride.resize(this->Rows.size());
  for (int w = 0; w < vertexCount; ++w)
  {
    const int degreeW =
      this->Offset[static_cast<size_t>(w) + 1] - this->Offset[static_cast<size_t>(w)];
    for (int p = this->Offset[static_cast<size_t>(w)]; p < this->Offset[static_cast<size_t>(w) + 1];
         ++p)
    {
      this->Base[static_cast<size_t>(p)] =
        9 * this->Offset[static_cast<size_t>(w)] + 3 * (p - this->Offset[static_cast<size_t>(w)]);
      this->Stride[static_cast<size_t>(p)] = 3 * degreeW;
    }
  }
}

int BlockPattern::Find(int v, int w) const
{
  const auto first = this->Rows.begin() + this->Offset[static_cast<size_t>(w)];
  const auto last = this->Rows.begin() + this->Offset[static_cast<size_t>(w) + 1];
  const auto it = std::lower_bound(first, last, v);
  return it != last && *it == v ? static_cast<int>(it - this->Rows.begin()) : -1;
}

Eigen::SparseMatrix<double> BlockPattern::ZeroMatrix() const
{
  // Column 3w+b lists the rows 3v+a of the pairs (v, w) in increasing order: exactly the layout
  // that Base and Stride address.
  const int n = 3 * this->VertexCount;
  Eigen::SparseMatrix<double> m(n, n);
  Eigen::VectorXi perColumn(n);
  for (int w = 0; w < this->VertexCount; ++w)
  {
    const int degree =
      this->Offset[static_cast<size_t>(w) + 1] - this->Offset[static_cast<size_t>(w)];
    perColumn.segment<3>(3 * w).setConstant(3 * degree);
  }
  m.reserve(perColumn);
  for (int w = 0; w < this->VertexCount; ++w)
  {
    for (int b = 0; b < 3; ++b)
    {
      for (int p = this->Offset[static_cast<size_t>(w)];
           p < this->Offset[static_cast<size_t>(w) + 1];
           ++p)
      {
        for (int a = 0; a < 3; ++a)
        {
          m.insert(3 * this->Rows[static_cast<size_t>(p)] + a, 3 * w + b) = 0.0;
        }
      }
    }
  }
  m.makeCompressed();
  return m;
}

PolycubeEnergy::PolycubeEnergy(const Points& rest,
  const Tets& cells,
  const Triangles& boundaryFaces,
  const std::vector<FacePairAcrossCut>& acrossCuts)
  : NumVertices(static_cast<int>(rest.rows()))
  , Cells(cells)
  , Faces(boundaryFaces)
{
  const int tetCount = static_cast<int>(cells.rows());
  const int faceCount = static_cast<int>(boundaryFaces.rows());
  this->RestInverse.resize(static_cast<size_t>(tetCount));
  this->TetWeight.resize(static_cast<size_t>(tetCount));
  this->RestVolume.resize(static_cast<size_t>(tetCount));
  double totalVolume = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    const Eigen::Vector3d p0 = rest.row(cells(t, 0)).transpose();
    Eigen::Matrix3d dm;
    for (int k = 0; k < 3; ++k)
    {
      dm.col(k) = rest.row(cells(t, k + 1)).transpose() - p0;
    }
    this->RestVolume[static_cast<size_t>(t)] = dm.determinant() / 6.0;
    this->RestInverse[static_cast<size_t>(t)] = dm.inverse();
    totalVolume += this->RestVolume[static_cast<size_t>(t)];
  }
  for (int t = 0; t < tetCount; ++t)
  {
    this->TetWeight[static_cast<size_t>(t)] =
      this->RestVolume[static_cast<size_t>(t)] / totalVolume;
  }

  std::vector<double> faceArea(static_cast<size_t>(faceCount));
  this->RestArea = 0.0;
  for (int f = 0; f < faceCount; ++f)
  {
    const Eigen::Vector3d p0 = rest.row(boundaryFaces(f, 0)).transpose();
    const Eigen::Vector3d p1 = rest.row(boundaryFaces(f, 1)).transpose();
    const Eigen::Vector3d p2 = rest.row(boundaryFaces(f, 2)).transpose();
    faceArea[static_cast<size_t>(f)] = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    this->RestArea += faceArea[static_cast<size_t>(f)];
  }
  this->FaceRestArea = faceArea;

  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(6 * static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        pairs.push_back({ cells(t, i), cells(t, j) });
      }
    }
  }
  // Face 0's corners, then face 1's corners that are not among them.
  auto addDiffEdge = [&](int f, int g, const Eigen::Matrix3d& rotation, bool rotated)
  {
    DiffEdge edge;
    edge.Faces = { f, g };
    edge.Vertices.fill(-1);
    for (int c = 0; c < 3; ++c)
    {
      edge.Vertices[static_cast<size_t>(c)] = boundaryFaces(f, c);
    }
    edge.VertexCount = 3;
    for (int c = 0; c < 3; ++c)
    {
      const int v = boundaryFaces(g, c);
      int slot = -1;
      for (int k = 0; k < 3; ++k)
      {
        if (edge.Vertices[static_cast<size_t>(k)] == v)
        {
          slot = k;
        }
      }
      if (slot < 0)
      {
        slot = edge.VertexCount++;
        edge.Vertices[static_cast<size_t>(slot)] = v;
      }
      edge.Face1Slots[static_cast<size_t>(c)] = slot;
    }
    if (edge.VertexCount == 3)
    {
      return; // two faces on the same three vertices: degenerate surface
    }
    edge.Rotation = rotation;
    edge.Rotated = rotated;
    edge.Weight = (faceArea[static_cast<size_t>(f)] + faceArea[static_cast<size_t>(g)]) /
      (3.0 * this->RestArea);
    this->DiffEdges.push_back(edge);
    // Pairs within a face are already in the pattern (its tet's).
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 3; j < edge.VertexCount; ++j)
      {
        pairs.push_back(
          { edge.Vertices[static_cast<size_t>(i)], edge.Vertices[static_cast<size_t>(j)] });
      }
    }
    for (int i = 3; i < edge.VertexCount; ++i)
    {
      for (int j = i + 1; j < edge.VertexCount; ++j)
      {
        pairs.push_back(
          { edge.Vertices[static_cast<size_t>(i)], edge.Vertices[static_cast<size_t>(j)] });
      }
    }
  };
  const Triangles adjacency = ComputeFaceAdjacency(this->NumVertices, boundaryFaces);
  for (int f = 0; f < faceCount; ++f)
  {
    for (int e = 0; e < 3; ++e)
    {
      const int g = adjacency(f, e);
      if (g > f)
      {
        addDiffEdge(f, g, Eigen::Matrix3d::Identity(), false);
      }
    }
  }
  for (const FacePairAcrossCut& pair : acrossCuts)
  {
    if (pair.MinusFace < 0 || pair.MinusFace >= faceCount || pair.PlusFace < 0 ||
      pair.PlusFace >= faceCount)
    {
      continue;
    }
    addDiffEdge(pair.MinusFace,
      pair.PlusFace,
      pair.Transition,
      !pair.Transition.isApprox(Eigen::Matrix3d::Identity()));
  }
  this->Blocks.Build(this->NumVertices, pairs);

  this->TetPairs.resize(static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        this->TetPairs[static_cast<size_t>(t)][static_cast<size_t>(4 * i + j)] =
          this->Blocks.Find(cells(t, i), cells(t, j));
      }
    }
  }
  this->FacePairs.resize(static_cast<size_t>(faceCount));
  for (int f = 0; f < faceCount; ++f)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        this->FacePairs[static_cast<size_t>(f)][static_cast<size_t>(3 * i + j)] =
          this->Blocks.Find(boundaryFaces(f, i), boundaryFaces(f, j));
      }
    }
  }
  for (auto& edge : this->DiffEdges)
  {
    edge.Pairs.fill(-1);
    for (int i = 0; i < edge.VertexCount; ++i)
    {
      for (int j = 0; j < edge.VertexCount; ++j)
      {
        edge.Pairs[static_cast<size_t>(6 * i + j)] = this->Blocks.Find(
          edge.Vertices[static_cast<size_t>(i)], edge.Vertices[static_cast<size_t>(j)]);
      }
    }
  }

  this->DiagonalValueIndex.resize(3 * static_cast<size_t>(this->NumVertices));
  for (int v = 0; v < this->NumVertices; ++v)
  {
    const int p = this->Blocks.Find(v, v);
    for (int a = 0; a < 3; ++a)
    {
      this->DiagonalValueIndex[3 * static_cast<size_t>(v) + static_cast<size_t>(a)] =
        this->Blocks.ValueIndex(p, a, a);
    }
  }

  // With the rotations held fixed, E_arap is quadratic with the same scalar stiffness matrix for
  // each coordinate: the matrix of the local/global ARAP solver, a good model of its Hessian.
  this->ArapHessianValues.assign(9 * this->Blocks.Rows.size(), 0.0);
  for (int t = 0; t < tetCount; ++t)
  {
    const Eigen::Matrix3d& g = this->RestInverse[static_cast<size_t>(t)];
    Eigen::Matrix<double, 4, 3> grads;
    grads.row(0) = -g.colwise().sum();
    grads.bottomRows<3>() = g;
    const double c = 2.0 * this->TetWeight[static_cast<size_t>(t)];
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        const double k = c * grads.row(i).dot(grads.row(j));
        AddBlock(this->ArapHessianValues.data(),
          this->Blocks,
          this->TetPairs[static_cast<size_t>(t)][static_cast<size_t>(4 * i + j)],
          k * Eigen::Matrix3d::Identity());
      }
    }
  }
}

double PolycubeEnergy::FaceOrientation(const double* x, int f, int label) const
{
  const Eigen::Vector3d p0 = Row(x, this->Faces(f, 0));
  const Eigen::Vector3d u =
    0.5 * (Row(x, this->Faces(f, 1)) - p0).cross(Row(x, this->Faces(f, 2)) - p0);
  return (label % 2 == 0 ? 1.0 : -1.0) * u(label / 2) / this->FaceRestArea[static_cast<size_t>(f)];
}

bool PolycubeEnergy::IsFeasible(const double* x) const
{
  if (!(this->MinVolumeRatio(x) > 0.0))
  {
    return false;
  }
  for (size_t f = 0; f < this->FaceLabel.size(); ++f)
  {
    if (this->FaceLabel[f] >= 0 && !(this->FaceOrientation(x, static_cast<int>(f)) > 0.0))
    {
      return false;
    }
  }
  return true;
}

std::vector<int> PolycubeEnergy::InfeasibleVertices(const double* x, double minVolumeRatio) const
{
  std::vector<int> vertices;
  const int tetCount = static_cast<int>(this->Cells.rows());
  for (int t = 0; t < tetCount; ++t)
  {
    if (!(this->VolumeRatio(x, t) > minVolumeRatio))
    {
      for (int k = 0; k < 4; ++k)
      {
        vertices.push_back(this->Cells(t, k));
      }
    }
  }
  for (size_t f = 0; f < this->FaceLabel.size(); ++f)
  {
    if (this->FaceLabel[f] >= 0 && !(this->FaceOrientation(x, static_cast<int>(f)) > 0.0))
    {
      for (int k = 0; k < 3; ++k)
      {
        vertices.push_back(this->Faces(static_cast<Eigen::Index>(f), k));
      }
    }
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

double PolycubeEnergy::VolumeRatio(const double* x, int t) const
{
  const double v = TetSignedVolume(Row(x, this->Cells(t, 0)),
    Row(x, this->Cells(t, 1)),
    Row(x, this->Cells(t, 2)),
    Row(x, this->Cells(t, 3)));
  return v / this->RestVolume[static_cast<size_t>(t)];
}

double PolycubeEnergy::MinVolumeRatio(const double* x) const
{
  double ratio = std::numeric_limits<double>::infinity();
  const int tetCount = static_cast<int>(this->Cells.rows());
  for (int t = 0; t < tetCount; ++t)
  {
    ratio = std::min(ratio, this->VolumeRatio(x, t));
  }
  return ratio;
}

namespace
{
/// The IPC barrier b(d) = -(d - d0)^2 log(d / d0) on (0, d0) and its first two derivatives.
void BarrierFunction(double d, double d0, double& b, double& db, double& ddb)
{
  if (d >= d0)
  {
    b = db = ddb = 0.0;
    return;
  }
  const double l = std::log(d / d0);
  const double e = d - d0;
  b = -e * e * l;
  db = -2.0 * e * l - e * e / d;
  ddb = -2.0 * l - 4.0 * e / d + e * e / (d * d);
}
} // namespace

namespace
{
/// Tets per thread at least: below two such chunks the threads cost more than they save.
constexpr int TetsPerThread = 2048;

/// Polar rotation of a J with det J > 0 from the eigen decomposition of J^T J (closed form, much
/// cheaper than an SVD); falls back to PolarRotation when J is close to singular.
void FastPolar(const Eigen::Matrix3d& j, Eigen::Matrix3d& r, Eigen::Vector3d& sigma)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(j.transpose() * j);
  const Eigen::Vector3d lambda = eigen.eigenvalues();
  if (!(lambda(0) > 1e-8 * lambda(2)) || !lambda.allFinite())
  {
    PolarRotation(j, r, sigma);
    return;
  }
  sigma = lambda.cwiseSqrt();
  const Eigen::Matrix3d& v = eigen.eigenvectors();
  r = j * v * sigma.cwiseInverse().asDiagonal() * v.transpose();
  // Guard against the closed form's loss of accuracy: R must be orthogonal.
  if (!((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9))
  {
    PolarRotation(j, r, sigma);
  }
}
} // namespace

void PolycubeEnergy::ArapTerm(const double* x,
  double& arap,
  double& barrier,
  Eigen::VectorXd* gradient,
  double* hessian) const
{
  const int tetCount = static_cast<int>(this->Cells.rows());
  const double wArap = this->Weights.Arap;
  const double wBarrier = this->Weights.Barrier / tetCount;
  const double d0 = this->Weights.BarrierThreshold;
  std::vector<double> arapValue(static_cast<size_t>(tetCount));
  std::vector<double> barrierValue(static_cast<size_t>(tetCount), 0.0);
  std::vector<Eigen::Matrix3d> vertexGradient(gradient ? static_cast<size_t>(tetCount) : 0);
  std::vector<double> barrierCurvature(gradient ? static_cast<size_t>(tetCount) : 0, 0.0);
  std::vector<Eigen::Matrix3d> volumeGradient(
    gradient && hessian ? static_cast<size_t>(tetCount) : 0);

  ParallelChunks(tetCount,
    TetsPerThread,
    [&](int begin, int end)
    {
      for (int t = begin; t < end; ++t)
      {
        const Eigen::Vector3d p0 = Row(x, this->Cells(t, 0));
        Eigen::Matrix3d ds;
        for (int k = 0; k < 3; ++k)
        {
          ds.col(k) = Row(x, this->Cells(t, k + 1)) - p0;
        }
        const Eigen::Matrix3d& g = this->RestInverse[static_cast<size_t>(t)];
        const Eigen::Matrix3d j = ds * g;
        const double c = this->TetWeight[static_cast<size_t>(t)];
        Eigen::Matrix3d r;
        if (this->TargetRotation.empty())
        {
          Eigen::Vector3d sigma;
          FastPolar(j, r, sigma);
          arapValue[static_cast<size_t>(t)] = c * (sigma.array() - 1.0).square().sum();
        }
        else
        {
          r = this->TargetRotation[static_cast<size_t>(t)];
          arapValue[static_cast<size_t>(t)] = c * (j - r).squaredNorm();
        }
        double b = 0.0, db = 0.0, ddb = 0.0;
        if (wBarrier > 0.0)
        {
          BarrierFunction(j.determinant(), d0, b, db, ddb);
          barrierValue[static_cast<size_t>(t)] = b / tetCount;
        }
        if (!gradient)
        {
          continue;
        }
        // d/dJ sum (sigma_i - 1)^2 = 2 (J - R): the derivative through R vanishes at the optimum.
        Eigen::Matrix3d dj = 2.0 * wArap * c * (j - r);
        Eigen::Matrix3d cofactor;
        if (db != 0.0)
        {
          cofactor.col(0) = j.col(1).cross(j.col(2));
          cofactor.col(1) = j.col(2).cross(j.col(0));
          cofactor.col(2) = j.col(0).cross(j.col(1));
          dj += wBarrier * db * cofactor;
          if (hessian && ddb > 0.0)
          {
            barrierCurvature[static_cast<size_t>(t)] = wBarrier * ddb;
            volumeGradient[static_cast<size_t>(t)] = cofactor * g.transpose();
          }
        }
        vertexGradient[static_cast<size_t>(t)] = dj * g.transpose();
      }
    });

  // Sums and scatters in tet order: the same bits for any thread count.
  arap = 0.0;
  barrier = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    arap += arapValue[static_cast<size_t>(t)];
    barrier += barrierValue[static_cast<size_t>(t)];
  }
  if (!gradient)
  {
    return;
  }
  for (int t = 0; t < tetCount; ++t)
  {
    const Eigen::Matrix3d& dds = vertexGradient[static_cast<size_t>(t)];
    for (int k = 0; k < 3; ++k)
    {
      gradient->segment<3>(3 * this->Cells(t, k + 1)) += dds.col(k);
    }
    gradient->segment<3>(3 * this->Cells(t, 0)) -= dds.rowwise().sum();
    const double s = barrierCurvature[static_cast<size_t>(t)];
    if (hessian && s > 0.0)
    {
      // Gauss-Newton part b''(d) grad d grad d^T of the barrier.
      const Eigen::Matrix3d& dd = volumeGradient[static_cast<size_t>(t)];
      std::array<Eigen::Vector3d, 4> gd;
      for (int k = 0; k < 3; ++k)
      {
        gd[static_cast<size_t>(k + 1)] = dd.col(k);
      }
      gd[0] = -dd.rowwise().sum();
      for (int i = 0; i < 4; ++i)
      {
        for (int jj = 0; jj < 4; ++jj)
        {
          AddBlock(hessian,
            this->Blocks,
            this->TetPairs[static_cast<size_t>(t)][static_cast<size_t>(4 * i + jj)],
            s * gd[static_cast<size_t>(i)] * gd[static_cast<size_t>(jj)].transpose());
        }
      }
    }
  }
}

bool PolycubeEnergy::Evaluate(const double* x, PolycubeEnergyTerms& terms) const
{
  Eigen::VectorXd unused;
  return this->EvaluateDerivatives(x, terms, unused, nullptr, nullptr);
}

double PolycubeEnergy::AreaRankOneCoefficient() const
{
  return 2.0 * this->Weights.Area / (this->RestArea * this->RestArea);
}

bool PolycubeEnergy::EvaluateDerivatives(const double* x,
  PolycubeEnergyTerms& terms,
  Eigen::VectorXd& gradient,
  Eigen::SparseMatrix<double>* hessian,
  Eigen::VectorXd* areaGradient) const
{
  // The caller asks for derivatives by passing a gradient vector of the right size.
  const bool wantGradient = gradient.size() == 3 * this->NumVertices;
  terms = PolycubeEnergyTerms();
  if (!this->IsFeasible(x))
  {
    return false;
  }
  if (wantGradient)
  {
    gradient.setZero();
  }
  if (areaGradient)
  {
    areaGradient->setZero(3 * this->NumVertices);
  }
  double* h = nullptr;
  if (hessian)
  {
    std::copy(this->ArapHessianValues.begin(), this->ArapHessianValues.end(), hessian->valuePtr());
    for (size_t i = 0; i < this->ArapHessianValues.size(); ++i)
    {
      hessian->valuePtr()[i] *= this->Weights.Arap;
    }
    h = hessian->valuePtr();
  }
  const PolycubeEnergyWeights& w = this->Weights;

  // ARAP, eq. (11).
  this->ArapTerm(x, terms.Arap, terms.Barrier, wantGradient ? &gradient : nullptr, h);

  // Per boundary face: the area vector u = (p1 - p0) x (p2 - p0) / 2.
  const int faceCount = static_cast<int>(this->Faces.rows());
  const double eps = w.AlignmentEpsilon;
  std::vector<Eigen::Vector3d> u(static_cast<size_t>(faceCount));
  std::vector<Eigen::Vector3d> e1(static_cast<size_t>(faceCount));
  std::vector<Eigen::Vector3d> e2(static_cast<size_t>(faceCount));
  double smoothed = 0.0;
  double exact = 0.0;
  double area = 0.0;
  for (int f = 0; f < faceCount; ++f)
  {
    const Eigen::Vector3d p0 = Row(x, this->Faces(f, 0));
    e1[static_cast<size_t>(f)] = Row(x, this->Faces(f, 1)) - p0;
    e2[static_cast<size_t>(f)] = Row(x, this->Faces(f, 2)) - p0;
    const Eigen::Vector3d& uf = u[static_cast<size_t>(f)] =
      0.5 * e1[static_cast<size_t>(f)].cross(e2[static_cast<size_t>(f)]);
    const double norm2 = uf.squaredNorm();
    const int skipped = AlignmentAxis(this->AlignmentLabel, f);
    for (int i = 0; i < 3; ++i)
    {
      if (i != skipped)
      {
        smoothed += std::sqrt(uf(i) * uf(i) + eps * norm2);
      }
    }
    exact += uf.lpNorm<1>();
    area += std::sqrt(norm2);
  }
  if (!(area > 0.0))
  {
    return false;
  }
  // Eq. (10), divided by the current area instead of the rest area: the term is then invariant
  // to scaling, so it cannot decrease by shrinking the shape.
  terms.Alignment = smoothed / area;
  terms.Residual = exact / area - 1.0;
  terms.BoundaryArea = area;
  terms.Area = (area / this->RestArea - 1.0) * (area / this->RestArea - 1.0);

  // Unit normals for eq. (12) and (13).
  std::vector<Eigen::Vector3d> normal(static_cast<size_t>(faceCount));
  for (int f = 0; f < faceCount; ++f)
  {
    const double norm = u[static_cast<size_t>(f)].norm();
    normal[static_cast<size_t>(f)] =
      norm > 0.0 ? Eigen::Vector3d(u[static_cast<size_t>(f)] / norm) : Eigen::Vector3d::Zero();
  }
  double difference = 0.0;
  for (const DiffEdge& edge : this->DiffEdges)
  {
    const Eigen::Vector3d& n0 = normal[static_cast<size_t>(edge.Faces[0])];
    const Eigen::Vector3d& n1 = normal[static_cast<size_t>(edge.Faces[1])];
    difference +=
      edge.Weight * ((edge.Rotated ? Eigen::Vector3d(edge.Rotation * n0) : n0) - n1).squaredNorm();
  }
  terms.Difference = difference;
  for (size_t i = 0; i < this->AnchorIndex.size(); ++i)
  {
    const double d = x[this->AnchorIndex[i]] - this->AnchorTarget[i];
    terms.Anchor += d * d;
    terms.MaxAnchorDeviation = std::max(terms.MaxAnchorDeviation, std::abs(d));
    if (wantGradient)
    {
      gradient(this->AnchorIndex[i]) += 2.0 * w.Anchor * d;
      if (h)
      {
        h[this->DiagonalValueIndex[static_cast<size_t>(this->AnchorIndex[i])]] += 2.0 * w.Anchor;
      }
    }
  }
  // Both orientation terms are functions of d_f = s u_axis / A_rest, u = e1 x e2 / 2; phi gives
  // the term's value and its first and (Gauss-Newton for the penalty) second derivatives in d.
  auto addOrientationTerm =
    [&](const std::vector<int>& faceLabels, double weight, double& value, const auto& phi)
  {
    const double scale = weight / static_cast<double>(std::max(1, faceCount));
    for (int f = 0; f < static_cast<int>(faceLabels.size()); ++f)
    {
      const int label = faceLabels[static_cast<size_t>(f)];
      if (label < 0)
      {
        continue;
      }
      double b = 0.0, db = 0.0, ddb = 0.0;
      phi(this->FaceOrientation(x, f, label), b, db, ddb);
      value += b / std::max(1, faceCount);
      if (!wantGradient || db == 0.0)
      {
        continue;
      }
      Eigen::Vector3d g = Eigen::Vector3d::Zero();
      g(label / 2) = (label % 2 == 0 ? 1.0 : -1.0) / this->FaceRestArea[static_cast<size_t>(f)];
      const Eigen::Vector3d& a1 = e1[static_cast<size_t>(f)];
      const Eigen::Vector3d& a2 = e2[static_cast<size_t>(f)];
      std::array<Eigen::Vector3d, 3> gd;
      gd[1] = 0.5 * a2.cross(g);
      gd[2] = 0.5 * g.cross(a1);
      gd[0] = -gd[1] - gd[2];
      for (int i = 0; i < 3; ++i)
      {
        gradient.segment<3>(3 * this->Faces(f, i)) += scale * db * gd[static_cast<size_t>(i)];
      }
      if (h && ddb > 0.0)
      {
        for (int i = 0; i < 3; ++i)
        {
          for (int j = 0; j < 3; ++j)
          {
            AddBlock(h,
              this->Blocks,
              this->FacePairs[static_cast<size_t>(f)][static_cast<size_t>(3 * i + j)],
              scale * ddb * gd[static_cast<size_t>(i)] * gd[static_cast<size_t>(j)].transpose());
          }
        }
      }
    }
  };
  if (w.FaceBarrier > 0.0)
  {
    addOrientationTerm(this->FaceLabel,
      w.FaceBarrier,
      terms.FaceBarrier,
      [&](double d, double& b, double& db, double& ddb)
      { BarrierFunction(d, w.FaceBarrierThreshold, b, db, ddb); });
  }
  if (w.FaceUnfold > 0.0)
  {
    addOrientationTerm(this->UnfoldLabel,
      w.FaceUnfold,
      terms.FaceUnfold,
      [&](double d, double& b, double& db, double& ddb)
      {
        const double gap = std::max(0.0, w.FaceBarrierThreshold - d);
        b = gap * gap;
        db = -2.0 * gap;
        ddb = gap > 0.0 ? 2.0 : 0.0;
      });
  }
  terms.Total = w.Arap * terms.Arap + w.Alignment * terms.Alignment +
    w.NormalDifference * terms.Difference + w.Area * terms.Area + w.Barrier * terms.Barrier +
    w.Anchor * terms.Anchor + w.FaceBarrier * terms.FaceBarrier + w.FaceUnfold * terms.FaceUnfold;
  if (!wantGradient)
  {
    return true;
  }

  // Alignment and area: derivative with respect to u_f, then through u_f = e1 x e2 / 2.
  const double alignment = terms.Alignment;
  const double areaFactor = 2.0 * w.Area * (area / this->RestArea - 1.0) / this->RestArea;
  for (int f = 0; f < faceCount; ++f)
  {
    const Eigen::Vector3d& uf = u[static_cast<size_t>(f)];
    const double norm = uf.norm();
    if (!(norm > 0.0))
    {
      continue;
    }
    const Eigen::Vector3d& n = normal[static_cast<size_t>(f)];
    Eigen::Vector3d ds = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hs = Eigen::Matrix3d::Zero();
    const int skipped = AlignmentAxis(this->AlignmentLabel, f);
    for (int i = 0; i < 3; ++i)
    {
      if (i == skipped)
      {
        continue;
      }
      const double si = std::sqrt(uf(i) * uf(i) + eps * norm * norm);
      Eigen::Vector3d q = eps * uf;
      q(i) += uf(i);
      ds += q / si;
      if (h)
      {
        Eigen::Matrix3d d = eps * Eigen::Matrix3d::Identity();
        d(i, i) += 1.0;
        hs += d / si - q * q.transpose() / (si * si * si);
      }
    }
    const Eigen::Vector3d du = w.Alignment * (ds - alignment * n) / area + areaFactor * n;
    const Eigen::Vector3d& a1 = e1[static_cast<size_t>(f)];
    const Eigen::Vector3d& a2 = e2[static_cast<size_t>(f)];
    const Eigen::Vector3d g1 = 0.5 * a2.cross(du);
    const Eigen::Vector3d g2 = 0.5 * du.cross(a1);
    gradient.segment<3>(3 * this->Faces(f, 1)) += g1;
    gradient.segment<3>(3 * this->Faces(f, 2)) += g2;
    gradient.segment<3>(3 * this->Faces(f, 0)) -= g1 + g2;
    if (areaGradient)
    {
      const Eigen::Vector3d b1 = 0.5 * a2.cross(n);
      const Eigen::Vector3d b2 = 0.5 * n.cross(a1);
      areaGradient->segment<3>(3 * this->Faces(f, 1)) += b1;
      areaGradient->segment<3>(3 * this->Faces(f, 2)) += b2;
      areaGradient->segment<3>(3 * this->Faces(f, 0)) -= b1 + b2;
    }
    if (h)
    {
      // Gauss-Newton in u: the curvature of u(x) itself (bilinear) is left out.
      const Eigen::Matrix3d tangent = (Eigen::Matrix3d::Identity() - n * n.transpose()) / norm;
      const Eigen::Matrix3d hu =
        ProjectPsd(w.Alignment * (hs - alignment * tangent) / area + areaFactor * tangent);
      std::array<Eigen::Matrix3d, 3> ju;
      ju[1] = -0.5 * Cross(a2);
      ju[2] = 0.5 * Cross(a1);
      ju[0] = -ju[1] - ju[2];
      std::array<Eigen::Matrix3d, 3> hj;
      for (int i = 0; i < 3; ++i)
      {
        hj[static_cast<size_t>(i)] = hu * ju[static_cast<size_t>(i)];
      }
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          AddBlock(h,
            this->Blocks,
            this->FacePairs[static_cast<size_t>(f)][static_cast<size_t>(3 * i + j)],
            ju[static_cast<size_t>(i)].transpose() * hj[static_cast<size_t>(j)]);
        }
      }
    }
  }

  // Normal difference, eq. (12); Gauss-Newton Hessian.
  if (w.NormalDifference != 0.0)
  {
    std::vector<std::array<Eigen::Matrix3d, 3>> jn(static_cast<size_t>(faceCount));
    for (int f = 0; f < faceCount; ++f)
    {
      const double norm2 = 2.0 * u[static_cast<size_t>(f)].norm();
      const Eigen::Vector3d& n = normal[static_cast<size_t>(f)];
      const Eigen::Matrix3d p = norm2 > 0.0
        ? Eigen::Matrix3d((Eigen::Matrix3d::Identity() - n * n.transpose()) / norm2)
        : Eigen::Matrix3d::Zero();
      auto& jf = jn[static_cast<size_t>(f)];
      jf[1] = -p * Cross(e2[static_cast<size_t>(f)]);
      jf[2] = p * Cross(e1[static_cast<size_t>(f)]);
      jf[0] = -jf[1] - jf[2];
    }
    for (const DiffEdge& edge : this->DiffEdges)
    {
      const int f = edge.Faces[0];
      const int g = edge.Faces[1];
      // d = R n_f - n_g, its Jacobian per vertex of the edge.
      const Eigen::Vector3d d =
        (edge.Rotated ? Eigen::Vector3d(edge.Rotation * normal[static_cast<size_t>(f)])
                      : normal[static_cast<size_t>(f)]) -
        normal[static_cast<size_t>(g)];
      const double c = 2.0 * w.NormalDifference * edge.Weight;
      const int count = edge.VertexCount;
      std::array<Eigen::Matrix3d, 6> jd;
      for (int k = 0; k < 3; ++k)
      {
        jd[static_cast<size_t>(k)] = edge.Rotated
          ? Eigen::Matrix3d(edge.Rotation * jn[static_cast<size_t>(f)][static_cast<size_t>(k)])
          : jn[static_cast<size_t>(f)][static_cast<size_t>(k)];
      }
      for (int k = 3; k < count; ++k)
      {
        jd[static_cast<size_t>(k)].setZero();
      }
      for (int k = 0; k < 3; ++k)
      {
        jd[static_cast<size_t>(edge.Face1Slots[static_cast<size_t>(k)])] -=
          jn[static_cast<size_t>(g)][static_cast<size_t>(k)];
      }
      for (int k = 0; k < count; ++k)
      {
        gradient.segment<3>(3 * edge.Vertices[static_cast<size_t>(k)]) +=
          c * jd[static_cast<size_t>(k)].transpose() * d;
      }
      if (h)
      {
        for (int i = 0; i < count; ++i)
        {
          for (int j = 0; j < count; ++j)
          {
            AddBlock(h,
              this->Blocks,
              edge.Pairs[static_cast<size_t>(6 * i + j)],
              c * jd[static_cast<size_t>(i)].transpose() * jd[static_cast<size_t>(j)]);
          }
        }
      }
    }
  }
  return true;
}

} // namespace polycubehex
