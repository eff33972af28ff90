// SPDX-License-Identifier: BSD-3-Clause
// extractHexMesh on polycubes made of unit cubes split into 6 tets each: exact counts and
// perfect hexes without padding and smoothing, bent originals, the padding layer, smoothing,
// refusals, and the valid-hex-mesh conditions of shared/DESIGN.md section 4 checked here.
#include "HexExtraction.h"
#include "HexMeshValidity.h"
#include "HexScaledJacobian.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <vector>

using namespace polycubehex;
using polycubehex_test::BlockCells;

namespace
{
constexpr int FaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

/// A polycube made of the unit cubes with minimum corners `cubes`, each split into 6 tets around
/// its main diagonal (the same split everywhere, so the tets are conforming). Original and
/// polycube positions are the grid; labels follow the boundary faces' normals.
/// `sheet` tells corners with one position apart: corners of two cubes are one vertex when
/// their positions and sheets agree (0 everywhere by default).
PolycubeTetMesh CubeComplex(const std::vector<std::array<int, 3>>& cubes,
  const std::function<int(int cube, int x, int y, int z)>& sheet = {})
{
  std::map<std::array<int, 4>, int> ids;
  std::vector<Eigen::RowVector3d> points;
  int cubeIndex = 0;
  auto id = [&](int x, int y, int z)
  {
    const int tag = sheet ? sheet(cubeIndex, x, y, z) : 0;
    const auto inserted =
      ids.emplace(std::array<int, 4>{ x, y, z, tag }, static_cast<int>(ids.size()));
    if (inserted.second)
    {
      points.emplace_back(x, y, z);
    }
    return inserted.first->second;
  };
  const int permutations[6][3] = {
    { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
  };
  std::vector<std::array<int, 4>> tets;
  for (; cubeIndex < static_cast<int>(cubes.size()); ++cubeIndex)
  {
    const auto& cube = cubes[cubeIndex];
    for (const auto& perm : permutations)
    {
      std::array<int, 3> corner = cube;
      std::array<int, 4> tet;
      tet[0] = id(corner[0], corner[1], corner[2]);
      for (int s = 0; s < 3; ++s)
      {
        ++corner[perm[s]];
        tet[s + 1] = id(corner[0], corner[1], corner[2]);
      }
      tets.push_back(tet);
    }
  }
  PolycubeTetMesh mesh;
  mesh.OriginalVertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i)
  {
    mesh.OriginalVertices.row(static_cast<Eigen::Index>(i)) = points[i];
  }
  mesh.PolycubeVertices = mesh.OriginalVertices;
  mesh.Cells.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
  {
    auto& tet = tets[t];
    const Eigen::Vector3d a = points[tet[0]].transpose();
    const double volume =
      (points[tet[1]].transpose() - a)
        .dot((points[tet[2]].transpose() - a).cross(points[tet[3]].transpose() - a));
    if (volume < 0.0)
    {
      std::swap(tet[1], tet[2]);
    }
    for (int k = 0; k < 4; ++k)
    {
      mesh.Cells(static_cast<Eigen::Index>(t), k) = tet[k];
    }
  }
  // Labels: faces seen once are on the boundary; the label is the normal's axis and sign.
  std::map<std::array<int, 3>, int> faceUses;
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      std::array<int, 3> key = { mesh.Cells(t, FaceTable[k][0]),
        mesh.Cells(t, FaceTable[k][1]),
        mesh.Cells(t, FaceTable[k][2]) };
      std::sort(key.begin(), key.end());
      ++faceUses[key];
    }
  }
  mesh.FaceLabels.setConstant(mesh.Cells.rows(), 4, -1);
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      std::array<int, 3> face = { mesh.Cells(t, FaceTable[k][0]),
        mesh.Cells(t, FaceTable[k][1]),
        mesh.Cells(t, FaceTable[k][2]) };
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      if (faceUses[key] != 1)
      {
        continue;
      }
      const Eigen::Vector3d a = points[face[0]].transpose();
      const Eigen::Vector3d n =
        (points[face[1]].transpose() - a).cross(points[face[2]].transpose() - a);
      int axis = 0;
      n.cwiseAbs().maxCoeff(&axis);
      mesh.FaceLabels(t, k) = 2 * axis + (n[axis] > 0.0 ? 0 : 1);
    }
  }
  return mesh;
}

