// SPDX-License-Identifier: BSD-3-Clause
// Handle cuts (Fang et al. 2016, section 2) on solids generated here and on the shipped models:
// the number of cuts equals beta_1, every cut lowers beta_1 by exactly one, beta_1 = 0 at the
// end by two independent counts, every cut is connected, manifold, two-sided and proper, the cut
// data (CutFaces, CutSide) is consistent with the cut mesh, and on an analytic torus the cut is
// no larger than 1.5 pi r^2.
#include "CutMesh.h"
#include "CutSurface.h"
#include "HandleCuts.h"
#include "MeditFormat.h"
#include "OffFormat.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"
#include "Tetrahedralize.h"
#include "TopologyAdjacency.h"
#include "TopologyBoundary.h"
#include "TopologyHomology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

using polycubehex::SurfaceMesh;
using polycubehex::TetMesh;
using polycubehex_test::Icosphere;
using polycubehex_test::Merge;
using polycubehex_test::Pi;
using polycubehex_test::SweptTorus;
using polycubehex_test::Torus;

namespace
{
/// A solid made of unit voxels (i, j, k) with inside(i, j, k) true, each cube split into the 6
/// tets of its Freudenthal (Kuhn) triangulation, which conforms across neighbouring cubes.
template<typename Inside>
TetMesh VoxelSolid(int nx, int ny, int nz, Inside inside)
{
  auto id = [&](int i, int j, int k) { return (i * (ny + 1) + j) * (nz + 1) + k; };
  TetMesh mesh;
  mesh.Vertices.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int i = 0; i <= nx; ++i)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int k = 0; k <= nz; ++k)
      {
        mesh.Vertices.row(id(i, j, k)) << i, j, k;
      }
    }
  }
  std::vector<std::array<int, 4>> tets;
  const int axes[6][3] = {
    { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
  };
  for (int i = 0; i < nx; ++i)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int k = 0; k < nz; ++k)
      {
        if (!inside(i, j, k))
        {
          continue;
        }
        for (const auto& order : axes)
        {
          std::array<int, 3> p = { i, j, k };
          std::array<int, 4> tet{};
          tet[0] = id(p[0], p[1], p[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++p[order[step]];
            tet[step + 1] = id(p[0], p[1], p[2]);
          }
          tets.push_back(tet);
        }
      }
    }
  }
  // Drop unused vertices.
  std::vector<int> used(mesh.Vertices.rows(), -1);
  int count = 0;
  for (auto& tet : tets)
  {
    for (int& v : tet)
    {
      if (used[v] < 0)
      {
        used[v] = count++;
      }
      v = used[v];
    }
  }
  TetMesh out;
  out.Vertices.resize(count, 3);
  for (int v = 0; v < mesh.Vertices.rows(); ++v)
  {
    if (used[v] >= 0)
    {
      out.Vertices.row(used[v]) = mesh.Vertices.row(v);
    }
  }
  polycubehex_test::SetPositiveCells(out, tets);
  return out;
}

bool ReadObj(const std::string& path, SurfaceMesh& mesh)
{
  std::ifstream in(path);
  if (!in)
  {
    return false;
  }
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> faces;
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "v")
    {
      Eigen::Vector3d p;
      words >> p.x() >> p.y() >> p.z();
      points.push_back(p);
    }
    else if (key == "f")
    {
      std::vector<int> ids;
      std::string token;
      while (words >> token)
      {
        ids.push_back(std::stoi(token.substr(0, token.find('/'))) - 1);
      }
      for (size_t i = 2; i < ids.size(); ++i)
      {
        faces.push_back({ ids[0], ids[i - 1], ids[i] });
      }
    }
  }
  mesh.Vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v)
  {
    mesh.Vertices.row(v) = points[v].transpose();
  }
  mesh.Faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
  {
    mesh.Faces.row(f) << faces[f][0], faces[f][1], faces[f][2];
  }
  return true;
}

bool ReadOffSurface(const std::string& path, SurfaceMesh& mesh)
{
  polycubehex::OffMesh off;
  if (!polycubehex::ReadOffFile(path, off))
  {
    return false;
  }
  mesh.Vertices = off.Vertices;
  std::vector<std::array<int, 3>> faces;
  for (size_t f = 0; f + 1 < off.FaceOffsets.size(); ++f)
  {
    for (int i = off.FaceOffsets[f] + 2; i < off.FaceOffsets[f + 1]; ++i)
    {
      faces.push_back(
        { off.FaceIndices[off.FaceOffsets[f]], off.FaceIndices[i - 1], off.FaceIndices[i] });
    }
  }
  mesh.Faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
  {
    mesh.Faces.row(f) << faces[f][0], faces[f][1], faces[f][2];
  }
  return true;
}

