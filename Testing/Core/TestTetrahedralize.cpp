// SPDX-License-Identifier: BSD-3-Clause
// Tetrahedralize on shapes built by TestMeshGenerators.h (shared with TestSurfaceCheck): tets
// positive, volume kept, voids kept empty, the boundary kept with PreserveBoundary, and broken
// surfaces refused with a message naming the problem.
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "Tetrahedralize.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

using polycubehex::SurfaceMesh;
using polycubehex::TetMesh;
using polycubehex::TetrahedralizeParameters;
using polycubehex_test::Contains;
using polycubehex_test::GlueTets;
using polycubehex_test::Icosphere;
using polycubehex_test::Merge;
using polycubehex_test::PolyhedronVolume;
using polycubehex_test::Torus;

namespace
{
double TetVolume(const TetMesh& mesh, int t)
{
  const Eigen::Vector3d p0 = mesh.Vertices.row(mesh.Cells(t, 0)).transpose();
  const Eigen::Vector3d p1 = mesh.Vertices.row(mesh.Cells(t, 1)).transpose();
  const Eigen::Vector3d p2 = mesh.Vertices.row(mesh.Cells(t, 2)).transpose();
  const Eigen::Vector3d p3 = mesh.Vertices.row(mesh.Cells(t, 3)).transpose();
  return (p1 - p0).cross(p2 - p0).dot(p3 - p0) / 6.0;
}

/// A triangle rotated so that its smallest index comes first: equal iff same oriented triangle.
std::array<int, 3> Canonical(int a, int b, int c)
{
  if (b < a && b < c)
  {
    return { b, c, a };
  }
  if (c < a && c < b)
  {
    return { c, a, b };
  }
  return { a, b, c };
}

/// Faces in one tet only, oriented out of the mesh (VTK's local face table).
std::vector<std::array<int, 3>> BoundaryFaces(const TetMesh& mesh)
{
  static const int table[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces; // sorted -> uses, face
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    for (const auto& local : table)
    {
      const std::array<int, 3> face =
        Canonical(mesh.Cells(t, local[0]), mesh.Cells(t, local[1]), mesh.Cells(t, local[2]));
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      ++entry.first;
      entry.second = face;
    }
  }
  std::vector<std::array<int, 3>> boundary;
  for (const auto& entry : faces)
  {
    if (entry.second.first == 1)
    {
      boundary.push_back(entry.second.second);
    }
  }
  std::sort(boundary.begin(), boundary.end());
  return boundary;
}

/// Connected components of the boundary faces, joined through shared vertices.
int BoundaryComponentCount(const std::vector<std::array<int, 3>>& faces, int vertexCount)
{
  std::vector<int> parent(vertexCount);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](int x)
  {
    while (parent[x] != x)
    {
      x = parent[x] = parent[parent[x]];
    }
    return x;
  };
  std::set<int> used;
  for (const auto& face : faces)
  {
    parent[find(face[1])] = find(face[0]);
    parent[find(face[2])] = find(face[0]);
    used.insert(face.begin(), face.end());
  }
  std::set<int> roots;
  for (int v : used)
  {
    roots.insert(find(v));
  }
  return static_cast<int>(roots.size());
}

double MeshVolume(const TetMesh& mesh)
{
  double volume = 0.0;
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    volume += TetVolume(mesh, t);
  }
  return volume;
}

int NonPositiveCount(const TetMesh& mesh)
{
  int count = 0;
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    count += TetVolume(mesh, t) > 0.0 ? 0 : 1;
  }
  return count;
}