/// An L-shaped prism: 3 x 3 x 2 cubes minus the 2 x 2 x 2 block at the far corner (10 cubes).
std::vector<std::array<int, 3>> LShape()
{
  std::vector<std::array<int, 3>> cubes;
  for (const auto& cube : BlockCells(3, 3, 2))
  {
    if (cube[0] == 0 || cube[1] == 0)
    {
      cubes.push_back(cube);
    }
  }
  return cubes;
}

/// A smooth bend that keeps every tet positive: used as the original of a cube polycube.
Eigen::RowVector3d Bend(const Eigen::RowVector3d& p)
{
  return Eigen::RowVector3d(p.x() + 0.15 * std::sin(1.3 * p.y()),
    p.y() + 0.1 * p.x() * p.z(),
    p.z() + 0.12 * std::cos(p.x() + p.y()));
}

double PointTriangleDistance(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  // Minimise over a fine barycentric sampling refined by projection onto the plane: enough for a
  // test that expects 0 up to rounding.
  const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  const Eigen::Vector3d q = p - n * n.dot(p - a);
  Eigen::Matrix<double, 3, 2> basis;
  basis << b - a, c - a;
  const Eigen::Vector2d uv = basis.colPivHouseholderQr().solve(q - a);
  if (uv[0] >= -1e-12 && uv[1] >= -1e-12 && uv[0] + uv[1] <= 1.0 + 1e-12)
  {
    return (p - q).norm();
  }
  auto segment = [&p](const Eigen::Vector3d& s, const Eigen::Vector3d& e)
  {
    const double t = std::clamp((p - s).dot(e - s) / (e - s).squaredNorm(), 0.0, 1.0);
    return (p - (s + t * (e - s))).norm();
  };
  return std::min({ segment(a, b), segment(b, c), segment(c, a) });
}

/// Largest distance from a boundary vertex of the hex mesh to the tet mesh's boundary surface.
double BoundaryDistance(const HexExtractionResult& result, const PolycubeTetMesh& input)
{
  std::map<std::array<int, 3>, std::array<int, 3>> faces;
  std::map<std::array<int, 3>, int> uses;
  for (int t = 0; t < input.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      std::array<int, 3> face = { input.Cells(t, FaceTable[k][0]),
        input.Cells(t, FaceTable[k][1]),
        input.Cells(t, FaceTable[k][2]) };
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      ++uses[key];
      faces[key] = face;
    }
  }
  std::vector<bool> onBoundary(result.Mesh.Vertices.rows(), false);
  for (int q = 0; q < result.BoundaryQuads.rows(); ++q)
  {
    for (int k = 0; k < 4; ++k)
    {
      onBoundary[result.BoundaryQuads(q, k)] = true;
    }
  }
  double worst = 0.0;
  for (int v = 0; v < result.Mesh.Vertices.rows(); ++v)
  {
    if (!onBoundary[v])
    {
      continue;
    }
    const Eigen::Vector3d p = result.Mesh.Vertices.row(v).transpose();
    double best = 1e300;
    for (const auto& entry : uses)
    {
      if (entry.second != 1)
      {
        continue;
      }
      const auto& f = faces[entry.first];
      best = std::min(best,
        PointTriangleDistance(p,
          input.OriginalVertices.row(f[0]).transpose(),
          input.OriginalVertices.row(f[1]).transpose(),
          input.OriginalVertices.row(f[2]).transpose()));
    }
    worst = std::max(worst, best);
  }
  return worst;
}

