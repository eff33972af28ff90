// SPDX-License-Identifier: BSD-3-Clause
// Charts, the plane solver and greedy integer rounding on small polycubes made of unit cubes:
// chart and plane counts, exact reproduction of the reference, translation invariance, a riser
// and a slab that nearest rounding would collapse, and a refusal with a readable message.
#include "IntegerRounding.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <vector>

using namespace polycubehex;
using polycubehex_test::BlockCells;

namespace
{
constexpr int FaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

struct Polycube
{
  Points Positions;
  Tets Cells;
  Tets Labels;
};

/// Unit cubes with the given minimum corners, 6 tets each around the main diagonal, labelled by
/// their boundary normals.
Polycube Cubes(const std::vector<std::array<int, 3>>& cubes)
{
  std::map<std::array<int, 3>, int> ids;
  auto id = [&ids](const std::array<int, 3>& p)
  { return ids.emplace(p, static_cast<int>(ids.size())).first->second; };
  const int permutations[6][3] = {
    { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
  };
  std::vector<std::array<int, 4>> tets;
  for (const auto& cube : cubes)
  {
    for (const auto& perm : permutations)
    {
      std::array<int, 3> corner = cube;
      std::array<int, 4> tet;
      tet[0] = id(corner);
      for (int s = 0; s < 3; ++s)
      {
        ++corner[perm[s]];
        tet[s + 1] = id(corner);
      }
      tets.push_back(tet);
    }
  }
  Polycube result;
  result.Positions.resize(static_cast<Eigen::Index>(ids.size()), 3);
  for (const auto& entry : ids)
  {
    result.Positions.row(entry.second) << entry.first[0], entry.first[1], entry.first[2];
  }
  result.Cells.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
  {
    auto tet = tets[t];
    const Eigen::Vector3d a = result.Positions.row(tet[0]).transpose();
    const Eigen::Vector3d b = result.Positions.row(tet[1]).transpose();
    const Eigen::Vector3d c = result.Positions.row(tet[2]).transpose();
    const Eigen::Vector3d d = result.Positions.row(tet[3]).transpose();
    if ((b - a).dot((c - a).cross(d - a)) < 0.0)
    {
      std::swap(tet[1], tet[2]);
    }
    for (int k = 0; k < 4; ++k)
    {
      result.Cells(static_cast<Eigen::Index>(t), k) = tet[k];
    }
  }
  std::map<std::array<int, 3>, int> uses;
  auto key = [&result](int t, int k)
  {
    std::array<int, 3> face = { result.Cells(t, FaceTable[k][0]),
      result.Cells(t, FaceTable[k][1]),
      result.Cells(t, FaceTable[k][2]) };
    std::sort(face.begin(), face.end());
    return face;
  };
  for (int t = 0; t < result.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      ++uses[key(t, k)];
    }
  }
  result.Labels.setConstant(result.Cells.rows(), 4, -1);
  for (int t = 0; t < result.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (uses[key(t, k)] == 1)
      {
        const Eigen::Vector3d a =
          result.Positions.row(result.Cells(t, FaceTable[k][0])).transpose();
        const Eigen::Vector3d b =
          result.Positions.row(result.Cells(t, FaceTable[k][1])).transpose();
        const Eigen::Vector3d c =
          result.Positions.row(result.Cells(t, FaceTable[k][2])).transpose();
        const Eigen::Vector3d n = (b - a).cross(c - a);
        int axis = 0;
        n.cwiseAbs().maxCoeff(&axis);
        result.Labels(t, k) = 2 * axis + (n[axis] > 0.0 ? 0 : 1);
      }
    }
  }
  return result;
}

bool AllIntegers(const Eigen::VectorXd& values)
{
  return (values.array() - values.array().round()).abs().maxCoeff() == 0.0;
}

/// Every coordinate of a vertex on a plane equals the plane's (integer) value exactly.
bool ChartsOnPlanes(const ChartPlanes& charts, const IntegerRoundingResult& result)
{
  for (int v = 0; v < charts.VertexPlane.rows(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int p = charts.VertexPlane(v, a);
      if (p >= 0 && result.Positions(v, a) != result.PlanesAfter[p])
      {
        return false;
      }
    }
  }
  return true;
}

