// SPDX-License-Identifier: BSD-3-Clause
// CheckClosedSurface on shapes built here: valid ones (sphere, torus, ball with a void, island in
// a void) must pass with the right topology and nesting; broken ones must be refused with a
// message that names the problem and the offending edge or vertex. MeasureSurfaceAngles counts
// needles and caps.
#include "SurfaceCheck.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <utility>

using polycubehex::SurfaceCheckReport;
using polycubehex::SurfaceMesh;
using polycubehex_test::Contains;
using polycubehex_test::GlueTets;
using polycubehex_test::Icosphere;
using polycubehex_test::Merge;
using polycubehex_test::Pi;
using polycubehex_test::PolyhedronVolume;
using polycubehex_test::Torus;

namespace
{
void TestValidShapes()
{
  SurfaceCheckReport report;
  const SurfaceMesh sphere = Icosphere(3, 2.0, Eigen::Vector3d(1, 2, 3));
  PCH_CHECK(polycubehex::CheckClosedSurface(sphere, report).Ok());
  PCH_CHECK(report.Components.size() == 1);
  PCH_CHECK(report.Components[0].EulerCharacteristic == 2);
  PCH_CHECK(report.Components[0].Genus == 0);
  PCH_CHECK(report.Components[0].NestingDepth == 0);
  PCH_CHECK(report.Components[0].OrientedOutward());
  PCH_CHECK_NEAR(report.EnclosedVolume, PolyhedronVolume(sphere), 1e-9);
  PCH_CHECK_NEAR(report.EnclosedVolume, 4.0 / 3.0 * Pi * 8.0, 0.05 * 4.0 / 3.0 * Pi * 8.0);
  PCH_CHECK_NEAR(polycubehex::ComponentWindingNumber(sphere, report, 0, { 1, 2, 3 }), 1.0, 1e-9);
  PCH_CHECK_NEAR(polycubehex::ComponentWindingNumber(sphere, report, 0, { 5, 2, 3 }), 0.0, 1e-9);

  const SurfaceMesh torus = Torus(3.0, 1.0, 24, 12);
  PCH_CHECK(polycubehex::CheckClosedSurface(torus, report).Ok());
  PCH_CHECK(report.Components.size() == 1);
  PCH_CHECK(report.Components[0].EulerCharacteristic == 0);
  PCH_CHECK(report.Components[0].Genus == 1);
  PCH_CHECK(report.Components[0].OrientedOutward());
  std::cout << "torus: " << report.Summary();

  // A ball with a spherical void: the inner sphere faces into the void.
  const SurfaceMesh outer = Icosphere(2, 1.0, Eigen::Vector3d::Zero());
  const SurfaceMesh inner = Icosphere(2, 0.5, Eigen::Vector3d(0.1, 0, 0), true);
  const SurfaceMesh hollow = Merge(outer, inner);
  PCH_CHECK(polycubehex::CheckClosedSurface(hollow, report).Ok());
  PCH_CHECK(report.Components.size() == 2);
  PCH_CHECK(report.VoidCount() == 1);
  PCH_CHECK(report.Components[1].NestingDepth == 1 && report.Components[1].IsVoid());
  PCH_CHECK(report.Components[1].Parent == 0);
  PCH_CHECK(report.Components[1].SignedVolume < 0.0);
  PCH_CHECK(report.Components[1].OrientedOutward());
  PCH_CHECK_NEAR(report.EnclosedVolume, PolyhedronVolume(outer) + PolyhedronVolume(inner), 1e-9);
  std::cout << "hollow ball: " << report.Summary();

  // The same void oriented like a body is still a void (nesting decides), flagged as inwards.
  const SurfaceMesh sameOrientation = Merge(outer, Icosphere(2, 0.5, Eigen::Vector3d(0.1, 0, 0)));
  PCH_CHECK(polycubehex::CheckClosedSurface(sameOrientation, report).Ok());
  PCH_CHECK(report.Components[1].IsVoid() && !report.Components[1].OrientedOutward());
  PCH_CHECK_NEAR(report.EnclosedVolume, PolyhedronVolume(outer) + PolyhedronVolume(inner), 1e-9);

  // An island inside the void (depth 2) is a body again; a separate ball is at depth 0.
  const SurfaceMesh island = Merge(Merge(hollow, Icosphere(1, 0.2, Eigen::Vector3d(0.1, 0, 0))),
    Icosphere(1, 0.5, Eigen::Vector3d(3, 0, 0)));
  PCH_CHECK(polycubehex::CheckClosedSurface(island, report).Ok());
  PCH_CHECK(report.Components.size() == 4);
  PCH_CHECK(report.Components[2].NestingDepth == 2 && !report.Components[2].IsVoid());
  PCH_CHECK(report.Components[2].Parent == 1);
  PCH_CHECK(report.Components[3].NestingDepth == 0);
  PCH_CHECK(report.VoidCount() == 1);

  // Unused vertices are ignored, not refused.
  SurfaceMesh extra = sphere;
  extra.Vertices.conservativeResize(extra.Vertices.rows() + 1, 3);
  extra.Vertices.row(extra.Vertices.rows() - 1) << 100, 100, 100;
  PCH_CHECK(polycubehex::CheckClosedSurface(extra, report).Ok());
  PCH_CHECK(report.UnusedVertexCount == 1);
}

void TestBrokenShapes()
{
  SurfaceCheckReport report;
  const SurfaceMesh sphere = Icosphere(2, 1.0, Eigen::Vector3d::Zero());

  SurfaceMesh open = sphere;
  open.Faces.conservativeResize(open.Faces.rows() - 1, 3);
  auto status = polycubehex::CheckClosedSurface(open, report);
  std::cout << "open: " << status.Message() << std::endl;
  PCH_CHECK(!status.Ok());
  PCH_CHECK(report.BoundaryEdgeCount == 3);
  PCH_CHECK(Contains(status.Message(), "not closed: 3 boundary edges"));
  PCH_CHECK(Contains(status.Message(), "e.g. edge ("));

  const SurfaceMesh sharedEdge = GlueTets(2);
  status = polycubehex::CheckClosedSurface(sharedEdge, report);
  std::cout << "shared edge: " << status.Message() << std::endl;
  PCH_CHECK(!status.Ok());
  PCH_CHECK(report.NonManifoldEdgeCount == 1);
  PCH_CHECK(Contains(status.Message(), "not 2-manifold: 1 edge in more than two triangles"));
  PCH_CHECK(Contains(status.Message(), "edge (0, 1) at (0, 0, 0)-(1, 0, 0) in 4 triangles"));

  const SurfaceMesh sharedVertex = GlueTets(1);
  status = polycubehex::CheckClosedSurface(sharedVertex, report);
  std::cout << "shared vertex: " << status.Message() << std::endl;
  PCH_CHECK(!status.Ok());
  PCH_CHECK(report.NonManifoldEdgeCount == 0 && report.NonManifoldVertexCount == 1);
  PCH_CHECK(Contains(status.Message(), "vertex 0 at (0, 0, 0) (2 fans)"));

  SurfaceMesh flipped = sphere;
  std::swap(flipped.Faces(7, 1), flipped.Faces(7, 2));
  status = polycubehex::CheckClosedSurface(flipped, report);
  std::cout << "flipped: " << status.Message() << std::endl;
  PCH_CHECK(!status.Ok());
  PCH_CHECK(report.MisorientedEdgeCount == 3);
  PCH_CHECK(Contains(status.Message(), "not consistently oriented: 3 edges"));

  SurfaceMesh outOfRange = sphere;
  outOfRange.Faces(4, 2) = 10000;
  status = polycubehex::CheckClosedSurface(outOfRange, report);
  PCH_CHECK(!status.Ok() && Contains(status.Message(), "face 4 ("));

  SurfaceMesh notFinite = sphere;
  notFinite.Vertices(3, 1) = std::numeric_limits<double>::quiet_NaN();
  status = polycubehex::CheckClosedSurface(notFinite, report);
  PCH_CHECK(!status.Ok() && Contains(status.Message(), "non-finite coordinates: 1 vertex"));

  SurfaceMesh flat = sphere;
  flat.Vertices.row(flat.Faces(0, 2)) =
    0.5 * (flat.Vertices.row(flat.Faces(0, 0)) + flat.Vertices.row(flat.Faces(0, 1)));
  status = polycubehex::CheckClosedSurface(flat, report);
  PCH_CHECK(!status.Ok() && report.DegenerateFaceCount == 1);
  PCH_CHECK(Contains(status.Message(), "1 degenerate triangle (a repeated vertex or no area)"));

  SurfaceMesh repeated = sphere;
  repeated.Faces(5, 1) = repeated.Faces(5, 0);
  status = polycubehex::CheckClosedSurface(repeated, report);
  PCH_CHECK(!status.Ok() && report.DegenerateFaceCount == 1);
  PCH_CHECK(Contains(status.Message(), "1 degenerate triangle"));
  PCH_CHECK(Contains(status.Message(), "not closed")); // its two other edges lost a side

  SurfaceMesh duplicated = sphere;
  duplicated.Faces.conservativeResize(duplicated.Faces.rows() + 1, 3);
  duplicated.Faces.row(duplicated.Faces.rows() - 1) = sphere.Faces.row(0);
  status = polycubehex::CheckClosedSurface(duplicated, report);
  PCH_CHECK(!status.Ok() && report.DuplicateFaceCount == 1);
  PCH_CHECK(Contains(status.Message(), "repeats face 0"));

  // Two spheres touching at one point given twice: refused before TetGen sees it.
  SurfaceMesh touching = Merge(sphere, Icosphere(2, 1.0, Eigen::Vector3d(2, 0, 0)));
  Eigen::Index rightmost = 0;
  Eigen::Index leftmost = 0;
  sphere.Vertices.col(0).maxCoeff(&rightmost);
  sphere.Vertices.col(0).minCoeff(&leftmost);
  touching.Vertices.row(sphere.Vertices.rows() + leftmost) << 1.0, 0.0, 0.0;
  touching.Vertices.row(rightmost) << 1.0, 0.0, 0.0;
  status = polycubehex::CheckClosedSurface(touching, report);
  PCH_CHECK(!status.Ok() && report.CoincidentVertexCount >= 1);
  PCH_CHECK(Contains(status.Message(), "at exactly the position of another vertex"));

  status = polycubehex::CheckClosedSurface(SurfaceMesh(), report);
  PCH_CHECK(!status.Ok() && Contains(status.Message(), "no triangles"));
}

/// MeasureSurfaceAngles: none on a regular sphere; a tetrahedron with one cap-shaped face (two
/// angles of about 0.0011 degrees) has that one face below 1 degree.
void TestSmallAngles()
{
  const auto round =
    polycubehex::MeasureSurfaceAngles(Icosphere(3, 1.0, Eigen::Vector3d::Zero()), 1.0);
  PCH_CHECK(round.SmallAngleFaceCount == 0);
  PCH_CHECK(round.SmallestAngleDegrees > 30.0);

  SurfaceMesh cap;
  cap.Vertices.resize(4, 3);
  cap.Vertices << 0, 0, 0, 1, 0, 0, 0.5, 1e-5, 0, 0.5, 0.5, 1;
  cap.Faces.resize(4, 3);
  cap.Faces << 0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3;
  const auto thin = polycubehex::MeasureSurfaceAngles(cap, 1.0);
  PCH_CHECK(thin.SmallAngleFaceCount == 1);
  PCH_CHECK(thin.SmallestAngleFace == 0);
  PCH_CHECK_NEAR(thin.SmallestAngleDegrees, std::atan(2e-5) * 180.0 / Pi, 1e-9);
}
} // namespace

int main(int, char*[])
{
  TestValidShapes();
  TestBrokenShapes();
  TestSmallAngles();
  return PCH_TEST_RESULT();
}