/// The conditions of a valid hex mesh (DESIGN.md section 4) checked directly: 8 distinct
/// vertices and SJ > 0 per hex, every quad shared by at most two hexes with opposite
/// orientations, a closed manifold boundary, no two vertices closer than 1e-9 of the diagonal.
void CheckValidHexMesh(const HexMesh& mesh, const char* name)
{
  HexMeshValidity validity;
  PCH_CHECK(checkHexMeshValidity(mesh, validity).Ok());
  if (!validity.IsValid())
  {
    std::cerr << name << ": " << validity.Report << std::endl;
  }
  PCH_CHECK(validity.IsValid());

  // Every interior quad is shared by exactly two hexes, seen in opposite directions.
  std::map<std::array<int, 4>, std::vector<std::array<int, 4>>> quads;
  for (int h = 0; h < mesh.Cells.rows(); ++h)
  {
    std::array<int, 8> sorted;
    for (int k = 0; k < 8; ++k)
    {
      sorted[k] = mesh.Cells(h, k);
    }
    std::sort(sorted.begin(), sorted.end());
    PCH_CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    for (const auto& face : HexFaces)
    {
      std::array<int, 4> quad;
      for (int k = 0; k < 4; ++k)
      {
        quad[k] = mesh.Cells(h, face[k]);
      }
      std::array<int, 4> key = quad;
      std::sort(key.begin(), key.end());
      quads[key].push_back(quad);
    }
  }
  int overShared = 0;
  int sameDirection = 0;
  for (const auto& entry : quads)
  {
    overShared += entry.second.size() > 2 ? 1 : 0;
    if (entry.second.size() == 2)
    {
      const auto& a = entry.second[0];
      const auto& b = entry.second[1];
      const int p = static_cast<int>(std::find(b.begin(), b.end(), a[0]) - b.begin());
      sameDirection += b[(p + 1) % 4] == a[1] ? 1 : 0;
    }
  }
  PCH_CHECK(overShared == 0);
  PCH_CHECK(sameDirection == 0);

  // No two vertices closer than 1e-9 of the diagonal (sorted sweep along x).
  const double diagonal =
    (mesh.Vertices.colwise().maxCoeff() - mesh.Vertices.colwise().minCoeff()).norm();
  std::vector<int> order(mesh.Vertices.rows());
  for (size_t i = 0; i < order.size(); ++i)
  {
    order[i] = static_cast<int>(i);
  }
  std::sort(order.begin(),
    order.end(),
    [&mesh](int a, int b) { return mesh.Vertices(a, 0) < mesh.Vertices(b, 0); });
  int close = 0;
  for (size_t i = 0; i < order.size(); ++i)
  {
    for (size_t j = i + 1; j < order.size() &&
         mesh.Vertices(order[j], 0) - mesh.Vertices(order[i], 0) < 1e-9 * diagonal;
         ++j)
    {
      close += (mesh.Vertices.row(order[i]) - mesh.Vertices.row(order[j])).norm() < 1e-9 * diagonal;
    }
  }
  PCH_CHECK(close == 0);

  const Eigen::VectorXd sj = ComputeHexScaledJacobians(mesh);
  PCH_CHECK(sj.minCoeff() > 0.0);
}

HexExtractionParameters Raw(int targetCount)
{
  HexExtractionParameters params;
  params.TargetHexCount = targetCount;
  params.Padding = false;
  params.Smoothing = false;
  return params;
}

void Report(const char* name, const HexExtractionResult& r, double seconds)
{
  std::cout << name << ": " << r.HexCount << " hexes (" << r.PaddingHexCount << " padding), SJ min "
            << r.ScaledJacobianMin << " mean " << r.ScaledJacobianMean << " (before smoothing "
            << r.ScaledJacobianMinBeforeSmoothing << " / " << r.ScaledJacobianMeanBeforeSmoothing
            << "), charts " << r.ChartCount << ", planes " << r.PlaneCount << ", max plane shift "
            << r.MaxPlaneShift << ", irregular boundary vertices " << r.IrregularBoundaryVertexCount
            << ", " << seconds << " s (rounding " << r.RoundingSeconds << ", extraction "
            << r.ExtractionSeconds << ", padding " << r.PaddingSeconds << ", smoothing "
            << r.SmoothingSeconds << " in " << r.SmoothingSweeps << " sweeps)" << std::endl;
}