void TestCharts()
{
  const Polycube cube = Cubes(BlockCells(2, 2, 2));
  ChartPlanes charts;
  PCH_CHECK(ComputeChartPlanes(cube.Positions, cube.Cells, cube.Labels, charts).Ok());
  PCH_CHECK(charts.ChartLabel.size() == 6);
  PCH_CHECK(charts.PlaneAxis.size() == 6);
  int corners = 0;
  int interior = 0;
  for (int v = 0; v < 27; ++v)
  {
    const int planes = static_cast<int>((charts.VertexPlane.row(v).array() >= 0).count());
    corners += planes == 3 ? 1 : 0;
    interior += planes == 0 ? 1 : 0;
  }
  PCH_CHECK(corners == 8);
  PCH_CHECK(interior == 1);
  for (int c = 0; c < 6; ++c)
  {
    PCH_CHECK(charts.ChartNeighbors[c].size() == 4); // a cube face touches the 4 others
  }
  // The opposite faces of each axis form a pair (they bound the four side charts).
  PCH_CHECK(charts.PlanePairs.size() == 3);

  // An L-shaped prism: 3 x-planes, 3 y-planes, 2 z-planes, one chart each.
  std::vector<std::array<int, 3>> l;
  for (const auto& c : BlockCells(3, 3, 2))
  {
    if (c[0] == 0 || c[1] == 0)
    {
      l.push_back(c);
    }
  }
  const Polycube shape = Cubes(l);
  PCH_CHECK(ComputeChartPlanes(shape.Positions, shape.Cells, shape.Labels, charts).Ok());
  PCH_CHECK(charts.ChartLabel.size() == 8);
  PCH_CHECK(charts.PlaneAxis.size() == 8);

  // Refusals: an unlabelled boundary face, a label on an interior face, a bad label.
  Tets labels = cube.Labels;
  for (int i = 0; i < labels.size(); ++i)
  {
    if (labels.data()[i] >= 0)
    {
      labels.data()[i] = -1;
      break;
    }
  }
  Status status = ComputeChartPlanes(cube.Positions, cube.Cells, labels, charts);
  PCH_CHECK(!status.Ok());
  std::cout << "unlabelled face: " << status.Message() << std::endl;
  labels = cube.Labels;
  for (int t = 0; t < labels.rows(); ++t)
  {
    if (labels(t, 1) < 0)
    {
      labels(t, 1) = 0;
      break;
    }
  }
  status = ComputeChartPlanes(cube.Positions, cube.Cells, labels, charts);
  PCH_CHECK(!status.Ok());
  std::cout << "labelled interior face: " << status.Message() << std::endl;
  labels = cube.Labels;
  labels(0, 0) = 7;
  PCH_CHECK(!ComputeChartPlanes(cube.Positions, cube.Cells, labels, charts).Ok());
}

void TestSolver()
{
  Polycube cube = Cubes(BlockCells(3, 2, 2));
  // Shear the interior a little so that the free coordinates matter.
  for (int v = 0; v < cube.Positions.rows(); ++v)
  {
    cube.Positions(v, 0) *= 1.1;
  }
  ChartPlanes charts;
  PCH_CHECK(ComputeChartPlanes(cube.Positions, cube.Cells, cube.Labels, charts).Ok());
  PolycubePlaneSolver solver;
  PCH_CHECK(solver.Build(cube.Positions, cube.Positions, cube.Cells, charts).Ok());
  Points positions;
  solver.Solve(solver.ReferencePlanes(), positions);
  PCH_CHECK((positions - cube.Positions).cwiseAbs().maxCoeff() < 1e-10);
  PCH_CHECK(std::fabs(solver.Energy(positions)) < 1e-18);
  PCH_CHECK_NEAR(solver.MinVolumeRatio(positions), 1.0, 1e-10);

  // Translating every plane of one axis costs nothing: H times the axis indicator is 0.
  for (int axis = 0; axis < 3; ++axis)
  {
    Eigen::VectorXd indicator = Eigen::VectorXd::Zero(charts.PlaneAxis.size());
    for (size_t p = 0; p < charts.PlaneAxis.size(); ++p)
    {
      indicator[static_cast<Eigen::Index>(p)] = charts.PlaneAxis[p] == axis ? 1.0 : 0.0;
    }
    PCH_CHECK((solver.PlaneHessian() * indicator).cwiseAbs().maxCoeff() < 1e-9);
  }
  // The reduced energy predicts the full one: E = P^T H P - 2 g^T P + E(reference planes)...
  Eigen::VectorXd planes = solver.ReferencePlanes();
  planes[0] += 0.3;
  solver.Solve(planes, positions);
  const Eigen::VectorXd p0 = solver.ReferencePlanes();
  const double predicted = planes.dot(solver.PlaneHessian() * planes) -
    2.0 * solver.PlaneGradient().dot(planes) -
    (p0.dot(solver.PlaneHessian() * p0) - 2.0 * solver.PlaneGradient().dot(p0));
  PCH_CHECK_NEAR(solver.Energy(positions), predicted, 1e-9);
  PCH_CHECK(solver.Energy(positions) > 0.0);
}