bool Tetrahedralized(const std::string& name, const SurfaceMesh& surface, TetMesh& mesh)
{
  std::string switches;
  polycubehex::TetrahedralizeParameters params;
  const auto start = std::chrono::steady_clock::now();
  const auto status = polycubehex::Tetrahedralize(surface, params, mesh, switches);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!status)
  {
    std::cerr << name << ": Tetrahedralize: " << status.Message() << std::endl;
  }
  else
  {
    std::cout << name << ": TetGen -" << switches << ": " << mesh.Cells.rows() << " tets in "
              << seconds << " s" << std::endl;
  }
  return status.Ok();
}

/// beta_1 of a tet mesh by both counts (-1 when they disagree or the boundary is broken).
int Beta1(const TetMesh& mesh)
{
  polycubehex::TetAdjacency adjacency;
  if (!polycubehex::BuildTetAdjacency(
        static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency))
  {
    return -1;
  }
  polycubehex::BoundaryTopology boundary;
  if (!polycubehex::ComputeBoundaryTopology(mesh.Cells, adjacency, boundary))
  {
    return -1;
  }
  polycubehex::CohomologyBasis basis;
  if (!polycubehex::ComputeCohomologyBasis(mesh.Cells, adjacency, false, basis))
  {
    return -1;
  }
  return boundary.Beta1 == basis.Beta1 ? boundary.Beta1 : -1;
}

/// The input split along the cuts with id < `count` (from CutFaces only).
TetMesh CutAlong(const TetMesh& mesh, const polycubehex::HandleCutResult& result, int count)
{
  polycubehex::TetAdjacency adjacency;
  polycubehex::BuildTetAdjacency(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency);
  std::vector<char> cut(adjacency.InteriorFaces.size(), 0);
  for (size_t f = 0; f < adjacency.InteriorFaces.size(); ++f)
  {
    const int id = result.CutFaces(adjacency.InteriorFaces[f][0], adjacency.InteriorFaces[f][1]);
    cut[f] = id >= 0 && id < count ? 1 : 0;
  }
  TetMesh out;
  std::vector<int> splitToOld;
  polycubehex::SplitAlongFaces(
    static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency, cut, out.Cells, splitToOld);
  out.Vertices.resize(static_cast<Eigen::Index>(splitToOld.size()), 3);
  for (size_t v = 0; v < splitToOld.size(); ++v)
  {
    out.Vertices.row(v) = mesh.Vertices.row(splitToOld[v]);
  }
  return out;
}

