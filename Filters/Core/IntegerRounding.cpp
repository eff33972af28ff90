// SPDX-License-Identifier: BSD-3-Clause
#include "IntegerRounding.h"

#include "CoordinateRelations.h"
#include "PolycubePlaneRelaxation.h"
#include "TetDistortionQuadratic.h"

#include "DisjointSets.h"
#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/Sparse>
#include <ceres/first_order_function.h>
#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/iteration_callback.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace polycubehex
{
namespace
{
constexpr int FaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

const char* const LabelNames[6] = { "+X", "-X", "+Y", "-Y", "+Z", "-Z" };


void Unite(std::vector<int>& parent, int a, int b)
{
  a = FindRoot(parent, a);
  b = FindRoot(parent, b);
  if (a != b)
  {
    parent[std::max(a, b)] = std::min(a, b);
  }
}

double SignedVolume(const Points& x, const Tets& cells, int t)
{
  const Eigen::Vector3d a = x.row(cells(t, 0)).transpose();
  const Eigen::Vector3d b = x.row(cells(t, 1)).transpose();
  const Eigen::Vector3d c = x.row(cells(t, 2)).transpose();
  const Eigen::Vector3d d = x.row(cells(t, 3)).transpose();
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

/// Whether every tet stays positive when each plane's coordinates are set to their mean: the
/// relaxation's shared-plane start (PolycubePlaneRelaxation.cpp). Invariant under scaling.
bool ChartsCanBeFlat(const Points& reference, const Tets& cells, const ChartPlanes& charts)
{
  const int planeCount = static_cast<int>(charts.PlaneAxis.size());
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(planeCount);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(planeCount);
  for (int v = 0; v < reference.rows(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int p = charts.VertexPlane(v, a);
      if (p >= 0)
      {
        sum[p] += reference(v, a);
        count[p] += 1.0;
      }
    }
  }
  Points flat = reference;
  for (int v = 0; v < reference.rows(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int p = charts.VertexPlane(v, a);
      if (p >= 0)
      {
        flat(v, a) = sum[p] / count[p];
      }
    }
  }
  for (int t = 0; t < cells.rows(); ++t)
  {
    if (!(SignedVolume(flat, cells, t) > 0.0))
    {
      return false;
    }
  }
  return true;
}

/// Face adjacency through sorted vertex triples; counts faces used by more than two tets.
int ComputeNeighbors(const Tets& cells, Tets& neighbors)
{
  struct Key
  {
    std::array<int, 3> Sorted;
    int Tet;
    int Local;
  };
  const int tetCount = static_cast<int>(cells.rows());
  std::vector<Key> keys;
  keys.reserve(4 * static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      Key key{
        { cells(t, FaceTable[k][0]), cells(t, FaceTable[k][1]), cells(t, FaceTable[k][2]) }, t, k
      };
      std::sort(key.Sorted.begin(), key.Sorted.end());
      keys.push_back(key);
    }
  }
  std::sort(keys.begin(),
    keys.end(),
    [](const Key& a, const Key& b)
    { return a.Sorted != b.Sorted ? a.Sorted < b.Sorted : a.Tet < b.Tet; });
  neighbors.setConstant(tetCount, 4, -1);
  int nonManifold = 0;
  for (size_t i = 0; i < keys.size();)
  {
    size_t j = i + 1;
    while (j < keys.size() && keys[j].Sorted == keys[i].Sorted)
    {
      ++j;
    }
    if (j - i == 2)
    {
      neighbors(keys[i].Tet, keys[i].Local) = keys[i + 1].Tet;
      neighbors(keys[i + 1].Tet, keys[i + 1].Local) = keys[i].Tet;
    }
    else if (j - i > 2)
    {
      ++nonManifold;
    }
    i = j;
  }
  return nonManifold;
}
} // namespace

Status ComputeChartPlanes(const Points& positions,
  const Tets& cells,
  const Tets& faceLabels,
  ChartPlanes& charts,
  const PolycubeSeams* seams)
{
  const int vertexCount = static_cast<int>(positions.rows());
  const int tetCount = static_cast<int>(cells.rows());
  if (tetCount > 0 && (cells.minCoeff() < 0 || cells.maxCoeff() >= vertexCount))
  {
    return Status::Failure("a tet refers to a vertex that does not exist");
  }
  if (faceLabels.rows() != cells.rows())
  {
    return Status::Failure("the polycube labels have " + std::to_string(faceLabels.rows()) +
      " rows for " + std::to_string(tetCount) + " tets");
  }
  const int nonManifold = ComputeNeighbors(cells, charts.Neighbors);
  if (nonManifold > 0)
  {
    return Status::Failure(std::to_string(nonManifold) + " faces are shared by more than two tets");
  }

  // Every boundary face needs a label and no interior face may have one.
  int unlabelled = 0;
  int interiorLabelled = 0;
  int firstBad = -1;
  std::vector<int> faces; // boundary faces as t * 4 + k
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int label = faceLabels(t, k);
      if (label < -1 || label > 5)
      {
        return Status::Failure("tet " + std::to_string(t) + " has the polycube label " +
          std::to_string(label) + " on face " + std::to_string(k) + " (valid: -1, 0..5)");
      }
      const bool seam = seams && seams->Neighbor.rows() == tetCount && seams->Neighbor(t, k) >= 0;
      if (seam && label >= 0)
      {
        ++interiorLabelled; // a cut face is inside M
      }
      if (seam)
      {
        continue;
      }
      const bool boundary = charts.Neighbors(t, k) < 0;
      if (boundary && label < 0)
      {
        firstBad = firstBad < 0 ? t : firstBad;
        ++unlabelled;
      }
      else if (!boundary && label >= 0)
      {
        ++interiorLabelled;
      }
      if (boundary)
      {
        faces.push_back(4 * t + k);
      }
    }
  }
  if (unlabelled > 0)
  {
    return Status::Failure(std::to_string(unlabelled) + " of " + std::to_string(faces.size()) +
      " boundary faces have no polycube label (first in tet " + std::to_string(firstBad) +
      "): hex extraction needs PolycubeLabels 0..5 on every boundary face");
  }
  if (interiorLabelled > 0)
  {
    return Status::Failure(std::to_string(interiorLabelled) +
      " interior faces carry a polycube label; only boundary faces may have one");
  }

  // Charts: boundary faces with one label joined through boundary edges.
  const int faceCount = static_cast<int>(faces.size());
  std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
  for (int f = 0; f < faceCount; ++f)
  {
    const int t = faces[f] / 4;
    const int k = faces[f] % 4;
    for (int e = 0; e < 3; ++e)
    {
      const int a = cells(t, FaceTable[k][e]);
      const int b = cells(t, FaceTable[k][(e + 1) % 3]);
      edgeFaces[{ std::min(a, b), std::max(a, b) }].push_back(f);
    }
  }
  std::vector<int> parent(faceCount);
  std::iota(parent.begin(), parent.end(), 0);
  auto labelOf = [&](int f) { return faceLabels(faces[f] / 4, faces[f] % 4); };
  for (const auto& entry : edgeFaces)
  {
    const std::vector<int>& around = entry.second;
    for (size_t i = 0; i < around.size(); ++i)
    {
      for (size_t j = i + 1; j < around.size(); ++j)
      {
        if (labelOf(around[i]) == labelOf(around[j]))
        {
          Unite(parent, around[i], around[j]);
        }
      }
    }
  }
  std::vector<int> chartOfRoot(faceCount, -1);
  charts.FaceChart.setConstant(tetCount, 4, -1);
  charts.ChartLabel.clear();
  for (int f = 0; f < faceCount; ++f)
  {
    const int root = FindRoot(parent, f);
    if (chartOfRoot[root] < 0)
    {
      chartOfRoot[root] = static_cast<int>(charts.ChartLabel.size());
      charts.ChartLabel.push_back(labelOf(f));
    }
    charts.FaceChart(faces[f] / 4, faces[f] % 4) = chartOfRoot[root];
  }
  const int chartCount = static_cast<int>(charts.ChartLabel.size());

  // Chart adjacency through boundary edges.
  std::vector<std::set<int>> neighborSets(chartCount);
  for (const auto& entry : edgeFaces)
  {
    for (int f : entry.second)
    {
      for (int g : entry.second)
      {
        const int cf = charts.FaceChart(faces[f] / 4, faces[f] % 4);
        const int cg = charts.FaceChart(faces[g] / 4, faces[g] % 4);
        if (cf != cg)
        {
          neighborSets[cf].insert(cg);
        }
      }
    }
  }
  charts.ChartNeighbors.assign(chartCount, {});
  for (int c = 0; c < chartCount; ++c)
  {
    charts.ChartNeighbors[c].assign(neighborSets[c].begin(), neighborSets[c].end());
  }

  // Planes: charts of one axis sharing a vertex give that vertex one coordinate, so they share
  // their plane.
  std::vector<std::vector<int>> vertexCharts(vertexCount);
  for (int f = 0; f < faceCount; ++f)
  {
    const int t = faces[f] / 4;
    const int k = faces[f] % 4;
    for (int c = 0; c < 3; ++c)
    {
      vertexCharts[cells(t, FaceTable[k][c])].push_back(charts.FaceChart(t, k));
    }
  }
  std::vector<int> chartParent(chartCount);
  std::iota(chartParent.begin(), chartParent.end(), 0);
  for (int v = 0; v < vertexCount; ++v)
  {
    for (size_t i = 0; i < vertexCharts[v].size(); ++i)
    {
      for (size_t j = i + 1; j < vertexCharts[v].size(); ++j)
      {
        const int a = vertexCharts[v][i];
        const int b = vertexCharts[v][j];
        if (charts.ChartLabel[a] / 2 == charts.ChartLabel[b] / 2)
        {
          Unite(chartParent, a, b);
        }
      }
    }
  }
  charts.ChartPlane.assign(chartCount, -1);
  charts.PlaneAxis.clear();
  for (int c = 0; c < chartCount; ++c)
  {
    const int root = FindRoot(chartParent, c);
    if (charts.ChartPlane[root] < 0)
    {
      charts.ChartPlane[root] = static_cast<int>(charts.PlaneAxis.size());
      charts.PlaneAxis.push_back(charts.ChartLabel[root] / 2);
    }
    charts.ChartPlane[c] = charts.ChartPlane[root];
  }
  charts.VertexPlane.setConstant(vertexCount, 3, -1);
  for (int v = 0; v < vertexCount; ++v)
  {
    for (int c : vertexCharts[v])
    {
      charts.VertexPlane(v, charts.ChartLabel[c] / 2) = charts.ChartPlane[c];
    }
  }

  // Where the positions put each plane: the mean coordinate of its vertices.
  std::vector<double> planeValue(charts.PlaneAxis.size(), 0.0);
  std::vector<int> planeCount(charts.PlaneAxis.size(), 0);
  for (int v = 0; v < vertexCount; ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int p = charts.VertexPlane(v, a);
      if (p >= 0)
      {
        planeValue[p] += positions(v, a);
        ++planeCount[p];
      }
    }
  }
  for (size_t p = 0; p < planeValue.size(); ++p)
  {
    planeValue[p] /= std::max(1, planeCount[p]);
  }

  // Plane pairs that must not collapse, each stored (lower, upper).
  std::set<std::array<int, 2>> pairs;
  auto addPair = [&](int low, int high)
  {
    if (low >= 0 && high >= 0 && low != high && planeValue[low] < planeValue[high])
    {
      pairs.insert({ low, high });
    }
  };
  // A tet whose vertices lie on two planes of one axis is flattened if they meet.
  for (int t = 0; t < tetCount; ++t)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (int i = 0; i < 4; ++i)
      {
        for (int j = 0; j < 4; ++j)
        {
          addPair(charts.VertexPlane(cells(t, i), a), charts.VertexPlane(cells(t, j), a));
        }
      }
    }
  }
  // A chart C spans, along an axis b of a neighbour D, from the neighbours it leaves towards +b
  // (it lies above them) to those it leaves towards -b: each such lower bound must stay below
  // each upper bound. Two neighbours on the same side (steps of a staircase seen from the big
  // chart on top of it) are not constrained through C: only the riser between them is.
  std::vector<std::set<int>> lowerBounds(chartCount);
  std::vector<std::set<int>> upperBounds(chartCount);
  for (const auto& entry : edgeFaces)
  {
    const std::vector<int>& around = entry.second;
    for (int f : around)
    {
      for (int g : around)
      {
        const int cf = charts.FaceChart(faces[f] / 4, faces[f] % 4);
        const int cg = charts.FaceChart(faces[g] / 4, faces[g] % 4);
        const int b = charts.ChartLabel[cg] / 2;
        if (cf == cg || charts.ChartLabel[cf] / 2 == b)
        {
          continue;
        }
        // The corner of face f off the shared edge tells on which side of D's plane C lies.
        const int t = faces[f] / 4;
        const int k = faces[f] % 4;
        double offset = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          const int w = cells(t, FaceTable[k][c]);
          if (w != entry.first.first && w != entry.first.second)
          {
            offset = positions(w, b) -
              0.5 * (positions(entry.first.first, b) + positions(entry.first.second, b));
          }
        }
        if (offset > 0.0)
        {
          lowerBounds[cf].insert(cg);
        }
        else if (offset < 0.0)
        {
          upperBounds[cf].insert(cg);
        }
      }
    }
  }
  for (int c = 0; c < chartCount; ++c)
  {
    for (int low : lowerBounds[c])
    {
      for (int high : upperBounds[c])
      {
        if (charts.ChartLabel[low] / 2 == charts.ChartLabel[high] / 2)
        {
          addPair(charts.ChartPlane[low], charts.ChartPlane[high]);
        }
      }
    }
  }
  charts.PlanePairs.assign(pairs.begin(), pairs.end());
  return Status::Success();
}