HexExtractionResult Run(const char* name,
  const PolycubeTetMesh& input,
  const HexExtractionParameters& params,
  bool expectSuccess = true)
{
  HexExtractionResult result;
  const auto start = std::chrono::steady_clock::now();
  const Status status = extractHexMesh(input, params, result);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  PCH_CHECK(status.Ok() == expectSuccess);
  if (!status)
  {
    std::cout << name << ": refused: " << status.Message() << std::endl;
  }
  else
  {
    Report(name, result, seconds);
  }
  return result;
}

/// Exact cube counts and perfect hexes: a 2 x 2 x 2 block at resolution n gives n^3 cubes.
void TestCube()
{
  const PolycubeTetMesh input = CubeComplex(BlockCells(2, 2, 2));
  for (int n = 1; n <= 6; ++n)
  {
    const HexExtractionResult r = Run("cube", input, Raw(n * n * n));
    PCH_CHECK(r.HexCount == n * n * n);
    PCH_CHECK((n + 1) * (n + 1) * (n + 1) == r.Mesh.Vertices.rows());
    PCH_CHECK_NEAR(r.ScaledJacobianMin, 1.0, 1e-12);
    PCH_CHECK(r.ChartCount == 6);
    PCH_CHECK(r.IrregularBoundaryVertexCount == 8);
    CheckValidHexMesh(r.Mesh, "cube");
    PCH_CHECK(BoundaryDistance(r, input) < 1e-12);
    int labelled = 0;
    for (int label : r.BoundaryQuadLabels)
    {
      labelled += label >= 0 ? 1 : 0;
    }
    PCH_CHECK(labelled == 6 * n * n);
  }
  // A resolution between cubes rounds to a cube that stays a cube.
  const HexExtractionResult r = Run("cube 30", input, Raw(30));
  PCH_CHECK(r.HexCount == 27);
  CheckValidHexMesh(r.Mesh, "cube 30");
}

/// An L-shaped prism of 10 cubes: at m hexes per cube edge, exactly 10 m^3 hexes.
void TestLShape()
{
  const PolycubeTetMesh input = CubeComplex(LShape());
  for (int m = 1; m <= 3; ++m)
  {
    const HexExtractionResult r = Run("L", input, Raw(10 * m * m * m));
    PCH_CHECK(r.HexCount == 10 * m * m * m);
    PCH_CHECK(r.ChartCount == 8);
    PCH_CHECK(r.ScaledJacobianMin > 0.0);
    CheckValidHexMesh(r.Mesh, "L");
  }
  // An uneven resolution: planes move off the unit cubes' lattice, all hexes stay positive.
  const HexExtractionResult r = Run("L 500", input, Raw(500));
  PCH_CHECK(r.HexCount > 300 && r.HexCount < 700);
  PCH_CHECK(r.ScaledJacobianMin > 0.0);
  CheckValidHexMesh(r.Mesh, "L 500");
}

/// A bent original over a box polycube: counts follow the polycube, vertices the original, and
/// boundary vertices lie on the original's boundary.
void TestBentOriginal()
{
  PolycubeTetMesh input = CubeComplex(BlockCells(3, 2, 2));
  for (int v = 0; v < input.OriginalVertices.rows(); ++v)
  {
    input.OriginalVertices.row(v) = Bend(input.PolycubeVertices.row(v));
  }
  const HexExtractionResult r = Run("bent", input, Raw(12 * 27));
  PCH_CHECK(r.HexCount == 12 * 27);
  PCH_CHECK(r.ScaledJacobianMin > 0.0);
  CheckValidHexMesh(r.Mesh, "bent");
  PCH_CHECK(BoundaryDistance(r, input) < 1e-12);

  // Edge length target: the bent box has volume ~12, so an edge of 0.5 gives ~96 hexes.
  HexExtractionParameters byEdge = Raw(1);
  byEdge.TargetEdgeLength = 0.5;
  const HexExtractionResult e = Run("bent, edge 0.5", input, byEdge);
  PCH_CHECK(e.HexCount >= 60 && e.HexCount <= 150);
  CheckValidHexMesh(e.Mesh, "bent, edge 0.5");
}