/// A block of unit cubes with its plane solver, and its positions with the free vertex at
/// (1, 1, 1) pushed through the face x = 2 of its neighbours.
struct TangledPolycube
{
  Polycube Cube;
  ChartPlanes Charts;
  PolycubePlaneSolver Solver;
  Points Tangled;
  int Pushed = -1;

  explicit TangledPolycube(const std::vector<std::array<int, 3>>& cells)
    : Cube(Cubes(cells))
  {
    PCH_CHECK(ComputeChartPlanes(Cube.Positions, Cube.Cells, Cube.Labels, Charts).Ok());
    PCH_CHECK(Solver.Build(Cube.Positions, Cube.Positions, Cube.Cells, Charts).Ok());
    for (int v = 0; v < Cube.Positions.rows(); ++v)
    {
      Pushed = Cube.Positions.row(v) == Eigen::RowVector3d(1.0, 1.0, 1.0) ? v : Pushed;
    }
    Tangled = Cube.Positions;
    Tangled.row(Pushed) << 2.3, 1.2, 0.95;
  }
};

/// Both untanglers repair a polycube whose free vertex was pushed through its neighbours.
void TestUntangle()
{
  const TangledPolycube setup(BlockCells(2, 2, 2));
  const Polycube& cube = setup.Cube;
  const ChartPlanes& charts = setup.Charts;
  const PolycubePlaneSolver& solver = setup.Solver;
  const Points& tangled = setup.Tangled;
  PCH_CHECK(solver.MinVolumeRatio(tangled) < 0.0);
  Points local = tangled;
  const double localRatio = solver.Untangle(local, 0.05);
  Points global = tangled;
  const double globalRatio = solver.UntangleGlobally(global, 0.05);
  // The stall rule must not end a run that is still freeing tets.
  Points stalled = tangled;
  const double stalledRatio = solver.UntangleGlobally(stalled, 0.05, -1, 10);
  std::cout << "untangle: local " << localRatio << ", global " << globalRatio << ", with stall "
            << stalledRatio << std::endl;
  PCH_CHECK(localRatio >= 0.05);
  PCH_CHECK(globalRatio >= 0.025);
  PCH_CHECK(stalledRatio >= 0.025);
  // Plane coordinates never move.
  for (int v = 0; v < cube.Positions.rows(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (charts.VertexPlane(v, a) >= 0)
      {
        PCH_CHECK(local(v, a) == tangled(v, a) && global(v, a) == tangled(v, a));
      }
    }
  }
}

/// The nonlinear untangling moves only a neighbourhood of the tets it repairs: on a long bar
/// tangled at one end, the far end stays exactly where the linear solve put it.
void TestUntangleGloballyIsLocal()
{
  TangledPolycube setup(BlockCells(16, 2, 2));
  const Polycube& bar = setup.Cube;
  const ChartPlanes& charts = setup.Charts;
  const PolycubePlaneSolver& solver = setup.Solver;
  Points& tangled = setup.Tangled;
  const int pushed = setup.Pushed;
  // The rest of the bar slightly off its optimum, so that a global solve would move it.
  for (int v = 0; v < tangled.rows(); ++v)
  {
    if (charts.VertexPlane(v, 1) < 0 && v != pushed)
    {
      tangled(v, 1) += 0.01 * std::sin(3.0 * tangled(v, 0));
    }
  }
  PCH_CHECK(solver.MinVolumeRatio(tangled) < 0.0);
  Points untangled = tangled;
  const double ratio = solver.UntangleGlobally(untangled, 0.05, 4);
  std::cout << "local global untangle: ratio " << ratio << std::endl;
  PCH_CHECK(ratio >= 0.025);
  int farMoved = 0;
  int nearMoved = 0;
  for (int v = 0; v < tangled.rows(); ++v)
  {
    const bool moved = (untangled.row(v) - tangled.row(v)).norm() > 0.0;
    farMoved += moved && bar.Positions(v, 0) >= 10.0 ? 1 : 0;
    nearMoved += moved && bar.Positions(v, 0) <= 3.0 ? 1 : 0;
  }
  PCH_CHECK(nearMoved > 0);
  PCH_CHECK(farMoved == 0);
}