// ------------------------------------------------------------------------------------------

struct PolycubePlaneSolver::Impl
{
  Tets Cells;
  Points Reference;
  /// The coordinates (x[3v+a], row-major positions) as x = Bf f + Bz z + Offset: f the free
  /// variables, z the integer ones (plane values, then free cut translations). Each row has at
  /// most one free entry (a coordinate is a copy of one free representative or lies on a plane).
  Eigen::SparseMatrix<double> Bf;
  Eigen::SparseMatrix<double> Bz;
  Eigen::VectorXd Offset;
  /// #3V: the free variable of coordinate i and its coefficient (+-1), or -1.
  std::vector<int> RowFree;
  std::vector<double> RowFreeSign;
  /// Per free variable, the coordinates it moves (its column of Bf).
  std::vector<std::vector<std::pair<int, double>>> FreeRows;
  int FreeCount = 0;
  int IntegerCount = 0;
  std::vector<double> RestVolume;      ///< #T volumes in the rest positions
  std::vector<double> ReferenceVolume; ///< #T volumes in the reference polycube
  /// Per tet, the gradients of the 4 barycentric coordinates on the rest tet (rows).
  std::vector<Eigen::Matrix<double, 4, 3>> Gradients;
  /// Per tet, the Jacobian of the reference polycube with respect to the rest positions.
  std::vector<Eigen::Matrix3d> ReferenceJacobian;
  /// Per vertex, its tets.
  std::vector<std::vector<int>> VertexTets;
  Eigen::SparseMatrix<double> Acc; ///< free x free block
  Eigen::SparseMatrix<double> Acz; ///< free x integer block
  Eigen::VectorXd Bc;              ///< free part of the linear term
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> Factor;
  /// With cuts: the relations, to read the cut translations back from z.
  std::unique_ptr<CoordinateRelations> Relations;
  std::vector<int> IntegerColumn; ///< #Z: column of the relations' reduction
  int ReducedCount = 0;           ///< columns of the relations' reduction
  int CutCount = 0;
  /// Per chart plane: the row of one of its coordinates (its value is that coordinate).
  std::vector<int> PlaneRow;
};

PolycubePlaneSolver::PolycubePlaneSolver() = default;
PolycubePlaneSolver::~PolycubePlaneSolver() = default;

namespace
{
/// The uniform case: every coordinate on a plane is that plane's value, the others are free.
void UniformVariables(const ChartPlanes& charts,
  int vertexCount,
  std::vector<Eigen::Triplet<double>>& free,
  std::vector<Eigen::Triplet<double>>& integer,
  int& freeCount,
  int& integerCount)
{
  freeCount = 0;
  for (int v = 0; v < vertexCount; ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int p = charts.VertexPlane(v, a);
      if (p >= 0)
      {
        integer.emplace_back(3 * v + a, p, 1.0);
      }
      else
      {
        free.emplace_back(3 * v + a, freeCount++, 1.0);
      }
    }
  }
  integerCount = static_cast<int>(charts.PlaneAxis.size());
}
} // namespace