std::vector<std::array<int, 3>> SortedFaces(const SurfaceMesh& surface)
{
  std::vector<std::array<int, 3>> faces;
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    faces.push_back(Canonical(surface.Faces(f, 0), surface.Faces(f, 1), surface.Faces(f, 2)));
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

/// Runs Tetrahedralize and the checks every valid result must pass; returns the tet mesh.
TetMesh Mesh(const std::string& name,
  const SurfaceMesh& surface,
  const TetrahedralizeParameters& params,
  double expectedVolume,
  int boundaryComponents)
{
  TetMesh mesh;
  std::string switches;
  const auto start = std::chrono::steady_clock::now();
  const auto status = polycubehex::Tetrahedralize(surface, params, mesh, switches);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << name << ": -" << switches << " -> " << mesh.Cells.rows() << " tets, "
            << mesh.Vertices.rows() << " vertices, " << seconds << " s " << status.Message()
            << std::endl;
  PCH_CHECK(status.Ok());
  PCH_CHECK(mesh.Cells.rows() > 0);
  if (!status.Ok())
  {
    return mesh;
  }
  PCH_CHECK(NonPositiveCount(mesh) == 0);
  PCH_CHECK_NEAR(MeshVolume(mesh), expectedVolume, 1e-9 * std::abs(expectedVolume));
  const auto boundary = BoundaryFaces(mesh);
  PCH_CHECK(
    BoundaryComponentCount(boundary, static_cast<int>(mesh.Vertices.rows())) == boundaryComponents);
  // The input vertices come first, unchanged.
  PCH_CHECK(mesh.Vertices.rows() >= surface.Vertices.rows());
  PCH_CHECK(mesh.Vertices.topRows(surface.Vertices.rows()) == surface.Vertices);
  if (params.PreserveBoundary)
  {
    PCH_CHECK(switches.find('Y') != std::string::npos);
    PCH_CHECK(boundary == SortedFaces(surface));
  }
  return mesh;
}

bool Refused(const SurfaceMesh& surface, const std::string& part)
{
  TetMesh mesh;
  std::string switches;
  const auto status =
    polycubehex::Tetrahedralize(surface, TetrahedralizeParameters(), mesh, switches);
  std::cout << "refused: " << status.Message() << std::endl;
  return !status.Ok() && mesh.Cells.rows() == 0 && switches.empty() &&
    Contains(status.Message(), "cannot tetrahedralize") && Contains(status.Message(), part);
}
} // namespace