/// Rounds and checks the invariants every rounding must satisfy.
IntegerRoundingResult Round(const Polycube& polycube,
  ChartPlanes& charts,
  const IntegerRoundingParameters& params = {},
  bool expectSuccess = true)
{
  IntegerRoundingResult result;
  PCH_CHECK(ComputeChartPlanes(polycube.Positions, polycube.Cells, polycube.Labels, charts).Ok());
  const Status status = roundPolycubePlanes(
    polycube.Positions, polycube.Positions, polycube.Cells, charts, params, result);
  PCH_CHECK(status.Ok() == expectSuccess);
  if (!status)
  {
    std::cout << "refused: " << status.Message() << std::endl;
    return result;
  }
  PCH_CHECK(AllIntegers(result.PlanesAfter));
  PCH_CHECK(ChartsOnPlanes(charts, result));
  PCH_CHECK(result.MinVolumeRatio >= params.MinimumVolumeRatio);
  std::cout << "planes " << result.PlanesBefore.transpose() << " -> "
            << result.PlanesAfter.transpose() << ", fallbacks " << result.FallbackCount
            << ", min volume ratio " << result.MinVolumeRatio << ", energy " << result.Energy
            << std::endl;
  return result;
}

void TestRounding()
{
  // A scaled block: planes at 0 and 2.6 (x), 0 and 1.3 (y, z) round to 0 and 3, 0 and 1.
  Polycube block = Cubes(BlockCells(2, 1, 1));
  block.Positions *= 1.3;
  ChartPlanes charts;
  IntegerRoundingResult r = Round(block, charts);
  PCH_CHECK(r.FallbackCount == 0);
  for (size_t p = 0; p < charts.PlaneAxis.size(); ++p)
  {
    const double extent = charts.PlaneAxis[p] == 0 ? 3.0 : 1.0;
    const double value = r.PlanesAfter[static_cast<Eigen::Index>(p)];
    PCH_CHECK(value == 0.0 || value == extent);
  }

  // A riser of height 0.3: the upper step must not fall onto the lower one.
  Polycube step = Cubes({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 } });
  for (int v = 0; v < step.Positions.rows(); ++v)
  {
    if (step.Positions(v, 2) > 1.0)
    {
      step.Positions(v, 2) = 1.3;
    }
  }
  r = Round(step, charts);
  std::vector<double> tops;
  for (size_t c = 0; c < charts.ChartLabel.size(); ++c)
  {
    if (charts.ChartLabel[c] == 4)
    {
      tops.push_back(r.PlanesAfter[charts.ChartPlane[c]]);
    }
  }
  std::sort(tops.begin(), tops.end());
  PCH_CHECK(tops.size() == 2 && tops[1] - tops[0] >= 1.0);
  PCH_CHECK(r.MaxPlaneShift >= 0.69); // 1.3 -> 2: the separation, not the nearest integer

  // A slab 0.2 thick: its two faces end one unit apart, not on one plane.
  Polycube slab = Cubes(BlockCells(3, 3, 1));
  slab.Positions.col(2) *= 0.2;
  r = Round(slab, charts);
  double low = 1e9;
  double high = -1e9;
  for (size_t p = 0; p < charts.PlaneAxis.size(); ++p)
  {
    if (charts.PlaneAxis[p] == 2)
    {
      low = std::min(low, r.PlanesAfter[static_cast<Eigen::Index>(p)]);
      high = std::max(high, r.PlanesAfter[static_cast<Eigen::Index>(p)]);
    }
  }
  PCH_CHECK(high - low == 1.0);

  // A slab 1.4 thick rounds to 1 (volume ratio 0.71): refused when that is not allowed and
  // only the nearest integer may be tried.
  Polycube thick = Cubes(BlockCells(2, 2, 1));
  thick.Positions.col(2) *= 1.4;
  IntegerRoundingParameters strict;
  strict.CandidateCount = 1;
  strict.MinimumVolumeRatio = 0.9;
  strict.AcceptInvertedTets = false;
  Round(thick, charts, strict, false);
  // By default the first rounding comes back as a best effort, its shortfall reported.
  {
    strict.AcceptInvertedTets = true;
    IntegerRoundingResult bestEffort;
    PCH_CHECK(roundPolycubePlanes(
      thick.Positions, thick.Positions, thick.Cells, charts, strict, bestEffort));
    PCH_CHECK(bestEffort.BestEffort);
    PCH_CHECK(bestEffort.MinVolumeRatio < strict.MinimumVolumeRatio);
    PCH_CHECK(bestEffort.InvertedTetCount == 0);
    PCH_CHECK(AllIntegers(bestEffort.PlanesAfter));
    strict.AcceptInvertedTets = false;
  }
  strict.CandidateCount = 2; // the next integer (2) expands instead
  r = Round(thick, charts, strict);
  PCH_CHECK(r.FallbackCount == 1);
  PCH_CHECK(r.CarefulPath);
}
} // namespace

int main(int, char*[])
{
  TestCharts();
  TestSolver();
  TestUntangle();
  TestUntangleGloballyIsLocal();
  TestRounding();
  return PCH_TEST_RESULT();
}
