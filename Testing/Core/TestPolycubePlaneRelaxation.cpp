// SPDX-License-Identifier: BSD-3-Clause
// The pieces that make a polycube flattenable and its planes integer without inverting a tet:
// shared-coordinate reductions, chart boundary turns (an island chart has none and is merged),
// and RelaxPolycubeToPlanes moving the planes of a cube to new values exactly, every tet
// positive, or refusing targets that would turn the cube inside out.
#include "IntegerRounding.h"
#include "PolycubeCharts.h"
#include "PolycubeNewton.h"
#include "PolycubePlaneRelaxation.h"
#include "TetGeometry.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <climits>
#include <iostream>
#include <vector>

using namespace polycubehex;

namespace
{
/// Labels of the boundary faces of a tet mesh by their normals, as PolycubeLabels (#T by 4).
Tets FaceLabelsOf(const TetMesh& mesh, const TetTopology& topology)
{
  Tets labels = Tets::Constant(mesh.Cells.rows(), 4, -1);
  const std::vector<int> faceLabels = PolycubeFaceLabels(mesh.Vertices, topology.BoundaryFaces);
  for (size_t f = 0; f < faceLabels.size(); ++f)
  {
    labels(topology.BoundaryFaceTet[f], topology.BoundaryFaceLocal[f]) = faceLabels[f];
  }
  return labels;
}

void TestShareCoordinates()
{
  // Vertex 0's x and vertex 2's x are one variable; everything else is its own.
  std::vector<int> group(9, -1);
  group[0] = 0;
  group[6] = 0;
  const VariableReduction reduction = VariableReduction::ShareCoordinates(3, group, 1);
  PCH_CHECK(reduction.VariableCount() == 8);
  Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(8, 1.0, 8.0);
  const Eigen::VectorXd x = reduction.Expand(y);
  PCH_CHECK(x(0) == 8.0 && x(6) == 8.0);
  PCH_CHECK(x(1) == 1.0 && x(8) == 7.0);
  PCH_CHECK(reduction.VariableAxis[7] == 0);
  PCH_CHECK((reduction.Restrict(x) - y).norm() < 1e-12);
}

void TestBoundaryTurns()
{
  const TetMesh cube = polycubehex_test::CubeGrid(4);
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(cube.Vertices.rows()), cube.Cells, topology);
  const Triangles adjacency =
    ComputeFaceAdjacency(static_cast<int>(cube.Vertices.rows()), topology.BoundaryFaces);
  std::vector<int> labels = PolycubeFaceLabels(cube.Vertices, topology.BoundaryFaces);
  PolycubeCharts charts = ComputePolycubeCharts(cube.Vertices, topology.BoundaryFaces, adjacency, labels);
  PCH_CHECK(charts.Count() == 6);
  for (int turns : ChartBoundaryTurns(topology.BoundaryFaces, adjacency, charts))
  {
    PCH_CHECK(turns == 4);
  }

  // An island: the faces of +Z around its centre labelled +X. Its loop meets only +Z.
  int island = 0;
  for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
  {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      centre += cube.Vertices.row(topology.BoundaryFaces(f, k)).transpose() / 3.0;
    }
    if (labels[static_cast<size_t>(f)] == 4 && std::abs(centre.x()) < 0.5 &&
      std::abs(centre.y()) < 0.5)
    {
      labels[static_cast<size_t>(f)] = 0;
      ++island;
    }
  }
  PCH_CHECK(island == 8);
  charts = ComputePolycubeCharts(cube.Vertices, topology.BoundaryFaces, adjacency, labels);
  PCH_CHECK(charts.Count() == 7);
  const std::vector<int> turns = ChartBoundaryTurns(topology.BoundaryFaces, adjacency, charts);
  PCH_CHECK(*std::min_element(turns.begin(), turns.end()) == 0);

  // The clean-up merges it whatever its size (the small-chart rule is switched off here).
  PolycubeChartCleanup cleanup;
  cleanup.MinAreaFraction = 0.0;
  cleanup.MinFaceCount = 0;
  const int relabelled =
    CleanUpPolycubeCharts(cube.Vertices, topology.BoundaryFaces, adjacency, cleanup, labels);
  PCH_CHECK(relabelled == 8);
  charts = ComputePolycubeCharts(cube.Vertices, topology.BoundaryFaces, adjacency, labels);
  PCH_CHECK(charts.Count() == 6);
}

void TestRelaxation()
{
  // A cube [-2, 2]^3 in lattice units (4^3 grid cubes of edge 1, 6 tets each).
  TetMesh cube = polycubehex_test::CubeGrid(4);
  cube.Vertices *= 2.0;
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(cube.Vertices.rows()), cube.Cells, topology);
  ChartPlanes charts;
  PCH_CHECK(ComputeChartPlanes(cube.Vertices, cube.Cells, FaceLabelsOf(cube, topology), charts));
  PCH_CHECK(charts.PlaneAxis.size() == 6);
  // The rest shape: the same cube, bent a little so that ARAP has something to say.
  Points rest = cube.Vertices;
  for (Eigen::Index v = 0; v < rest.rows(); ++v)
  {
    rest(v, 2) += 0.05 * rest(v, 0) * rest(v, 0);
  }

  // Move every plane outwards or inwards by up to 0.45.
  Eigen::VectorXd targets(6);
  for (int p = 0; p < 6; ++p)
  {
    const int v = static_cast<int>(std::find_if(charts.VertexPlane.data(),
                    charts.VertexPlane.data() + charts.VertexPlane.size(),
                    [p](int q) { return q == p; }) -
      charts.VertexPlane.data());
    const double value = cube.Vertices(v / 3, v % 3);
    targets(p) = value + (value > 0.0 ? 0.45 : -0.3);
  }
  Points positions;
  PlaneRelaxationResult result;
  const Status status = RelaxPolycubeToPlanes(
    rest, cube.Vertices, cube.Cells, charts, targets, PlaneRelaxationParameters(), positions, result);
  PCH_CHECK(status);
  PCH_CHECK(result.SharedPlanes);
  PCH_CHECK(result.MinVolumeRatio > 0.5);
  for (Eigen::Index v = 0; v < positions.rows(); ++v)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int p = charts.VertexPlane(v, a);
      if (p >= 0)
      {
        PCH_CHECK(positions(v, a) == targets(p));
      }
    }
  }
  for (int t = 0; t < static_cast<int>(cube.Cells.rows()); ++t)
  {
    PCH_CHECK(TetSignedVolume(positions, cube.Cells, t) > 0.0);
  }

  // Targets that turn the cube inside out along x are refused, not inverted.
  Eigen::VectorXd crossed = targets;
  for (int p = 0; p < 6; ++p)
  {
    if (charts.PlaneAxis[static_cast<size_t>(p)] == 0)
    {
      crossed(p) = -targets(p);
    }
  }
  const Status refused = RelaxPolycubeToPlanes(
    rest, cube.Vertices, cube.Cells, charts, crossed, PlaneRelaxationParameters(), positions, result);
  PCH_CHECK(!refused);
  std::cout << "refused: " << refused.Message() << std::endl;
}
} // namespace

int main(int, char*[])
{
  TestShareCoordinates();
  TestBoundaryTurns();
  TestRelaxation();
  return PCH_TEST_RESULT();
}