Status PolycubePlaneSolver::Build(const Points& rest,
  const Points& reference,
  const Tets& cells,
  const ChartPlanes& charts,
  const PolycubeSeams* seams)
{
  this->Data = std::make_unique<Impl>();
  Impl& d = *this->Data;
  const int vertexCount = static_cast<int>(reference.rows());
  const int tetCount = static_cast<int>(cells.rows());
  const int planeCount = static_cast<int>(charts.PlaneAxis.size());
  const int n = 3 * vertexCount;
  d.Cells = cells;
  d.Reference = reference;
  if (charts.VertexPlane.rows() != vertexCount)
  {
    return Status::Failure("the charts were computed for another vertex count");
  }
  if (rest.rows() != vertexCount)
  {
    return Status::Failure("the rest and reference positions differ in size");
  }
  const Eigen::VectorXd referenceVector =
    Eigen::Map<const Eigen::VectorXd>(reference.data(), n);
  d.PlaneRow.assign(static_cast<size_t>(planeCount), -1);
  for (int v = vertexCount - 1; v >= 0; --v)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (charts.VertexPlane(v, a) >= 0)
      {
        d.PlaneRow[static_cast<size_t>(charts.VertexPlane(v, a))] = 3 * v + a;
      }
    }
  }

  // 1. The variables.
  std::vector<Eigen::Triplet<double>> freeTriplets;
  std::vector<Eigen::Triplet<double>> integerTriplets;
  d.Offset.setZero(n);
  if (!seams || seams->Empty())
  {
    UniformVariables(charts, vertexCount, freeTriplets, integerTriplets, d.FreeCount, d.IntegerCount);
    this->Pairs = charts.PlanePairs;
    this->VariablePlane.resize(static_cast<size_t>(planeCount));
    std::iota(this->VariablePlane.begin(), this->VariablePlane.end(), 0);
  }
  else
  {
    // Copies across the cuts (x_plus = Pi x_minus + t_c, extras 3c..3c+2) and every coordinate
    // of a plane equal to the plane's first one, reduced by identifying variables.
    d.CutCount = seams->CutCount();
    std::vector<int> extraAxis(static_cast<size_t>(3 * d.CutCount));
    for (size_t k = 0; k < extraAxis.size(); ++k)
    {
      extraAxis[k] = static_cast<int>(k % 3);
    }
    d.Relations = std::make_unique<CoordinateRelations>(vertexCount, 3 * d.CutCount, extraAxis);
    for (const SeamCopy& copy : seams->Copies)
    {
      const Eigen::Matrix3i& pi = seams->Rotations[static_cast<size_t>(copy.Cut)];
      for (int a = 0; a < 3; ++a)
      {
        for (int b = 0; b < 3; ++b)
        {
          if (pi(a, b) != 0)
          {
            d.Relations->Relate(
              3 * copy.Plus + a, 3 * copy.Minus + b, pi(a, b), { { 3 * copy.Cut + a, 1.0 } });
          }
        }
      }
    }
    for (int i = 0; i < n; ++i)
    {
      const int p = charts.VertexPlane(i / 3, i % 3);
      if (p >= 0 && d.PlaneRow[static_cast<size_t>(p)] != i)
      {
        d.Relations->Relate(i, d.PlaneRow[static_cast<size_t>(p)], 1.0);
      }
    }
    VariableReduction reduction;
    Status status = d.Relations->Build(reduction);
    if (!status)
    {
      return Status::Failure("the cut transitions and the chart planes contradict each other: " +
        status.Message());
    }
    d.ReducedCount = reduction.VariableCount();
    // A column is an integer variable when it carries a plane or is a free translation.
    std::vector<int> kind(static_cast<size_t>(d.ReducedCount), 0); // 0 free, 1 plane, 2 t
    for (int column : d.Relations->FreeExtraVariables())
    {
      kind[static_cast<size_t>(column)] = 2;
    }
    for (int column = 0; column < d.ReducedCount; ++column)
    {
      for (Eigen::SparseMatrix<double>::InnerIterator it(reduction.B, column); it; ++it)
      {
        const int i = static_cast<int>(it.row());
        if (kind[static_cast<size_t>(column)] == 0 && charts.VertexPlane(i / 3, i % 3) >= 0)
        {
          kind[static_cast<size_t>(column)] = 1;
        }
      }
    }
    std::vector<int> index(static_cast<size_t>(d.ReducedCount), -1);
    d.FreeCount = 0;
    d.IntegerCount = 0;
    for (int column = 0; column < d.ReducedCount; ++column)
    {
      if (kind[static_cast<size_t>(column)] == 0)
      {
        index[static_cast<size_t>(column)] = d.FreeCount++;
      }
      else
      {
        index[static_cast<size_t>(column)] = d.IntegerCount++;
        d.IntegerColumn.push_back(column);
      }
    }
    for (int column = 0; column < d.ReducedCount; ++column)
    {
      for (Eigen::SparseMatrix<double>::InnerIterator it(reduction.B, column); it; ++it)
      {
        (kind[static_cast<size_t>(column)] == 0 ? freeTriplets : integerTriplets)
          .emplace_back(static_cast<int>(it.row()), index[static_cast<size_t>(column)], it.value());
      }
    }
    d.Offset = reduction.Offset;
    // The reference values of the integer variables: the least-squares fit of the reference.
    const Eigen::VectorXd fit = reduction.Restrict(referenceVector);
    this->RefPlanes.resize(d.IntegerCount);
    for (int z = 0; z < d.IntegerCount; ++z)
    {
      this->RefPlanes[z] = fit[d.IntegerColumn[static_cast<size_t>(z)]];
    }
    // Each plane's value as a row of (Bz z + Offset); a separated pair of planes stays a pair of
    // integer variables when both are the same function of the translations (one frame).
    Eigen::SparseMatrix<double, Eigen::RowMajor> rows(n, d.IntegerCount);
    rows.setFromTriplets(integerTriplets.begin(), integerTriplets.end());
    this->VariablePlane.assign(static_cast<size_t>(d.IntegerCount), -1);
    std::vector<int> planeVariable(static_cast<size_t>(planeCount), -1);
    std::vector<double> planeSign(static_cast<size_t>(planeCount), 0.0);
    std::vector<std::map<int, double>> planeTerms(static_cast<size_t>(planeCount));
    for (int p = 0; p < planeCount; ++p)
    {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(
             rows, d.PlaneRow[static_cast<size_t>(p)]);
           it;
           ++it)
      {
        const int z = static_cast<int>(it.col());
        if (kind[static_cast<size_t>(d.IntegerColumn[static_cast<size_t>(z)])] == 1)
        {
          planeVariable[static_cast<size_t>(p)] = z;
          planeSign[static_cast<size_t>(p)] = it.value();
          if (this->VariablePlane[static_cast<size_t>(z)] < 0)
          {
            this->VariablePlane[static_cast<size_t>(z)] = p;
          }
        }
        else
        {
          planeTerms[static_cast<size_t>(p)][z] = it.value();
        }
      }
    }
    for (const auto& pair : charts.PlanePairs)
    {
      const size_t p = static_cast<size_t>(pair[0]);
      const size_t q = static_cast<size_t>(pair[1]);
      if (planeVariable[p] >= 0 && planeVariable[q] >= 0 && planeVariable[p] != planeVariable[q] &&
        planeSign[p] == planeSign[q] && planeTerms[p] == planeTerms[q])
      {
        this->Pairs.push_back({ planeVariable[p], planeVariable[q] });
      }
    }
  }
  d.Bf.resize(n, d.FreeCount);
  d.Bf.setFromTriplets(freeTriplets.begin(), freeTriplets.end());
  d.Bz.resize(n, d.IntegerCount);
  d.Bz.setFromTriplets(integerTriplets.begin(), integerTriplets.end());
  d.RowFree.assign(static_cast<size_t>(n), -1);
  d.RowFreeSign.assign(static_cast<size_t>(n), 0.0);
  d.FreeRows.assign(static_cast<size_t>(d.FreeCount), {});
  for (int column = 0; column < d.FreeCount; ++column)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(d.Bf, column); it; ++it)
    {
      d.RowFree[static_cast<size_t>(it.row())] = column;
      d.RowFreeSign[static_cast<size_t>(it.row())] = it.value();
      d.FreeRows[static_cast<size_t>(column)].emplace_back(static_cast<int>(it.row()), it.value());
    }
  }
  if (!seams || seams->Empty())
  {
    // Reference plane values: the mean coordinate of their vertices.
    this->RefPlanes = Eigen::VectorXd::Zero(d.IntegerCount);
    Eigen::VectorXd counts = Eigen::VectorXd::Zero(d.IntegerCount);
    for (int v = 0; v < vertexCount; ++v)
    {
      for (int a = 0; a < 3; ++a)
      {
        const int p = charts.VertexPlane(v, a);
        if (p >= 0)
        {
          this->RefPlanes[p] += reference(v, a);
          counts[p] += 1.0;
        }
      }
    }
    for (int p = 0; p < d.IntegerCount; ++p)
    {
      this->RefPlanes[p] /= std::max(1.0, counts[p]);
    }
  }

  // 2. FEM stiffness of each tet on the rest positions: K_ij = V grad(l_i) . grad(l_j),
  // identical for the three axes. The linear term is K times the reference, so that the
  // reference is the unconstrained minimiser.
  d.VertexTets.assign(vertexCount, {});
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      d.VertexTets[cells(t, k)].push_back(t);
    }
  }
  d.RestVolume.resize(tetCount);
  d.ReferenceVolume.resize(tetCount);
  d.Gradients.resize(tetCount);
  d.ReferenceJacobian.resize(tetCount);
  std::vector<Eigen::Triplet<double>> stiffnessTriplets;
  stiffnessTriplets.reserve(static_cast<size_t>(48 * tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    Eigen::Matrix3d edges;
    Eigen::Matrix3d mapped;
    for (int i = 0; i < 3; ++i)
    {
      edges.col(i) = (rest.row(cells(t, i + 1)) - rest.row(cells(t, 0))).transpose();
      mapped.col(i) = (reference.row(cells(t, i + 1)) - reference.row(cells(t, 0))).transpose();
    }
    const double volume = edges.determinant() / 6.0;
    d.ReferenceVolume[t] = mapped.determinant() / 6.0;
    if (!(volume > 0.0) || !(d.ReferenceVolume[t] > 0.0))
    {
      return Status::Failure("tet " + std::to_string(t) + " is inverted or flat in the " +
        (volume > 0.0 ? "polycube" : "rest positions"));
    }
    d.RestVolume[t] = volume;
    const Eigen::Matrix3d inverse = edges.inverse();
    Eigen::Matrix<double, 4, 3> gradients;
    gradients.block<3, 3>(1, 0) = inverse;
    gradients.row(0) = -inverse.colwise().sum();
    d.Gradients[t] = gradients;
    d.ReferenceJacobian[t] = mapped * inverse;
    const Eigen::Matrix4d stiffness = volume * gradients * gradients.transpose();
    for (int a = 0; a < 3; ++a)
    {
      for (int i = 0; i < 4; ++i)
      {
        for (int j = 0; j < 4; ++j)
        {
          stiffnessTriplets.emplace_back(3 * cells(t, i) + a, 3 * cells(t, j) + a, stiffness(i, j));
        }
      }
    }
  }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(stiffnessTriplets.begin(), stiffnessTriplets.end());
  const Eigen::VectorXd linear = laplacian * (referenceVector - d.Offset);
  const Eigen::SparseMatrix<double> bft = d.Bf.transpose();
  const Eigen::SparseMatrix<double> bzt = d.Bz.transpose();
  const Eigen::SparseMatrix<double> lbf = laplacian * d.Bf;
  d.Acc = bft * lbf;
  d.Acz = bft * (laplacian * d.Bz);
  const Eigen::SparseMatrix<double> azz = bzt * (laplacian * d.Bz);
  d.Bc = bft * linear;
  const Eigen::VectorXd bz = bzt * linear;

  if (d.FreeCount > 0)
  {
    d.Factor.compute(d.Acc);
    if (d.Factor.info() != Eigen::Success || (d.Factor.vectorD().array() <= 0.0).any())
    {
      return Status::Failure("the polycube's free coordinates are not pinned by its charts (a "
                             "connected part lacks charts of some axis)");
    }
  }

  // 3. Schur complement onto the integer variables: H = Azz - Azc Acc^-1 Acz,
  // g = bz - Azc Acc^-1 bc.
  this->H = Eigen::MatrixXd(azz);
  this->G = bz;
  if (d.FreeCount > 0)
  {
    const Eigen::SparseMatrix<double> azc = d.Acz.transpose();
    for (int p = 0; p < d.IntegerCount; ++p)
    {
      const Eigen::VectorXd column = Eigen::VectorXd(d.Acz.col(p));
      if (column.squaredNorm() == 0.0)
      {
        continue;
      }
      const Eigen::VectorXd z = d.Factor.solve(column);
      this->H.col(p) -= azc * z;
    }
    this->G -= azc * d.Factor.solve(d.Bc);
  }
  this->H = 0.5 * (this->H + this->H.transpose()).eval();
  return Status::Success();
}

