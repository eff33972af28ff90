// SPDX-License-Identifier: BSD-3-Clause
// CheckClosedSurface on shapes built here: valid ones (sphere, torus, ball with a void, island in
// a void) must pass with the right topology and nesting; broken ones must be refused with a
// message that names the problem and the offending edge or vertex.
#include "SurfaceCheck.h"
#include "TestAssert.h"

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

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Icosahedron subdivided `levels` times and projected on a sphere; outward unless `inward`.
SurfaceMesh Icosphere(int levels, double radius, const Eigen::Vector3d& centre, bool inward = false)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> points = { { -1, t, 0 },
    { 1, t, 0 },
    { -1, -t, 0 },
    { 1, -t, 0 },
    { 0, -1, t },
    { 0, 1, t },
    { 0, -1, -t },
    { 0, 1, -t },
    { t, 0, -1 },
    { t, 0, 1 },
    { -t, 0, -1 },
    { -t, 0, 1 } };
  std::vector<std::array<int, 3>> faces = { { 0, 11, 5 },
    { 0, 5, 1 },
    { 0, 1, 7 },
    { 0, 7, 10 },
    { 0, 10, 11 },
    { 1, 5, 9 },
    { 5, 11, 4 },
    { 11, 10, 2 },
    { 10, 7, 6 },
    { 7, 1, 8 },
    { 3, 9, 4 },
    { 3, 4, 2 },
    { 3, 2, 6 },
    { 3, 6, 8 },
    { 3, 8, 9 },
    { 4, 9, 5 },
    { 2, 4, 11 },
    { 6, 2, 10 },
    { 8, 6, 7 },
    { 9, 8, 1 } };
  for (int level = 0; level < levels; ++level)
  {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b)
    {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      points.push_back(0.5 * (points[a] + points[b]));
      midpoints[key] = static_cast<int>(points.size()) - 1;
      return static_cast<int>(points.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& f : faces)
    {
      const int ab = midpoint(f[0], f[1]);
      const int bc = midpoint(f[1], f[2]);
      const int ca = midpoint(f[2], f[0]);
      finer.push_back({ f[0], ab, ca });
      finer.push_back({ f[1], bc, ab });
      finer.push_back({ f[2], ca, bc });
      finer.push_back({ ab, bc, ca });
    }
    faces.swap(finer);
  }
  SurfaceMesh mesh;
  mesh.Vertices.resize(points.size(), 3);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    mesh.Vertices.row(v) = (centre + radius * points[v].normalized()).transpose();
  }
  mesh.Faces.resize(faces.size(), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    // Convex around the centre: orient each face by its normal against its centroid.
    const Eigen::Vector3d p0 = points[faces[f][0]];
    const Eigen::Vector3d n = (points[faces[f][1]] - p0).cross(points[faces[f][2]] - p0);
    const bool outward = n.dot(p0 + points[faces[f][1]] + points[faces[f][2]]) > 0.0;
    if (outward == inward)
    {
      std::swap(faces[f][1], faces[f][2]);
    }
    mesh.Faces.row(f) << faces[f][0], faces[f][1], faces[f][2];
  }
  return mesh;
}

/// A torus of radii R > r around the z axis, n by m quads split into triangles, outward.
SurfaceMesh Torus(double R, double r, int n, int m)
{
  SurfaceMesh mesh;
  mesh.Vertices.resize(n * m, 3);
  mesh.Faces.resize(2 * n * m, 3);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const double u = 2.0 * Pi * i / n;
      const double v = 2.0 * Pi * j / m;
      mesh.Vertices.row(i * m + j) << (R + r * std::cos(v)) * std::cos(u),
        (R + r * std::cos(v)) * std::sin(u), r * std::sin(v);
      const int a = i * m + j;
      const int b = ((i + 1) % n) * m + j;
      const int c = ((i + 1) % n) * m + (j + 1) % m;
      const int d = i * m + (j + 1) % m;
      // Counter-clockwise seen from outside for this parametrization.
      mesh.Faces.row(2 * a) << a, b, c;
      mesh.Faces.row(2 * a + 1) << a, c, d;
    }
  }
  return mesh;
}