/// A helix of 9 cubes around a square hole whose last cube lies on its first one in the polycube
/// but one turn higher in the original: the map is not injective, so a lattice coordinate stands
/// for two points of the input. Vertices must be told apart by their tet region, not merged by
/// coordinate, and both overlapping cubes must become hexes of their own.
void TestOverlappingHelix()
{
  const std::vector<std::array<int, 3>> cubes = { { 0, 0, 0 },
    { 1, 0, 0 },
    { 2, 0, 0 },
    { 2, 1, 0 },
    { 2, 2, 0 },
    { 1, 2, 0 },
    { 0, 2, 0 },
    { 0, 1, 0 },
    { 0, 0, 0 } };
  const double pi = std::acos(-1.0);
  // Unwrapped angle around the hole's axis (1.5, 1.5), continuous along the chain of cubes.
  auto angle = [&cubes, pi](int cube, double x, double y)
  {
    const double centre = -0.75 * pi + 0.25 * pi * cube;
    double raw = std::atan2(y - 1.5, x - 1.5) - centre;
    raw -= 2.0 * pi * std::round(raw / (2.0 * pi));
    (void)cubes;
    return centre + raw;
  };
  PolycubeTetMesh input = CubeComplex(cubes,
    [&angle](int cube, int x, int y, int)
    { return static_cast<int>(std::lround(angle(cube, x, y) * 1000.0)); });
  // Lift each vertex by its angle: 2 units per turn, so the last cube sits above the first.
  std::map<std::array<long, 3>, std::vector<int>> byPosition;
  for (int t = 0; t < input.Cells.rows(); ++t)
  {
    const int cube = t / 6;
    for (int k = 0; k < 4; ++k)
    {
      const int v = input.Cells(t, k);
      const Eigen::RowVector3d p = input.PolycubeVertices.row(v);
      input.OriginalVertices(v, 2) =
        p.z() + 2.0 * (angle(cube, p.x(), p.y()) + 0.75 * pi) / (2 * pi);
    }
  }
  for (int n = 1; n <= 3; ++n)
  {
    const HexExtractionResult r = Run("helix", input, Raw(9 * n * n * n));
    PCH_CHECK(r.HexCount == 9 * n * n * n);
    PCH_CHECK(r.ScaledJacobianMin > 0.0);
    CheckValidHexMesh(r.Mesh, "helix");
    PCH_CHECK(BoundaryDistance(r, input) < 1e-12);
    // The first and the last cube share their lattice coordinates but no vertex.
    int shared = 0;
    for (int v = 0; v < r.LatticeVertices.rows(); ++v)
    {
      for (int w = v + 1; w < r.LatticeVertices.rows(); ++w)
      {
        shared += r.LatticeVertices.row(v) == r.LatticeVertices.row(w) ? 1 : 0;
      }
    }
    PCH_CHECK(shared == (n + 1) * (n + 1) * (n + 1));
  }
  HexExtractionParameters padded;
  padded.TargetHexCount = 2000;
  const HexExtractionResult r = Run("helix + padding + smoothing", input, padded);
  PCH_CHECK(r.ScaledJacobianMin > 0.0);
  CheckValidHexMesh(r.Mesh, "helix + padding + smoothing");
  PCH_CHECK(BoundaryDistance(r, input) < 1e-9);
}

