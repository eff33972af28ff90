// SPDX-License-Identifier: BSD-3-Clause
// checkHexMeshValidity on hand-made meshes: a valid grid, and one mesh per kind of defect.
#include "HexMeshValidity.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <Eigen/Geometry>

#include <iostream>
#include <vector>

using namespace polycubehex;

namespace
{
/// Appends the unit cube with minimum corner (x, y, z); corners already in `points` are reused,
/// so that cubes touching at corners share vertices.
void AddCube(HexMesh& mesh, std::vector<Eigen::RowVector3d>& points, double x, double y, double z)
{
  const double corners[8][3] = { { 0, 0, 0 },
    { 1, 0, 0 },
    { 1, 1, 0 },
    { 0, 1, 0 },
    { 0, 0, 1 },
    { 1, 0, 1 },
    { 1, 1, 1 },
    { 0, 1, 1 } };
  Eigen::Matrix<int, 1, 8> hex;
  for (int c = 0; c < 8; ++c)
  {
    const Eigen::RowVector3d p(x + corners[c][0], y + corners[c][1], z + corners[c][2]);
    int found = -1;
    for (size_t i = 0; i < points.size() && found < 0; ++i)
    {
      found = (points[i] - p).norm() < 1e-12 ? static_cast<int>(i) : -1;
    }
    if (found < 0)
    {
      found = static_cast<int>(points.size());
      points.push_back(p);
    }
    hex[c] = found;
  }
  mesh.Cells.conservativeResize(mesh.Cells.rows() + 1, 8);
  mesh.Cells.row(mesh.Cells.rows() - 1) = hex;
  mesh.Vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i)
  {
    mesh.Vertices.row(static_cast<Eigen::Index>(i)) = points[i];
  }
}

HexMeshValidity Check(const HexMesh& mesh)
{
  HexMeshValidity result;
  const Status status = checkHexMeshValidity(mesh, result);
  PCH_CHECK(status.Ok());
  std::cout << result.Report << std::endl;
  return result;
}

void TestValidGrid()
{
  const HexMesh mesh = polycubehex_test::HexCubeGrid(2);
  const HexMeshValidity result = Check(mesh);
  PCH_CHECK(result.IsValid());
  PCH_CHECK(result.HexCount == 8);
  PCH_CHECK(result.BoundaryQuadCount == 24);
  // Corners have 3 boundary quads; edge midpoints and face centres have 4.
  PCH_CHECK(result.IrregularBoundaryVertexCount == 8);
  PCH_CHECK(result.DegenerateHexCount == 0);
  PCH_CHECK(result.NonManifoldBoundaryEdgeCount == 0);
  PCH_CHECK(result.NonManifoldBoundaryVertexCount == 0);

  // The face table gives outward normals: each boundary quad faces away from the centre (1,1,1).
  int inward = 0;
  for (int q = 0; q < result.BoundaryQuads.rows(); ++q)
  {
    const Eigen::RowVector3d p0 = mesh.Vertices.row(result.BoundaryQuads(q, 0));
    const Eigen::RowVector3d p1 = mesh.Vertices.row(result.BoundaryQuads(q, 1));
    const Eigen::RowVector3d p3 = mesh.Vertices.row(result.BoundaryQuads(q, 3));
    const Eigen::RowVector3d normal = (p1 - p0).cross(p3 - p0);
    const Eigen::RowVector3d outward = p0 - Eigen::RowVector3d(1, 1, 1);
    inward += normal.dot(outward) > 0 ? 0 : 1;
  }
  PCH_CHECK(inward == 0);

  // A bigger grid: (n+1)^3 - (n-1)^3 boundary vertices, still only 8 irregular.
  const HexMeshValidity big = Check(polycubehex_test::HexCubeGrid(4));
  PCH_CHECK(big.IsValid());
  PCH_CHECK(big.BoundaryQuadCount == 6 * 16);
  PCH_CHECK(big.IrregularBoundaryVertexCount == 8);
}

void TestRepeatedVertex()
{
  HexMesh mesh = polycubehex_test::HexCubeGrid(1);
  mesh.Cells(0, 6) = mesh.Cells(0, 5); // collapse the edge 5-6
  const HexMeshValidity result = Check(mesh);
  PCH_CHECK(!result.IsValid());
  PCH_CHECK(result.DegenerateHexCount == 1);
  PCH_CHECK(result.Report.find("hex 0") != std::string::npos);
}