/// The four outward faces of a positive tet (VTK's local face table).
SurfaceMesh TetSurface(const std::array<Eigen::Vector3d, 4>& p)
{
  SurfaceMesh mesh;
  mesh.Vertices.resize(4, 3);
  for (int v = 0; v < 4; ++v)
  {
    mesh.Vertices.row(v) = p[v].transpose();
  }
  mesh.Faces.resize(4, 3);
  mesh.Faces << 0, 1, 3, 1, 2, 3, 2, 0, 3, 0, 2, 1;
  return mesh;
}

SurfaceMesh Merge(const SurfaceMesh& a, const SurfaceMesh& b)
{
  SurfaceMesh mesh;
  mesh.Vertices.resize(a.Vertices.rows() + b.Vertices.rows(), 3);
  mesh.Vertices << a.Vertices, b.Vertices;
  mesh.Faces.resize(a.Faces.rows() + b.Faces.rows(), 3);
  mesh.Faces << a.Faces, (b.Faces.array() + static_cast<int>(a.Vertices.rows())).matrix();
  return mesh;
}

/// Two tet surfaces glued at the first `shared` vertices of the second onto the first's.
SurfaceMesh GlueTets(int shared)
{
  const SurfaceMesh a = TetSurface({ Eigen::Vector3d(0, 0, 0),
    Eigen::Vector3d(1, 0, 0),
    Eigen::Vector3d(0, 1, 0),
    Eigen::Vector3d(0, 0, 1) });
  SurfaceMesh b = shared == 2 ? TetSurface({ Eigen::Vector3d(0, 0, 0),
                                  Eigen::Vector3d(1, 0, 0),
                                  Eigen::Vector3d(0, -1, 0),
                                  Eigen::Vector3d(0, 0, -1) })
                              : TetSurface({ Eigen::Vector3d(0, 0, 0),
                                  Eigen::Vector3d(0, -1, 0),
                                  Eigen::Vector3d(-1, 0, 0),
                                  Eigen::Vector3d(0, 0, -1) });
  SurfaceMesh glued = Merge(a, b);
  // Vertex i < shared of b is vertex i of a: renumber, leaving b's copy unused.
  for (Eigen::Index f = a.Faces.rows(); f < glued.Faces.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (glued.Faces(f, k) < 4 + shared)
      {
        glued.Faces(f, k) -= 4;
      }
    }
  }
  return glued;
}

bool Contains(const std::string& text, const std::string& part)
{
  const bool found = text.find(part) != std::string::npos;
  if (!found)
  {
    std::cerr << "message \"" << text << "\" does not contain \"" << part << "\"" << std::endl;
  }
  return found;
}

double PolyhedronVolume(const SurfaceMesh& mesh)
{
  // Relative to a vertex: far from the origin the plain sum cancels catastrophically.
  const Eigen::Vector3d origin = mesh.Vertices.row(0).transpose();
  double sixVolume = 0.0;
  for (int f = 0; f < mesh.Faces.rows(); ++f)
  {
    const Eigen::Vector3d p0 = mesh.Vertices.row(mesh.Faces(f, 0)).transpose() - origin;
    const Eigen::Vector3d p1 = mesh.Vertices.row(mesh.Faces(f, 1)).transpose() - origin;
    const Eigen::Vector3d p2 = mesh.Vertices.row(mesh.Faces(f, 2)).transpose() - origin;
    sixVolume += p0.dot(p1.cross(p2));
  }
  return sixVolume / 6.0;
}

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
} // namespace

int main(int, char*[])
{
  TestValidShapes();
  TestBrokenShapes();
  return PCH_TEST_RESULT();
}