int main(int, char*[])
{
  const SurfaceMesh sphere = Icosphere(3, 1.0, Eigen::Vector3d(0.5, -1.0, 2.0));
  TetrahedralizeParameters defaults;
  {
    TetMesh mesh;
    std::string switches;
    const auto status = polycubehex::Tetrahedralize(sphere, defaults, mesh, switches);
    if (!status.Ok() && status.Message().find("without TetGen") != std::string::npos)
    {
      std::cout << "built without TetGen: " << status.Message() << std::endl;
      return PCH_TEST_RESULT();
    }
    PCH_CHECK(switches == "pq2Q");
  }

  // A ball, at default quality and with the boundary kept.
  const TetMesh ball = Mesh("ball", sphere, defaults, PolyhedronVolume(sphere), 1);
  TetrahedralizeParameters preserve;
  preserve.PreserveBoundary = true;
  Mesh("ball, boundary kept", sphere, preserve, PolyhedronVolume(sphere), 1);

  // A volume bound holds for every tet and refines the mesh.
  TetrahedralizeParameters bounded;
  bounded.MaxTetVolume = 1e-3;
  const TetMesh fine = Mesh("ball, a1e-3", sphere, bounded, PolyhedronVolume(sphere), 1);
  PCH_CHECK(fine.Cells.rows() > ball.Cells.rows());
  double largest = 0.0;
  for (int t = 0; t < fine.Cells.rows(); ++t)
  {
    largest = std::max(largest, TetVolume(fine, t));
  }
  // TetGen's bound is not strict: measured up to 12% above it on fertility.
  std::cout << "largest tet volume " << largest << " for a bound of 1e-3" << std::endl;
  PCH_CHECK(largest <= 1.25e-3);

  // A target count lands within a factor of two.
  TetrahedralizeParameters target;
  target.TargetTetCount = 20000;
  const TetMesh targeted = Mesh("ball, 20000 tets", sphere, target, PolyhedronVolume(sphere), 1);
  PCH_CHECK(targeted.Cells.rows() > 10000 && targeted.Cells.rows() < 40000);

  // Guard rail: a bound that would make about 2e16 tets is refused before TetGen runs.
  {
    TetrahedralizeParameters huge;
    huge.MaxTetVolume = 1e-15;
    TetMesh unused;
    std::string switches;
    const polycubehex::Status refused =
      polycubehex::Tetrahedralize(sphere, huge, unused, switches);
    PCH_CHECK(!refused && refused.Message().find("GB") != std::string::npos);
    std::cout << "refused: " << refused.Message() << std::endl;
  }

  // A ball with a void (inner sphere facing into the void): the void stays empty.
  const SurfaceMesh outer = Icosphere(3, 1.0, Eigen::Vector3d::Zero());
  const SurfaceMesh inner = Icosphere(2, 0.4, Eigen::Vector3d(0.2, 0.1, 0.0), true);
  const SurfaceMesh hollow = Merge(outer, inner);
  const double shell = PolyhedronVolume(outer) + PolyhedronVolume(inner);
  Mesh("hollow ball", hollow, defaults, shell, 2);
  Mesh("hollow ball, boundary kept", hollow, preserve, shell, 2);
  // The void is found by nesting, whatever its orientation.
  const SurfaceMesh inner2 = Icosphere(2, 0.4, Eigen::Vector3d(0.2, 0.1, 0.0));
  Mesh("hollow ball, void oriented outwards", Merge(outer, inner2), defaults, shell, 2);

  // An island in the void is meshed; so is a second, separate ball.
  const SurfaceMesh islandBall = Icosphere(1, 0.15, Eigen::Vector3d(0.2, 0.1, 0.0));
  const SurfaceMesh other = Icosphere(2, 0.5, Eigen::Vector3d(3.0, 0.0, 0.0));
  Mesh("island in a void, and a second ball",
    Merge(Merge(hollow, islandBall), other),
    defaults,
    shell + PolyhedronVolume(islandBall) + PolyhedronVolume(other),
    4);

  // A torus (genus 1); and a small ball far from the origin (tolerances are relative).
  const SurfaceMesh torus = Torus(3.0, 1.0, 48, 16);
  Mesh("torus", torus, preserve, PolyhedronVolume(torus), 1);
  const SurfaceMesh far = Icosphere(2, 1e-3, Eigen::Vector3d(1e3, -2e3, 5e2));
  Mesh("tiny far ball", far, defaults, PolyhedronVolume(far), 1);

  // Unused vertices are dropped, not meshed.
  SurfaceMesh extra = sphere;
  extra.Vertices.conservativeResize(extra.Vertices.rows() + 1, 3);
  extra.Vertices.row(extra.Vertices.rows() - 1) << 0.5, -1.0, 2.0; // the centre
  {
    TetMesh mesh;
    std::string switches;
    PCH_CHECK(polycubehex::Tetrahedralize(extra, preserve, mesh, switches).Ok());
    PCH_CHECK(mesh.Vertices.topRows(sphere.Vertices.rows()) == sphere.Vertices);
    PCH_CHECK(BoundaryFaces(mesh) == SortedFaces(sphere));
  }

  // Broken surfaces are refused with CheckClosedSurface's message.
  SurfaceMesh open = sphere;
  open.Faces.conservativeResize(open.Faces.rows() - 1, 3);
  PCH_CHECK(Refused(open, "the surface is not closed: 3 boundary edges"));
  PCH_CHECK(Refused(GlueTets(2), "edge (0, 1) at (0, 0, 0)-(1, 0, 0) in 4 triangles"));
  PCH_CHECK(Refused(GlueTets(1), "vertex 0 at (0, 0, 0) (2 fans)"));
  SurfaceMesh flipped = sphere;
  std::swap(flipped.Faces(11, 0), flipped.Faces(11, 1));
  PCH_CHECK(Refused(flipped, "the surface is not consistently oriented: 3 edges"));

  // Self-intersection: TetGen's own check, reported as a sentence.
  {
    const SurfaceMesh crossing = Merge(sphere, Icosphere(2, 1.0, Eigen::Vector3d(1.0, -1.0, 2.0)));
    TetMesh mesh;
    std::string switches;
    const auto status = polycubehex::Tetrahedralize(crossing, defaults, mesh, switches);
    std::cout << "crossing spheres: " << status.Message() << std::endl;
    PCH_CHECK(!status.Ok());
    PCH_CHECK(status.Message().find("intersects itself") != std::string::npos);
  }

  // Bad parameters, and an abort from the progress callback.
  {
    TetMesh mesh;
    std::string switches;
    TetrahedralizeParameters bad;
    bad.RadiusEdgeRatio = 0.5;
    const auto status = polycubehex::Tetrahedralize(sphere, bad, mesh, switches);
    PCH_CHECK(!status.Ok() && status.Message().find("RadiusEdgeRatio") != std::string::npos);
    const auto aborted =
      polycubehex::Tetrahedralize(sphere, defaults, mesh, switches, [](double) { return false; });
    PCH_CHECK(!aborted.Ok() && aborted.Message().find("abort") != std::string::npos);
    PCH_CHECK(mesh.Cells.rows() == 0);
  }
  return PCH_TEST_RESULT();
}