/// Runs the cuts and checks everything; returns the cut areas.
std::vector<double> RunCase(const std::string& name,
  const TetMesh& mesh,
  int expectedBeta1,
  const std::string& outputDir)
{
  polycubehex::HandleCutParameters params;
  polycubehex::HandleCutResult result;
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpuStart = std::clock();
  const auto status = polycubehex::ComputeHandleCuts(mesh, params, result);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  std::vector<double> areas;
  if (!status)
  {
    std::cerr << name << ": " << status.Message() << std::endl;
  }
  PCH_CHECK(status.Ok());
  if (!status)
  {
    return areas;
  }
  std::cout << name << ": " << mesh.Cells.rows() << " tets, beta1 " << result.Beta1
            << ", boundary genera";
  for (int g : result.BoundaryGenus)
  {
    std::cout << " " << g;
  }
  std::cout << ", " << result.Cuts.size() << " cuts in " << seconds << " s (cpu " << cpuSeconds
            << " s; " << result.ClassCount << " classes, " << result.MinCutCount << " min cuts, "
            << result.RepairMoveCount << " repair moves, " << result.RejectedCandidateCount << "/"
            << result.CandidateCount << " candidates rejected); areas";
  for (const auto& cut : result.Cuts)
  {
    std::cout << " " << cut.Area << " (" << cut.Faces.size() << " faces, chi "
              << cut.EulerCharacteristic << ", " << cut.Loops.size() << " loops, "
              << cut.MismatchedEdgeCount << " mismatched)";
    areas.push_back(cut.Area);
  }
  std::cout << std::endl;
  PCH_CHECK(result.Beta1 == expectedBeta1);
  PCH_CHECK(static_cast<int>(result.Cuts.size()) == expectedBeta1);
  PCH_CHECK(result.Beta1After == 0);
  PCH_CHECK(Beta1(result.CutMesh) == 0);

  // CutFaces and CutSide: both sides of a cut face carry the id, one side -1, the other +1.
  polycubehex::TetAdjacency adjacency;
  polycubehex::BuildTetAdjacency(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency);
  std::vector<int> faceCount(result.Cuts.size(), 0);
  bool consistent = true;
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int id = result.CutFaces(t, k);
      const int n = adjacency.Neighbor(t, k);
      if (id < 0)
      {
        consistent = consistent && result.CutSide(t, k) == 0;
        continue;
      }
      consistent = consistent && n >= 0;
      if (n < 0)
      {
        continue;
      }
      const int nk = adjacency.NeighborFace(t, k);
      consistent = consistent && result.CutFaces(n, nk) == id &&
        result.CutSide(t, k) * result.CutSide(n, nk) == -1;
      if (result.CutSide(t, k) < 0)
      {
        ++faceCount[id];
      }
    }
  }
  PCH_CHECK(consistent);
  for (size_t c = 0; c < result.Cuts.size(); ++c)
  {
    PCH_CHECK(faceCount[c] == static_cast<int>(result.Cuts[c].Faces.size()));
  }

  // Each cut, on the input cut by the earlier ones: valid, and beta_1 falls by exactly one.
  int previous = result.Beta1;
  for (size_t c = 0; c < result.Cuts.size(); ++c)
  {
    const TetMesh before = CutAlong(mesh, result, static_cast<int>(c));
    polycubehex::TetAdjacency adj;
    polycubehex::BuildTetAdjacency(static_cast<int>(before.Vertices.rows()), before.Cells, adj);
    std::vector<polycubehex::CutFaceEntry> entries;
    for (const auto& face : result.Cuts[c].Faces)
    {
      const int id = adj.InteriorFaceId(face[0], face[1]);
      PCH_CHECK(id >= 0);
      if (id >= 0)
      {
        entries.push_back({ id, adj.InteriorFaces[id][0] == face[0] ? 1 : -1 });
      }
    }
    polycubehex::CutSurfaceReport report;
    polycubehex::AnalyzeCutSurface(before.Cells, adj, before.Vertices, entries, report);
    if (!report.Valid())
    {
      std::cerr << name << ": cut " << c << ": " << report.Problem << std::endl;
    }
    PCH_CHECK(report.Connected);
    PCH_CHECK(report.Manifold);
    PCH_CHECK(report.TwoSided);
    PCH_CHECK_NEAR(report.Area, result.Cuts[c].Area, 1e-9 * (1.0 + report.Area));
    PCH_CHECK(!result.Cuts[c].Loops.empty());
    const int beta1Before = Beta1(before);
    const int beta1After = Beta1(CutAlong(mesh, result, static_cast<int>(c) + 1));
    PCH_CHECK(beta1Before == previous);
    PCH_CHECK(beta1After == beta1Before - 1);
    PCH_CHECK(result.Cuts[c].Beta1Before == beta1Before && result.Cuts[c].Beta1After == beta1After);
    previous = beta1After;
  }

  // The cut surfaces, for a look in ParaView.
  if (!outputDir.empty())
  {
    std::string file = name;
    std::replace(file.begin(), file.end(), ' ', '_');
    std::ofstream out(outputDir + "/HandleCuts_" + file + ".obj");
    for (int v = 0; v < mesh.Vertices.rows(); ++v)
    {
      out << "v " << mesh.Vertices(v, 0) << " " << mesh.Vertices(v, 1) << " " << mesh.Vertices(v, 2)
          << "\n";
    }
    for (size_t c = 0; c < result.Cuts.size(); ++c)
    {
      out << "g cut" << c << "\n";
      for (const auto& face : result.Cuts[c].Faces)
      {
        out << "f";
        for (int i = 0; i < 3; ++i)
        {
          out << " " << mesh.Cells(face[0], polycubehex::TetFaceTable[face[1]][i]) + 1;
        }
        out << "\n";
      }
    }
  }
  return areas;
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string dataDir = argc > 1 ? argv[1] : "";
  const std::string outputDir = argc > 2 ? argv[2] : "";

  // Analytic solid torus: the cut must be about a meridian disk, area <= 1.5 pi r^2.
  {
    const double r = 0.5;
    const auto areas = RunCase("swept torus", SweptTorus(2.0, r, 0, 4, 48), 1, outputDir);
    PCH_CHECK(areas.size() == 1 && areas[0] <= 1.5 * Pi * r * r);
    const auto thin = RunCase("thin swept torus", SweptTorus(2.0, r, 0, 1, 12), 1, outputDir);
    PCH_CHECK(thin.size() == 1 && thin[0] <= 1.5 * Pi * r * r);
  }
  // Hollow torus (torus-shaped void in a torus): an annulus, then a disk crossing it.
  RunCase("swept hollow torus", SweptTorus(2.0, 0.8, 2, 5, 40), 2, outputDir);

  // Voxel solids: every vertex of a one-voxel-thick frame is on the boundary, and the many
  // equal-area cuts of a grid stress the repair of improper surfaces.
  RunCase("voxel frame",
    VoxelSolid(5, 5, 1, [](int i, int j, int) { return i == 0 || j == 0 || i == 4 || j == 4; }),
    1,
    outputDir);
  RunCase("thick voxel frame",
    VoxelSolid(8, 8, 3, [](int i, int j, int) { return !(i >= 3 && i < 5 && j >= 3 && j < 5); }),
    1,
    outputDir);
  RunCase("voxel plate with 3 holes",
    VoxelSolid(
      11, 5, 2, [](int i, int j, int) { return !(j == 2 && (i == 2 || i == 5 || i == 8)); }),
    3,
    outputDir);
  RunCase("voxel hollow frame",
    VoxelSolid(9,
      9,
      5,
      [](int i, int j, int k)
      {
        const bool frame = !(i >= 3 && i < 6 && j >= 3 && j < 6);
        const bool voidCell =
          k == 2 && (i == 1 || i == 7 || j == 1 || j == 7) && i >= 1 && i <= 7 && j >= 1 && j <= 7;
        return frame && !voidCell;
      }),
    2,
    outputDir);
  RunCase("two voxel frames",
    VoxelSolid(11,
      5,
      1,
      [](int i, int j, int)
      {
        return (i < 5 && (i == 0 || j == 0 || i == 4 || j == 4)) ||
          (i >= 6 && (i == 6 || j == 0 || i == 10 || j == 4));
      }),
    2,
    outputDir);
  RunCase("voxel grid of 4 holes",
    VoxelSolid(5, 5, 1, [](int i, int j, int) { return i % 2 == 0 || j % 2 == 0; }),
    4,
    outputDir);

  TetMesh mesh;
  if (Tetrahedralized("ball", Icosphere(2, 1.0), mesh))
  {
    RunCase("ball", mesh, 0, outputDir);
  }
  if (Tetrahedralized(
        "ball with a spherical void", Merge(Icosphere(3, 2.0), Icosphere(2, 1.0)), mesh))
  {
    RunCase("ball with a spherical void", mesh, 0, outputDir);
  }
  if (Tetrahedralized("ball with a torus-shaped void",
        Merge(Icosphere(3, 2.0), Torus(1.0, 0.35, 32, 12)),
        mesh))
  {
    RunCase("ball with a torus-shaped void", mesh, 1, outputDir);
  }
  if (Tetrahedralized("hollow torus",
        Merge(Torus(2.0, 0.8, 48, 16), Torus(2.0, 0.4, 40, 12)),
        mesh))
  {
    RunCase("hollow torus", mesh, 2, outputDir);
  }

  SurfaceMesh surface;
  const std::vector<std::pair<std::string, int>> models = {
    { "sphere_coarse.obj", 0 }, { "torus.obj", 1 }, { "3holes.obj", 3 }, { "fertility.off", 4 }
  };
  for (const auto& model : models)
  {
    const std::string path = dataDir + "/" + model.first;
    const bool read = model.first.size() > 4 && model.first.substr(model.first.size() - 4) == ".off"
      ? ReadOffSurface(path, surface)
      : ReadObj(path, surface);
    PCH_CHECK(read);
    if (read && Tetrahedralized(model.first, surface, mesh))
    {
      RunCase(model.first, mesh, model.second, outputDir);
    }
  }

  polycubehex::MeditMesh medit;
  const auto readStatus = polycubehex::ReadMeditFile(dataDir + "/rockerarm.mesh", medit);
  PCH_CHECK(readStatus.Ok());
  if (readStatus)
  {
    mesh.Vertices = medit.Vertices;
    mesh.Cells = medit.TetCells;
    for (int t = 0; t < mesh.Cells.rows(); ++t)
    {
      if (polycubehex::TetSignedVolume(mesh.Vertices, mesh.Cells, t) < 0.0)
      {
        std::swap(mesh.Cells(t, 0), mesh.Cells(t, 1));
      }
    }
    RunCase("rockerarm.mesh", mesh, 1, outputDir);
  }
  return PCH_TEST_RESULT();
}