void PolycubePlaneSolver::Solve(const Eigen::VectorXd& planes, Points& positions) const
{
  const Impl& d = *this->Data;
  const int vertexCount = static_cast<int>(d.Reference.rows());
  Eigen::VectorXd x = d.Bz * planes + d.Offset;
  if (d.FreeCount > 0)
  {
    x += d.Bf * d.Factor.solve(d.Bc - d.Acz * planes);
  }
  positions.resize(vertexCount, 3);
  Eigen::Map<Eigen::VectorXd>(positions.data(), 3 * vertexCount) = x;
}

std::vector<Eigen::Vector3d> PolycubePlaneSolver::CutTranslations(
  const Eigen::VectorXd& planes) const
{
  const Impl& d = *this->Data;
  std::vector<Eigen::Vector3d> result(static_cast<size_t>(d.CutCount), Eigen::Vector3d::Zero());
  if (!d.Relations)
  {
    return result;
  }
  Eigen::VectorXd y = Eigen::VectorXd::Zero(d.ReducedCount);
  for (int z = 0; z < d.IntegerCount; ++z)
  {
    y[d.IntegerColumn[static_cast<size_t>(z)]] = planes[z];
  }
  const Eigen::VectorXd t = d.Relations->Extras(y);
  for (int c = 0; c < d.CutCount; ++c)
  {
    result[static_cast<size_t>(c)] = t.segment<3>(3 * c);
  }
  return result;
}

Eigen::VectorXd PolycubePlaneSolver::ChartPlaneValues(const Eigen::VectorXd& planes) const
{
  const Impl& d = *this->Data;
  const Eigen::VectorXd x = d.Bz * planes + d.Offset;
  Eigen::VectorXd values(static_cast<Eigen::Index>(d.PlaneRow.size()));
  for (size_t p = 0; p < d.PlaneRow.size(); ++p)
  {
    values[static_cast<Eigen::Index>(p)] = d.PlaneRow[p] >= 0 ? x[d.PlaneRow[p]] : 0.0;
  }
  return values;
}