/// The padding layer: one hex per boundary quad, none with two faces on the boundary, and the
/// budget shared between the layer and the core.
void TestPadding()
{
  const PolycubeTetMesh input = CubeComplex(BlockCells(2, 2, 2));
  for (int n = 2; n <= 4; ++n)
  {
    HexExtractionParameters params = Raw(n * n * n + 6 * n * n);
    params.Padding = true;
    const HexExtractionResult r = Run("cube + padding", input, params);
    PCH_CHECK(r.HexCount == n * n * n + 6 * n * n);
    PCH_CHECK(r.PaddingHexCount == 6 * n * n);
    PCH_CHECK(r.ScaledJacobianMin > 0.0);
    CheckValidHexMesh(r.Mesh, "cube + padding");
    PCH_CHECK(BoundaryDistance(r, input) < 1e-12);
    // No hex has two faces on the boundary.
    std::map<std::array<int, 4>, int> uses;
    for (int h = 0; h < r.Mesh.Cells.rows(); ++h)
    {
      for (const auto& face : HexFaces)
      {
        std::array<int, 4> key;
        for (int k = 0; k < 4; ++k)
        {
          key[k] = r.Mesh.Cells(h, face[k]);
        }
        std::sort(key.begin(), key.end());
        ++uses[key];
      }
    }
    int worst = 0;
    for (int h = 0; h < r.Mesh.Cells.rows(); ++h)
    {
      int onBoundary = 0;
      for (const auto& face : HexFaces)
      {
        std::array<int, 4> key;
        for (int k = 0; k < 4; ++k)
        {
          key[k] = r.Mesh.Cells(h, face[k]);
        }
        std::sort(key.begin(), key.end());
        onBoundary += uses[key] == 1 ? 1 : 0;
      }
      worst = std::max(worst, onBoundary);
    }
    PCH_CHECK(worst == 1);
  }

  // Padding + smoothing on the L and on the bent box: valid, on the surface, min SJ not lowered.
  const PolycubeTetMesh l = CubeComplex(LShape());
  HexExtractionParameters params;
  params.TargetHexCount = 600;
  const HexExtractionResult r = Run("L + padding + smoothing", l, params);
  PCH_CHECK(r.PaddingHexCount > 0);
  PCH_CHECK(r.ScaledJacobianMin > 0.0);
  PCH_CHECK(r.ScaledJacobianMin >= r.ScaledJacobianMinBeforeSmoothing);
  CheckValidHexMesh(r.Mesh, "L + padding + smoothing");
  PCH_CHECK(BoundaryDistance(r, l) < 1e-9);

  PolycubeTetMesh bent = CubeComplex(BlockCells(3, 2, 2));
  for (int v = 0; v < bent.OriginalVertices.rows(); ++v)
  {
    bent.OriginalVertices.row(v) = Bend(bent.PolycubeVertices.row(v));
  }
  params.TargetHexCount = 1000;
  const HexExtractionResult b = Run("bent + padding + smoothing", bent, params);
  PCH_CHECK(b.ScaledJacobianMin > 0.0);
  PCH_CHECK(b.ScaledJacobianMin >= b.ScaledJacobianMinBeforeSmoothing);
  // Moves that raise the worst hex may cost a little of the mean.
  PCH_CHECK(b.ScaledJacobianMean >= b.ScaledJacobianMeanBeforeSmoothing - 0.01);
  CheckValidHexMesh(b.Mesh, "bent + padding + smoothing");
  PCH_CHECK(BoundaryDistance(b, bent) < 1e-9);
}

/// A thin tet is not a flat one: a bar of 40 cubes whose last cube is squeezed to 1e-9 of its
/// length has tets of volume 1.7e-10, under 1e-14 of the bar's diagonal cubed, but sound for
/// their size (a height of 1e-9 of their edges); extraction takes them. Squeezed to nothing,
/// the same tets are flat and refused.
void TestThinTets()
{
  PolycubeTetMesh thin = CubeComplex(BlockCells(40, 1, 1));
  PolycubeTetMesh flat = thin;
  for (int v = 0; v < thin.PolycubeVertices.rows(); ++v)
  {
    if (thin.PolycubeVertices(v, 0) == 40.0)
    {
      thin.PolycubeVertices(v, 0) = thin.OriginalVertices(v, 0) = 39.0 + 1e-9;
      flat.PolycubeVertices(v, 0) = flat.OriginalVertices(v, 0) = 39.0;
    }
  }
  HexExtractionResult result;
  const Status accepted = extractHexMesh(thin, Raw(40), result);
  std::cout << "thin tets: " << (accepted ? "extracted, " : accepted.Message()) << result.HexCount
            << " hexes" << std::endl;
  PCH_CHECK(accepted.Ok());
  PCH_CHECK(result.HexCount > 0);
  const Status refused = extractHexMesh(flat, Raw(40), result);
  std::cout << "flat tets: " << refused.Message() << std::endl;
  PCH_CHECK(!refused.Ok());
  PCH_CHECK(refused.Message().find("inverted or flat") != std::string::npos);
}