void TestQuadSharedByThree()
{
  // Two stacked cubes, plus a third hex that also sits on the top of the bottom cube.
  HexMesh mesh = polycubehex_test::HexCubeGrid(1);
  std::vector<Eigen::RowVector3d> points;
  for (int i = 0; i < mesh.Vertices.rows(); ++i)
  {
    points.push_back(mesh.Vertices.row(i));
  }
  AddCube(mesh, points, 0, 0, 1);
  const int base = static_cast<int>(mesh.Vertices.rows());
  mesh.Vertices.conservativeResize(base + 4, 3);
  mesh.Vertices.bottomRows(4) << 0, 0, 1.5, 1, 0, 1.5, 1, 1, 1.5, 0, 1, 1.5;
  mesh.Cells.conservativeResize(3, 8);
  mesh.Cells.row(2) << mesh.Cells(0, 4), mesh.Cells(0, 5), mesh.Cells(0, 6), mesh.Cells(0, 7), base,
    base + 1, base + 2, base + 3;
  const HexMeshValidity result = Check(mesh);
  PCH_CHECK(!result.IsValid());
  PCH_CHECK(result.OverSharedQuadCount == 1);
  PCH_CHECK(result.DegenerateHexCount == 0);
}

void TestEdgeContact()
{
  // Two cubes touching along the edge x = y = 1 only: that edge is in 4 boundary quads.
  HexMesh mesh;
  std::vector<Eigen::RowVector3d> points;
  AddCube(mesh, points, 0, 0, 0);
  AddCube(mesh, points, 1, 1, 0);
  PCH_CHECK(mesh.Vertices.rows() == 14);
  const HexMeshValidity result = Check(mesh);
  PCH_CHECK(!result.IsValid());
  PCH_CHECK(result.BoundaryQuadCount == 12);
  PCH_CHECK(result.NonManifoldBoundaryEdgeCount == 1);
}

void TestVertexContact()
{
  // Two cubes touching at the vertex (1,1,1) only: every edge is fine, the vertex has two fans.
  HexMesh mesh;
  std::vector<Eigen::RowVector3d> points;
  AddCube(mesh, points, 0, 0, 0);
  AddCube(mesh, points, 1, 1, 1);
  const HexMeshValidity result = Check(mesh);
  PCH_CHECK(!result.IsValid());
  PCH_CHECK(result.NonManifoldBoundaryEdgeCount == 0);
  PCH_CHECK(result.NonManifoldBoundaryVertexCount == 1);
}

void TestMisorientedQuad()
{
  // A 2x1x1 bar with one hex flipped (top and bottom swapped): the shared quad is seen twice the
  // same way round, as when two hexes overlap.
  HexMesh mesh;
  std::vector<Eigen::RowVector3d> points;
  AddCube(mesh, points, 0, 0, 0);
  AddCube(mesh, points, 1, 0, 0);
  const Eigen::Matrix<int, 1, 8> hex = mesh.Cells.row(1);
  mesh.Cells.row(1) << hex.tail<4>(), hex.head<4>();
  const HexMeshValidity result = Check(mesh);
  PCH_CHECK(!result.IsValid());
  PCH_CHECK(result.MisorientedQuadCount == 1);
  // The flipped hex's boundary quads point inwards, so the edges they share with the other
  // hex's boundary quads are walked twice in the same direction.
  PCH_CHECK(result.NonManifoldBoundaryEdgeCount > 0);
}

void TestRefusals()
{
  HexMeshValidity result;
  PCH_CHECK(!checkHexMeshValidity(HexMesh(), result).Ok());
  HexMesh mesh = polycubehex_test::HexCubeGrid(1);
  mesh.Cells(0, 3) = 99;
  const Status status = checkHexMeshValidity(mesh, result);
  PCH_CHECK(!status.Ok());
  std::cout << "refused: " << status.Message() << std::endl;
}
} // namespace

int main(int, char*[])
{
  TestValidGrid();
  TestRepeatedVertex();
  TestQuadSharedByThree();
  TestEdgeContact();
  TestVertexContact();
  TestMisorientedQuad();
  TestRefusals();
  return PCH_TEST_RESULT();
}