double PolycubePlaneSolver::Untangle(Points& positions, double target) const
{
  const Impl& d = *this->Data;
  const int tetCount = static_cast<int>(d.Cells.rows());
  auto ratio = [&](int t) { return SignedVolume(positions, d.Cells, t) / d.ReferenceVolume[t]; };
  // Vertices with a free coordinate in a tet below the target, a few sweeps of a pattern search
  // that maximises the smallest volume ratio of their tets along their free axes.
  for (int sweep = 0; sweep < 8; ++sweep)
  {
    std::vector<int> vertices;
    for (int t = 0; t < tetCount; ++t)
    {
      if (ratio(t) < target)
      {
        for (int k = 0; k < 4; ++k)
        {
          vertices.push_back(d.Cells(t, k));
        }
      }
    }
    if (vertices.empty())
    {
      break;
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for (int v : vertices)
    {
      // A free variable moves every copy of its coordinate (across cuts), so the tets that
      // count are those around all of them.
      std::vector<int> around;
      auto gather = [&](int variable)
      {
        for (const auto& row : d.FreeRows[static_cast<size_t>(variable)])
        {
          const std::vector<int>& tets = d.VertexTets[row.first / 3];
          around.insert(around.end(), tets.begin(), tets.end());
        }
      };
      for (int a = 0; a < 3; ++a)
      {
        if (d.RowFree[static_cast<size_t>(3 * v + a)] >= 0)
        {
          gather(d.RowFree[static_cast<size_t>(3 * v + a)]);
        }
      }
      if (around.empty())
      {
        continue;
      }
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      auto worst = [&]()
      {
        double result = std::numeric_limits<double>::max();
        for (int t : around)
        {
          result = std::min(result, ratio(t));
        }
        return result;
      };
      double current = worst();
      if (current >= target)
      {
        continue;
      }
      // Step: a fraction of the shortest reference edge at v.
      double length = std::numeric_limits<double>::max();
      for (int t : d.VertexTets[v])
      {
        for (int k = 0; k < 4; ++k)
        {
          const int w = d.Cells(t, k);
          if (w != v)
          {
            length = std::min(length, (d.Reference.row(w) - d.Reference.row(v)).norm());
          }
        }
      }
      auto move = [&](int variable, double delta)
      {
        for (const auto& row : d.FreeRows[static_cast<size_t>(variable)])
        {
          positions(row.first / 3, row.first % 3) += row.second * delta;
        }
      };
      int moves = 0;
      for (double step = 0.5 * length; step > length / 512.0 && moves < 64 && current < target;
           ++moves)
      {
        bool improved = false;
        for (int a = 0; a < 3; ++a)
        {
          const int variable = d.RowFree[static_cast<size_t>(3 * v + a)];
          if (variable < 0)
          {
            continue;
          }
          const double sign0 = d.RowFreeSign[static_cast<size_t>(3 * v + a)];
          for (double sign : { 1.0, -1.0 })
          {
            move(variable, sign * sign0 * step);
            const double moved = worst();
            if (moved > current)
            {
              current = moved;
              improved = true;
            }
            else
            {
              move(variable, -sign * sign0 * step);
            }
          }
        }
        if (!improved)
        {
          step *= 0.5;
        }
      }
    }
  }
  return this->MinVolumeRatio(positions);
}

namespace
{
/// The energy the nonlinear untangling minimises over the free coordinates: the distortion
/// energy (a quadratic form, TetDistortionQuadratic.h) plus a penalty
/// Weight * sum_t w_t ((Target - r_t) / Target)^2 on every tet whose volume ratio r_t is below
/// Target (w_t its share of the rest volume). A penalty, not a barrier, so that it can start
/// from inverted tets.
class UntangleFunction : public ceres::FirstOrderFunction
{
public:
  UntangleFunction(const Points& start,
    const Tets& cells,
    const Eigen::SparseMatrix<double>& freeMap,
    const Eigen::SparseMatrix<double>& freeMapTransposed,
    const Eigen::VectorXd& constant,
    const TetDistortionQuadratic& distortion,
    const std::vector<double>& weights,
    const std::vector<double>& referenceVolume,
    double target,
    double weight)
    : Cells(cells)
    , FreeMap(freeMap)
    , FreeMapTransposed(freeMapTransposed)
    , Constant(constant)
    , Distortion(distortion)
    , Weights(weights)
    , ReferenceVolume(referenceVolume)
    , Target(target)
    , Weight(weight)
    , X(start)
    , G(start.rows(), 3)
  {
  }

  int NumParameters() const override { return static_cast<int>(this->FreeMap.cols()); }

  /// Writes the positions x = FreeMap y + Constant.
  void Scatter(const double* y, Points& x) const
  {
    const Eigen::Map<const Eigen::VectorXd> free(y, this->FreeMap.cols());
    Eigen::Map<Eigen::VectorXd>(x.data(), x.size()) = this->FreeMap * free + this->Constant;
  }

  bool Evaluate(const double* y, double* cost, double* gradient) const override
  {
    this->Scatter(y, this->X);
    double energy = this->Distortion.Evaluate(this->X, gradient ? &this->G : nullptr);
    // The penalty: only the few tets below the target contribute.
    for (int t = 0; t < static_cast<int>(this->Cells.rows()); ++t)
    {
      const Eigen::Vector3d a = this->X.row(this->Cells(t, 0)).transpose();
      const Eigen::Vector3d b = this->X.row(this->Cells(t, 1)).transpose();
      const Eigen::Vector3d c = this->X.row(this->Cells(t, 2)).transpose();
      const Eigen::Vector3d d = this->X.row(this->Cells(t, 3)).transpose();
      const Eigen::Vector3d gb = (c - a).cross(d - a);
      const double ratio = (b - a).dot(gb) / (6.0 * this->ReferenceVolume[t]);
      const double shortfall = (this->Target - ratio) / this->Target;
      if (!(shortfall > 0.0))
      {
        continue;
      }
      const double w = this->Weights[static_cast<size_t>(t)];
      energy += this->Weight * w * shortfall * shortfall;
      if (gradient)
      {
        // d ratio / d vertex: the gradients of the signed volume, over 6 V_ref.
        const double scale =
          -2.0 * this->Weight * w * shortfall / this->Target / (6.0 * this->ReferenceVolume[t]);
        const Eigen::Vector3d gc = (d - a).cross(b - a);
        const Eigen::Vector3d gd = (b - a).cross(c - a);
        this->G.row(this->Cells(t, 0)) -= scale * (gb + gc + gd).transpose();
        this->G.row(this->Cells(t, 1)) += scale * gb.transpose();
        this->G.row(this->Cells(t, 2)) += scale * gc.transpose();
        this->G.row(this->Cells(t, 3)) += scale * gd.transpose();
      }
    }
    *cost = energy;
    if (gradient)
    {
      Eigen::Map<Eigen::VectorXd>(gradient, this->FreeMap.cols()) =
        this->FreeMapTransposed * Eigen::Map<const Eigen::VectorXd>(this->G.data(), this->G.size());
    }
    return true;
  }

private:
  const Tets& Cells;
  const Eigen::SparseMatrix<double>& FreeMap;
  const Eigen::SparseMatrix<double>& FreeMapTransposed;
  const Eigen::VectorXd& Constant;
  const TetDistortionQuadratic& Distortion;
  const std::vector<double>& Weights;
  const std::vector<double>& ReferenceVolume;
  double Target;
  double Weight;
  mutable Points X;
  mutable Points G;
};

/// Ends an L-BFGS run of the untangling once the count of tets below a ratio has not fallen
/// for `Window` iterations: where the charts cannot all be flat some tets cannot be freed, and
/// the iterations after the last one freed only polish the distortion at full cost.
class UntangleStallCallback : public ceres::IterationCallback
{
public:
  UntangleStallCallback(const UntangleFunction& function,
    const double* y,
    const Points& start,
    const Tets& cells,
    const std::vector<double>& referenceVolume,
    double threshold,
    int window)
    : Function(function)
    , Y(y)
    , X(start)
    , Cells(cells)
    , ReferenceVolume(referenceVolume)
    , Threshold(threshold)
    , Window(window)
  {
  }

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
  {
    if (summary.iteration == 0 || summary.iteration % Check != 0)
    {
      return ceres::SOLVER_CONTINUE;
    }
    this->Function.Scatter(this->Y, this->X);
    int below = 0;
    for (int t = 0; t < static_cast<int>(this->Cells.rows()); ++t)
    {
      below += SignedVolume(this->X, this->Cells, t) / this->ReferenceVolume[t] < this->Threshold;
    }
    if (below < this->Fewest)
    {
      this->Fewest = below;
      this->LastFall = summary.iteration;
    }
    const bool stalled = summary.iteration - this->LastFall >= this->Window;
    return stalled ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

private:
  static constexpr int Check = 10;
  const UntangleFunction& Function;
  const double* Y;
  Points X;
  const Tets& Cells;
  const std::vector<double>& ReferenceVolume;
  double Threshold;
  int Window;
  int Fewest = std::numeric_limits<int>::max();
  int LastFall = 0;
};
} // namespace

double PolycubePlaneSolver::UntangleGlobally(Points& positions,
  double target,
  int rings,
  int stall) const
{
  const Impl& d = *this->Data;
  double ratio = this->MinVolumeRatio(positions);
  if (ratio >= target || d.FreeCount == 0)
  {
    return ratio;
  }
  // With rings >= 0 only a neighbourhood of the tets below the target moves: elsewhere the
  // linear re-solve is already the distortion's optimum, and an L-BFGS iteration then costs the
  // neighbourhood instead of the mesh.
  const int vertexCount = static_cast<int>(positions.rows());
  const int tetCount = static_cast<int>(d.Cells.rows());
  std::vector<char> inRegion(static_cast<size_t>(vertexCount), rings < 0 ? 1 : 0);
  for (int t = 0; t < tetCount && rings >= 0; ++t)
  {
    if (SignedVolume(positions, d.Cells, t) / d.ReferenceVolume[t] < target)
    {
      for (int k = 0; k < 4; ++k)
      {
        inRegion[static_cast<size_t>(d.Cells(t, k))] = 1;
      }
    }
  }
  for (int ring = 0; ring < rings; ++ring)
  {
    std::vector<char> grown = inRegion;
    for (int t = 0; t < tetCount; ++t)
    {
      bool touches = false;
      for (int k = 0; k < 4 && !touches; ++k)
      {
        touches = inRegion[static_cast<size_t>(d.Cells(t, k))] != 0;
      }
      if (touches)
      {
        for (int k = 0; k < 4; ++k)
        {
          grown[static_cast<size_t>(d.Cells(t, k))] = 1;
        }
      }
    }
    inRegion.swap(grown);
  }
  // The free variables with a coordinate in the region (with cuts, a variable also moves the
  // copies it is tied to, wherever they are), and every vertex they move.
  std::vector<int> variables;
  std::vector<char> moved(static_cast<size_t>(vertexCount), 0);
  for (int f = 0; f < d.FreeCount; ++f)
  {
    const auto& rows = d.FreeRows[static_cast<size_t>(f)];
    bool touches = false;
    for (const auto& row : rows)
    {
      touches = touches || inRegion[static_cast<size_t>(row.first / 3)] != 0;
    }
    if (touches)
    {
      variables.push_back(f);
      for (const auto& row : rows)
      {
        moved[static_cast<size_t>(row.first / 3)] = 1;
      }
    }
  }
  if (variables.empty())
  {
    return ratio;
  }
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> y(variables.size());
  for (size_t i = 0; i < variables.size(); ++i)
  {
    const auto& rows = d.FreeRows[static_cast<size_t>(variables[i])];
    for (const auto& row : rows)
    {
      entries.emplace_back(row.first, static_cast<int>(i), row.second);
    }
    // A free variable reads from one of its coordinates; the rest of x stays as it is.
    y[i] = positions(rows.front().first / 3, rows.front().first % 3) / rows.front().second;
  }
  Eigen::SparseMatrix<double> regionBasis(3 * vertexCount, static_cast<int>(variables.size()));
  regionBasis.setFromTriplets(entries.begin(), entries.end());
  const Eigen::VectorXd constant =
    Eigen::Map<const Eigen::VectorXd>(positions.data(), positions.size()) -
    regionBasis * Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
  // The tets a variable moves; the others' terms are constant.
  std::vector<int> tets;
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (moved[static_cast<size_t>(d.Cells(t, k))] != 0)
      {
        tets.push_back(t);
        break;
      }
    }
  }
  Tets regionCells(static_cast<Eigen::Index>(tets.size()), 4);
  std::vector<Eigen::Matrix<double, 4, 3>> gradients(tets.size());
  std::vector<Eigen::Matrix3d> targets(tets.size());
  std::vector<double> weights(tets.size());
  std::vector<double> referenceVolume(tets.size());
  const double totalVolume = std::accumulate(d.RestVolume.begin(), d.RestVolume.end(), 0.0);
  for (size_t i = 0; i < tets.size(); ++i)
  {
    const int t = tets[i];
    regionCells.row(static_cast<Eigen::Index>(i)) = d.Cells.row(t);
    gradients[i] = d.Gradients[static_cast<size_t>(t)];
    targets[i] = d.ReferenceJacobian[static_cast<size_t>(t)];
    weights[i] = d.RestVolume[static_cast<size_t>(t)] / totalVolume;
    referenceVolume[i] = d.ReferenceVolume[static_cast<size_t>(t)];
  }
  const TetDistortionQuadratic distortion(positions, regionCells, gradients, targets, weights);
  const Eigen::SparseMatrix<double> regionBasisTransposed = regionBasis.transpose();
  // Escalate the penalty until every tet is above half the target (or give up).
  for (double weight : { 1e2, 1e4, 1e6 })
  {
    auto* function = new UntangleFunction(positions,
      regionCells,
      regionBasis,
      regionBasisTransposed,
      constant,
      distortion,
      weights,
      referenceVolume,
      target,
      weight);
    ceres::GradientProblem problem(function);
    ceres::GradientProblemSolver::Options options;
    options.line_search_direction_type = ceres::LBFGS;
    options.max_num_iterations = 500;
    options.logging_type = ceres::SILENT;
    options.function_tolerance = 1e-12;
    options.gradient_tolerance = 1e-12;
    UntangleStallCallback stallCallback(
      *function, y.data(), positions, regionCells, referenceVolume, 0.5 * target, stall);
    if (stall > 0)
    {
      options.update_state_every_iteration = true;
      options.callbacks.push_back(&stallCallback);
    }
    ceres::GradientProblemSolver::Summary summary;
    ceres::Solve(options, problem, y.data(), &summary);
    function->Scatter(y.data(), positions);
    ratio = this->MinVolumeRatio(positions);
    if (ratio >= 0.5 * target)
    {
      break;
    }
  }
  return ratio;
}