/// Inputs extraction must refuse, each with a message that says why.
void TestRefusals()
{
  const PolycubeTetMesh good = CubeComplex(BlockCells(2, 2, 2));
  HexExtractionResult result;

  PolycubeTetMesh inverted = good;
  std::swap(inverted.Cells(5, 1), inverted.Cells(5, 2));
  Status status = extractHexMesh(inverted, Raw(8), result);
  PCH_CHECK(!status.Ok());
  PCH_CHECK(status.Message().find("inverted") != std::string::npos);
  std::cout << "inverted tet: " << status.Message() << std::endl;

  // The centre vertex pushed through the block's side inverts tets in the polycube only.
  PolycubeTetMesh invertedPolycube = good;
  for (int v = 0; v < invertedPolycube.PolycubeVertices.rows(); ++v)
  {
    if (invertedPolycube.PolycubeVertices.row(v) == Eigen::RowVector3d(1.0, 1.0, 1.0))
    {
      invertedPolycube.PolycubeVertices(v, 0) = 2.5;
    }
  }
  status = extractHexMesh(invertedPolycube, Raw(8), result);
  PCH_CHECK(!status.Ok());
  PCH_CHECK(status.Message().find("polycube") != std::string::npos);
  std::cout << "inverted in the polycube: " << status.Message() << std::endl;

  PolycubeTetMesh unlabelled = good;
  unlabelled.FaceLabels.setConstant(-1);
  status = extractHexMesh(unlabelled, Raw(8), result);
  PCH_CHECK(!status.Ok());
  PCH_CHECK(status.Message().find("no polycube labels") != std::string::npos);
  std::cout << "no labels: " << status.Message() << std::endl;

  PolycubeTetMesh missing = good;
  for (int t = 0; t < missing.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (missing.FaceLabels(t, k) >= 0)
      {
        missing.FaceLabels(t, k) = -1;
        t = static_cast<int>(missing.Cells.rows());
        break;
      }
    }
  }
  status = extractHexMesh(missing, Raw(8), result);
  PCH_CHECK(!status.Ok());
  PCH_CHECK(status.Message().find("no polycube label") != std::string::npos);
  std::cout << "one label missing: " << status.Message() << std::endl;

  PolycubeTetMesh wrong = good;
  for (int t = 0; t < wrong.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (wrong.FaceLabels(t, k) >= 0)
      {
        wrong.FaceLabels(t, k) ^= 1; // +X <-> -X and so on
      }
    }
  }
  status = extractHexMesh(wrong, Raw(8), result);
  PCH_CHECK(!status.Ok());
  std::cout << "flipped labels: " << status.Message() << std::endl;

  // Guard rail: two billion hexes would need terabytes; refused up front with the estimate.
  status = extractHexMesh(good, Raw(2000000000), result);
  PCH_CHECK(!status.Ok() && status.Message().find("GB") != std::string::npos);
  std::cout << "too many hexes: " << status.Message() << std::endl;

  HexExtractionParameters none = Raw(0);
  status = extractHexMesh(good, none, result);
  PCH_CHECK(!status.Ok());
  std::cout << "no target: " << status.Message() << std::endl;
}