const Eigen::SparseMatrix<double>& PolycubePlaneSolver::FreeBasis() const
{
  return this->Data->Bf;
}

double PolycubePlaneSolver::MinVolumeRatio(const Points& positions) const
{
  const Impl& d = *this->Data;
  double result = std::numeric_limits<double>::max();
  for (int t = 0; t < static_cast<int>(d.Cells.rows()); ++t)
  {
    result = std::min(result, SignedVolume(positions, d.Cells, t) / d.ReferenceVolume[t]);
  }
  return result;
}

namespace
{
/// Energy sum_t V_t |grad x - J_t|^2, gradients and volumes on the rest tets.
double DistortionEnergy(const Points& x,
  const Tets& cells,
  const std::vector<Eigen::Matrix<double, 4, 3>>& gradients,
  const std::vector<double>& volumes,
  const std::vector<Eigen::Matrix3d>& targets)
{
  double energy = 0.0;
  for (int t = 0; t < static_cast<int>(cells.rows()); ++t)
  {
    Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 4; ++i)
    {
      jacobian += x.row(cells(t, i)).transpose() * gradients[t].row(i);
    }
    energy += volumes[t] * (jacobian - targets[t]).squaredNorm();
  }
  return energy;
}

/// The difference constraints x_q - x_p >= 1 between planes that were apart, as a DAG from the
/// lower plane to the upper one; longest paths give the interval each plane may take.
class SeparationGraph
{
public:
  SeparationGraph(const std::vector<std::array<int, 2>>& pairs,
    const Eigen::VectorXd& reference,
    double tol)
  {
    const int planeCount = static_cast<int>(reference.size());
    this->Up.assign(planeCount, {});
    this->Down.assign(planeCount, {});
    for (const auto& pair : pairs)
    {
      const double gap = reference[pair[1]] - reference[pair[0]];
      if (std::fabs(gap) <= tol)
      {
        continue;
      }
      const int low = gap > 0.0 ? pair[0] : pair[1];
      const int high = gap > 0.0 ? pair[1] : pair[0];
      this->Up[low].push_back(high);
      this->Down[high].push_back(low);
      this->Pairs.push_back({ low, high });
    }
    // Topological order: increasing reference value (edges go strictly upwards).
    this->Order.resize(planeCount);
    std::iota(this->Order.begin(), this->Order.end(), 0);
    std::stable_sort(this->Order.begin(),
      this->Order.end(),
      [&reference](int a, int b) { return reference[a] < reference[b]; });
    this->Rank.resize(planeCount);
    for (int i = 0; i < planeCount; ++i)
    {
      this->Rank[this->Order[i]] = i;
    }
  }

  /// The integers plane p may take given the fixed planes: [low, high].
  void Interval(int p,
    const std::vector<bool>& fixed,
    const Eigen::VectorXd& values,
    double& low,
    double& high) const
  {
    const int planeCount = static_cast<int>(this->Order.size());
    low = -std::numeric_limits<double>::infinity();
    high = std::numeric_limits<double>::infinity();
    std::vector<int> distance(planeCount, -1);
    distance[p] = 0;
    for (int i = this->Rank[p]; i < planeCount; ++i) // longest paths upwards from p
    {
      const int u = this->Order[i];
      if (distance[u] < 0)
      {
        continue;
      }
      if (u != p && fixed[u])
      {
        high = std::min(high, values[u] - distance[u]);
      }
      for (int w : this->Up[u])
      {
        distance[w] = std::max(distance[w], distance[u] + 1);
      }
    }
    std::fill(distance.begin(), distance.end(), -1);
    distance[p] = 0;
    for (int i = this->Rank[p]; i >= 0; --i) // and downwards
    {
      const int u = this->Order[i];
      if (distance[u] < 0)
      {
        continue;
      }
      if (u != p && fixed[u])
      {
        low = std::max(low, values[u] + distance[u]);
      }
      for (int w : this->Down[u])
      {
        distance[w] = std::max(distance[w], distance[u] + 1);
      }
    }
  }

  /// The constraints as (lower, upper) pairs.
  const std::vector<std::array<int, 2>>& Edges() const { return this->Pairs; }

private:
  std::vector<std::array<int, 2>> Pairs;
  std::vector<std::vector<int>> Up;
  std::vector<std::vector<int>> Down;
  std::vector<int> Order;
  std::vector<int> Rank;
};

/// Minimises P^T H P - 2 g^T P over the free planes with the fixed ones held, plus a tiny pull
/// towards the current values that pins the translations the energy does not see, keeping each
/// separated pair (lower, upper) at least one unit apart: violated pairs become equalities
/// upper = lower + 1 (an active set that only grows), which chains planes into groups with
/// fixed offsets. The result predicts where the free planes will end, in the right order.
void SolveFreePlanes(const Eigen::MatrixXd& H,
  const Eigen::VectorXd& g,
  const std::vector<bool>& fixed,
  const std::vector<std::array<int, 2>>& separations,
  Eigen::VectorXd& planes)
{
  const int planeCount = static_cast<int>(fixed.size());
  const double regularisation = 1e-10 * std::max(1.0, H.diagonal().cwiseAbs().maxCoeff());
  std::vector<int> parent(planeCount);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<double> offset(planeCount, 0.0); // value(p) = value(parent[p]) + offset[p]
  auto root = [&](int p)
  {
    double total = 0.0;
    while (parent[p] != p)
    {
      total += offset[p];
      p = parent[p];
    }
    return std::make_pair(p, total);
  };
  const Eigen::VectorXd previous = planes;
  for (int round = 0; round <= planeCount; ++round)
  {
    // Groups: a group with a fixed plane is determined, the others are unknowns.
    std::vector<int> unknown(planeCount, -1);
    std::vector<double> known(planeCount, std::numeric_limits<double>::quiet_NaN());
    for (int p = 0; p < planeCount; ++p)
    {
      if (fixed[p])
      {
        const auto r = root(p);
        known[r.first] = planes[p] - r.second;
      }
    }
    int m = 0;
    for (int p = 0; p < planeCount; ++p)
    {
      if (parent[p] == p && std::isnan(known[p]))
      {
        unknown[p] = m++;
      }
    }
    if (m > 0)
    {
      // P = S y + c; minimise (S y + c)^T H (S y + c) - 2 g^T (S y + c) + reg |y - y_prev|^2.
      Eigen::MatrixXd S = Eigen::MatrixXd::Zero(planeCount, m);
      Eigen::VectorXd c = Eigen::VectorXd::Zero(planeCount);
      Eigen::VectorXd y0 = Eigen::VectorXd::Zero(m);
      Eigen::VectorXd count = Eigen::VectorXd::Zero(m);
      for (int p = 0; p < planeCount; ++p)
      {
        const auto r = root(p);
        c[p] = r.second;
        if (unknown[r.first] >= 0)
        {
          S(p, unknown[r.first]) = 1.0;
          y0[unknown[r.first]] += previous[p] - r.second;
          count[unknown[r.first]] += 1.0;
        }
        else
        {
          c[p] += known[r.first];
        }
      }
      y0 = y0.cwiseQuotient(count);
      Eigen::MatrixXd A = S.transpose() * H * S;
      A.diagonal().array() += regularisation;
      const Eigen::VectorXd b = S.transpose() * (g - H * c) + regularisation * y0;
      planes = S * A.ldlt().solve(b) + c;
    }
    else
    {
      for (int p = 0; p < planeCount; ++p)
      {
        const auto r = root(p);
        planes[p] = known[r.first] + r.second;
      }
    }
    // Activate the most violated separation whose planes are in different groups.
    int worst = -1;
    double violation = 1e-9;
    for (size_t k = 0; k < separations.size(); ++k)
    {
      const int low = separations[k][0];
      const int high = separations[k][1];
      const double gap = 1.0 - (planes[high] - planes[low]);
      if (gap > violation && root(low).first != root(high).first && !(fixed[low] && fixed[high]))
      {
        const auto rl = root(low);
        const auto rh = root(high);
        if (!std::isnan(known[rl.first]) && !std::isnan(known[rh.first]))
        {
          continue; // both groups determined: nothing to move
        }
        worst = static_cast<int>(k);
        violation = gap;
      }
    }
    if (worst < 0)
    {
      return;
    }
    const auto rl = root(separations[worst][0]);
    const auto rh = root(separations[worst][1]);
    // value(high) = value(low) + 1, i.e. root_h + off_h = root_l + off_l + 1.
    if (std::isnan(known[rh.first]))
    {
      parent[rh.first] = rl.first;
      offset[rh.first] = rl.second + 1.0 - rh.second;
    }
    else
    {
      parent[rl.first] = rh.first;
      offset[rl.first] = rh.second - 1.0 - rl.second;
    }
  }
}
} // namespace

double PolycubePlaneSolver::Energy(const Points& positions) const
{
  const Impl& d = *this->Data;
  return DistortionEnergy(positions, d.Cells, d.Gradients, d.RestVolume, d.ReferenceJacobian);
}

namespace
{
/// Greedy rounding of `planes` (Bommes et al.: the free plane nearest to an integer first; the
/// others re-solved after each fix). Candidates are the integers allowed by the separations,
/// nearest first; with `checkVolumes`, a candidate is taken only if the re-solved and locally
/// untangled polycube keeps every tet above the minimum volume ratio.
Status GreedyRound(const PolycubePlaneSolver& solver,
  const ChartPlanes& charts,
  const SeparationGraph& separation,
  const IntegerRoundingParameters& params,
  bool checkVolumes,
  Eigen::VectorXd& planes,
  int& fallbackCount,
  const Progress& progress,
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max())
{
  const int planeCount = static_cast<int>(planes.size());
  const int candidateCount = std::max(1, params.CandidateCount);
  std::vector<bool> fixed(planeCount, false);
  fallbackCount = 0;
  Points positions;
  for (int step = 0; step < planeCount; ++step)
  {
    if (!ReportProgress(progress, static_cast<double>(step) / std::max(1, planeCount)))
    {
      return Status::Failure("integer rounding aborted");
    }
    if (std::chrono::steady_clock::now() > deadline)
    {
      return Status::Failure("integer rounding ran out of its time budget (TimeBudgetSeconds)");
    }
    int chosen = -1;
    double best = std::numeric_limits<double>::max();
    for (int p = 0; p < planeCount; ++p)
    {
      const double distance = std::fabs(planes[p] - std::round(planes[p]));
      if (!fixed[p] && distance < best - 1e-12)
      {
        best = distance;
        chosen = p;
      }
    }
    double low = 0.0;
    double high = 0.0;
    separation.Interval(chosen, fixed, planes, low, high);
    // Integers in [low, high], nearest first.
    std::vector<double> candidates;
    if (low <= high)
    {
      const double nearest = std::clamp(std::round(planes[chosen]), low, high);
      candidates.push_back(nearest);
      for (int offset = 1; static_cast<int>(candidates.size()) < candidateCount && offset < 64;
           ++offset)
      {
        const double below = nearest - offset;
        const double above = nearest + offset;
        const bool aboveFirst =
          std::fabs(above - planes[chosen]) < std::fabs(below - planes[chosen]);
        for (double c : aboveFirst ? std::array<double, 2>{ above, below }
                                   : std::array<double, 2>{ below, above })
        {
          if (c >= low && c <= high && static_cast<int>(candidates.size()) < candidateCount)
          {
            candidates.push_back(c);
          }
        }
        if (below < low && above > high)
        {
          break;
        }
      }
    }
    bool accepted = false;
    for (size_t i = 0; i < candidates.size() && !accepted; ++i)
    {
      Eigen::VectorXd trial = planes;
      trial[chosen] = candidates[i];
      fixed[chosen] = true;
      SolveFreePlanes(
        solver.PlaneHessian(), solver.PlaneGradient(), fixed, separation.Edges(), trial);
      bool valid = true;
      if (checkVolumes)
      {
        solver.Solve(trial, positions);
        valid = solver.Untangle(positions, params.UntangleTarget) >= params.MinimumVolumeRatio;
      }
      if (valid)
      {
        accepted = true;
        fallbackCount += candidates[i] != std::round(planes[chosen]) ? 1 : 0;
        planes = trial;
      }
      else
      {
        fixed[chosen] = false;
      }
    }
    if (!accepted)
    {
      const int plane = solver.PlaneOfVariable()[static_cast<size_t>(chosen)];
      int chart = 0;
      while (
        chart < static_cast<int>(charts.ChartPlane.size()) && charts.ChartPlane[chart] != plane)
      {
        ++chart;
      }
      std::ostringstream message;
      message << "integer rounding failed: no integer near " << planes[chosen] << " keeps ";
      if (plane >= 0 && chart < static_cast<int>(charts.ChartPlane.size()))
      {
        message << "chart " << chart << " (" << LabelNames[charts.ChartLabel[chart]] << ")";
      }
      else
      {
        message << "a cut translation";
      }
      message << " from collapsing a chart or inverting a tet; increase the resolution";
      return Status::Failure(message.str());
    }
  }
  return Status::Success();
}
} // namespace