/// A staircase of 6 x 6 columns of heights 1..4 (monotone, so no two columns touch along an
/// edge only), each unit cube split into 2 x 2 x 2 cubes, under a bent original: many charts,
/// planes that do not fall on the lattice, and a tet mesh finer than the hexes.
void TestStaircase()
{
  std::vector<std::array<int, 3>> cubes;
  for (int i = 0; i < 12; ++i)
  {
    for (int j = 0; j < 12; ++j)
    {
      const int height = 2 * (1 + ((i / 2) * (i / 2) + 2 * (j / 2)) / 8);
      for (int k = 0; k < height; ++k)
      {
        cubes.push_back({ i, j, k });
      }
    }
  }
  PolycubeTetMesh input = CubeComplex(cubes);
  for (int v = 0; v < input.OriginalVertices.rows(); ++v)
  {
    input.OriginalVertices.row(v) = Bend(0.25 * input.PolycubeVertices.row(v));
  }
  std::cout << "staircase: " << input.Cells.rows() << " tets" << std::endl;
  for (int target : { 300, 3000, 30000 })
  {
    const HexExtractionResult raw = Run("staircase raw", input, Raw(target));
    PCH_CHECK(raw.ScaledJacobianMin > 0.0);
    PCH_CHECK(std::abs(raw.HexCount - target) < 0.5 * target);
    CheckValidHexMesh(raw.Mesh, "staircase raw");
    HexExtractionParameters params;
    params.TargetHexCount = target;
    // The untangling (TestHexUntangling, and the smaller runs here) at 3k and 30k hexes costs
    // minutes under the sanitizers; these runs are about extraction at scale.
    params.Untangling = target < 3000;
    const HexExtractionResult r = Run("staircase + padding + smoothing", input, params);
    PCH_CHECK(r.ScaledJacobianMin > 0.0);
    PCH_CHECK(std::abs(r.HexCount - target) < 0.5 * target);
    CheckValidHexMesh(r.Mesh, "staircase + padding + smoothing");
  }
}

/// A larger block for timing: 8 x 6 x 4 cubes (1152 tets) at 20k hexes with padding and smoothing.
void TestTiming()
{
  const PolycubeTetMesh input = CubeComplex(BlockCells(8, 6, 4));
  HexExtractionParameters params;
  params.TargetHexCount = 20000;
  params.Untangling = false; // the local smoothing's timing, as before the untangling existed
  const HexExtractionResult r = Run("block 8x6x4, 20k", input, params);
  PCH_CHECK(std::abs(r.HexCount - 20000) < 2000);
  PCH_CHECK(r.ScaledJacobianMin > 0.0);
}

/// The order the two untangling paths are chosen by: inverted count first, then the minimum
/// unless it differs by no more than the margin, then the mean.
void TestPathChoiceOrder()
{
  const auto summary = [](double min, double mean, int inverted)
  {
    HexQualitySummary s;
    s.Min = min;
    s.Mean = mean;
    s.Inverted = inverted;
    return s;
  };
  const double margin = HexExtractionParameters().PathMinimumMargin;
  PCH_CHECK(margin > 0.0);
  // Fewer inverted hexes win whatever the rest.
  PCH_CHECK(BetterHexQuality(summary(-0.5, 0.5, 1), summary(0.1, 0.9, 2), margin));
  // A gain in the minimum beyond the margin wins over the mean.
  PCH_CHECK(BetterHexQuality(summary(0.5, 0.90, 0), summary(0.48, 0.95, 0), margin));
  // Within the margin, the mean decides (torus l1: 0.767 / 0.957 over 0.768 / 0.949) ...
  PCH_CHECK(BetterHexQuality(summary(0.767, 0.957, 0), summary(0.768, 0.949, 0), margin));
  PCH_CHECK(!BetterHexQuality(summary(0.768, 0.949, 0), summary(0.767, 0.957, 0), margin));
  // ... whereas without a margin the larger minimum always wins.
  PCH_CHECK(BetterHexQuality(summary(0.768, 0.949, 0), summary(0.767, 0.957, 0)));
  // Equal means: the larger minimum; equal everything: not better.
  PCH_CHECK(BetterHexQuality(summary(0.768, 0.95, 0), summary(0.767, 0.95, 0), margin));
  PCH_CHECK(!BetterHexQuality(summary(0.7, 0.95, 0), summary(0.7, 0.95, 0), margin));
}
} // namespace

int main(int, char*[])
{
  TestPathChoiceOrder();
  TestCube();
  TestLShape();
  TestBentOriginal();
  TestOverlappingHelix();
  TestPadding();
  TestRefusals();
  TestThinTets();
  TestStaircase();
  TestTiming();
  return PCH_TEST_RESULT();
}