Status roundPolycubePlanes(const Points& rest,
  const Points& reference,
  const Tets& cells,
  const ChartPlanes& charts,
  const IntegerRoundingParameters& params,
  IntegerRoundingResult& result,
  const Progress& progress,
  const PolycubeSeams* seams)
{
  PolycubePlaneSolver solver;
  Status status = solver.Build(rest, reference, cells, charts, seams);
  if (!status)
  {
    return status;
  }
  const bool cut = seams && !seams->Empty();
  const int planeCount = static_cast<int>(solver.ReferencePlanes().size());
  result.PlanesBefore = solver.ReferencePlanes();
  result.FallbackCount = 0;
  result.CarefulPath = false;
  result.Relaxed = false;
  result.BestEffort = false;

  // Start from the optimum with the separations (the reference planes when the charts are flat
  // and every separated pair is at least one unit apart).
  const SeparationGraph separation(
    solver.SeparationPairs(), result.PlanesBefore, params.SeparationTolerance);
  Eigen::VectorXd start = result.PlanesBefore;
  SolveFreePlanes(solver.PlaneHessian(),
    solver.PlaneGradient(),
    std::vector<bool>(planeCount, false),
    separation.Edges(),
    start);

  // Fast path: round with the separations only, then re-solve and untangle once. Where the
  // charts cannot all be flat, the untangling starts from tets it cannot free; it gets the whole
  // mesh there (one rounding only, see UnflattenableCharts).
  const bool flattenable = ChartsCanBeFlat(reference, cells, charts);
  auto finish = [&](const Eigen::VectorXd& planes)
  {
    solver.Solve(planes, result.Positions);
    result.MinVolumeRatio = solver.Untangle(result.Positions, params.UntangleTarget);
    if (result.MinVolumeRatio < params.MinimumVolumeRatio)
    {
      result.MinVolumeRatio = solver.UntangleGlobally(result.Positions,
        params.UntangleTarget,
        flattenable ? params.UntangleRings : -1,
        params.UntangleStallIterations);
    }
    return result.MinVolumeRatio >= params.MinimumVolumeRatio;
  };
  Eigen::VectorXd planes = start;
  status = GreedyRound(solver,
    charts,
    separation,
    params,
    false,
    planes,
    result.FallbackCount,
    [&progress](double p) { return ReportProgress(progress, 0.2 * p); });
  if (!status)
  {
    return status;
  }
  const auto started = std::chrono::steady_clock::now();
  const auto budget = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
    std::chrono::duration<double>(std::max(0.0, params.TimeBudgetSeconds)));
  const auto deadline = started + budget;
  const bool fastFailed = !finish(planes);
  result.UnflattenableCharts = fastFailed && params.AcceptInvertedTets &&
    !params.FallbacksWhenUnflattenable && !flattenable;
  if (fastFailed && !result.UnflattenableCharts && !cut && !params.FastPathOnly &&
    std::chrono::steady_clock::now() < started + budget / 2)
  {
    // The same integers, reached by moving the planes under a barrier (every tet stays
    // positive) instead of the linear re-solve.
    PlaneRelaxationResult relaxation;
    if (RelaxPolycubeToPlanes(rest,
          reference,
          cells,
          charts,
          planes,
          PlaneRelaxationParameters(),
          result.Positions,
          relaxation,
          [&progress](double p) { return ReportProgress(progress, 0.2 + 0.8 * p); }) &&
      relaxation.MinVolumeRatio >= params.MinimumVolumeRatio)
    {
      result.MinVolumeRatio = relaxation.MinVolumeRatio;
      result.Relaxed = true;
    }
  }
  const Eigen::VectorXd fastPlanes = planes;
  const Points fastPositions = result.Positions;
  const double fastRatio = result.MinVolumeRatio;
  if (result.UnflattenableCharts)
  {
    result.BestEffort = true;
    result.BestEffortReason = "the polycube's charts cannot all be flat without inverting a tet";
  }
  else if (params.FastPathOnly && fastFailed)
  {
    result.BestEffort = true;
    result.BestEffortReason = "a tet stays below the minimum volume ratio after untangling";
  }
  else if (!result.Relaxed && !(result.MinVolumeRatio >= params.MinimumVolumeRatio))
  {
    // Careful path: each candidate must keep the re-solved polycube positive.
    result.CarefulPath = true;
    planes = start;
    status = GreedyRound(solver,
      charts,
      separation,
      params,
      true,
      planes,
      result.FallbackCount,
      [&progress](double p) { return ReportProgress(progress, 0.3 + 0.7 * p); },
      deadline);
    if (!status && status.Message().find("aborted") != std::string::npos)
    {
      return status;
    }
    if (!status || !finish(planes))
    {
      if (!params.AcceptInvertedTets)
      {
        if (status)
        {
          std::ostringstream message;
          message << "integer rounding failed: the rounded polycube keeps a tet at volume ratio "
                  << result.MinVolumeRatio << " after untangling; increase the resolution";
          return Status::Failure(message.str());
        }
        return status;
      }
      // Best effort: the first rounding, untangled as far as it went. The caller reports the
      // inverted tets; the hex mesh around them is likely inverted too.
      planes = fastPlanes;
      result.Positions = fastPositions;
      result.MinVolumeRatio = fastRatio;
      result.BestEffort = true;
      result.BestEffortReason = status ? "a tet stays below the minimum volume ratio after untangling"
                                       : status.Message();
    }
  }
  // The rounded map, smoothed where the planes and cuts leave it free (the rounding keeps the
  // deformation's own distortion, and the hexes are that map's image of unit cubes).
  PolycubeMapSmoothingParameters smoothing = params.MapSmoothing;
  if (!params.SmoothMap)
  {
    smoothing.MaxRounds = 0;
  }
  status = smoothPolycubeMap(rest,
    cells,
    solver.FreeBasis(),
    smoothing,
    result.Positions,
    result.MapSmoothing,
    [&progress](double p) { return ReportProgress(progress, 0.9 + 0.1 * p); });
  if (!status)
  {
    return status;
  }
  result.InvertedTetCount = result.MapSmoothing.InvertedTetsAfter;
  if (result.MapSmoothing.Kept)
  {
    result.MinVolumeRatio = solver.MinVolumeRatio(result.Positions);
    if (result.BestEffort && result.MinVolumeRatio >= params.MinimumVolumeRatio)
    {
      // The smoothing untangled what the rounding could not.
      result.BestEffort = false;
      result.BestEffortReason.clear();
    }
  }
  result.PlanesAfter = planes;
  result.MaxPlaneShift =
    planeCount > 0 ? (result.PlanesAfter - result.PlanesBefore).cwiseAbs().maxCoeff() : 0.0;
  result.Energy = solver.Energy(result.Positions);
  result.CutTranslations = solver.CutTranslations(planes);
  const Eigen::VectorXd values = solver.ChartPlaneValues(planes);
  result.MaxPlaneFraction = 0.0;
  for (Eigen::Index p = 0; p < values.size(); ++p)
  {
    result.MaxPlaneFraction =
      std::max(result.MaxPlaneFraction, std::fabs(values[p] - std::round(values[p])));
  }
  for (const Eigen::Vector3d& t : result.CutTranslations)
  {
    result.MaxPlaneFraction =
      std::max(result.MaxPlaneFraction, (t - t.array().round().matrix()).cwiseAbs().maxCoeff());
  }
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
