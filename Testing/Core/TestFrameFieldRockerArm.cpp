// SPDX-License-Identifier: BSD-3-Clause
// The frame field on Data/rockerarm.mesh (30.8k tets, genus 1, no cuts yet), benchmark style:
// prints the time of each stage against the target (12 s on this machine), the alignment
// error, the singular edges and their depth (the issue wants every one within 3% of the
// bounding-box diagonal from the boundary). Checks the numbers that matter, not the time, which
// a loaded machine distorts; a wall time over 5x the target fails as a hang.
//
// Benchmark use: TestFrameFieldRockerArm <Data dir> <output dir> [mesh.mesh|mesh.vtk [target s]]
// runs the same on another MEDIT or legacy-VTK (ASCII unstructured grid of tets) file instead,
// e.g. the kitten with a 20 s target.
#include "FrameField.h"
#include "MeditFormat.h"
#include "TestAssert.h"
#include "TetGeometry.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <string>

using namespace polycubehex;

namespace
{
// The tets of an ASCII legacy VTK unstructured grid (cell type 10); other cells are skipped.
bool ReadLegacyVtkTets(const std::string& path, TetMesh& mesh)
{
  std::ifstream in(path);
  std::string word;
  std::vector<std::vector<int>> cells;
  while (in >> word)
  {
    if (word == "POINTS")
    {
      int n = 0;
      in >> n >> word;
      mesh.Vertices.resize(n, 3);
      for (int i = 0; i < n; ++i)
        in >> mesh.Vertices(i, 0) >> mesh.Vertices(i, 1) >> mesh.Vertices(i, 2);
    }
    else if (word == "CELLS")
    {
      int n = 0;
      int size = 0;
      in >> n >> size;
      cells.resize(n);
      for (auto& cell : cells)
      {
        int count = 0;
        in >> count;
        cell.resize(count);
        for (int& v : cell)
          in >> v;
      }
    }
    else if (word == "CELL_TYPES")
    {
      int n = 0;
      in >> n;
      std::vector<int> tets;
      for (int i = 0; i < n; ++i)
      {
        int type = 0;
        in >> type;
        if (type == 10 && cells[i].size() == 4)
          tets.push_back(i);
      }
      mesh.Cells.resize(static_cast<Eigen::Index>(tets.size()), 4);
      for (size_t t = 0; t < tets.size(); ++t)
        for (int c = 0; c < 4; ++c)
          mesh.Cells(static_cast<Eigen::Index>(t), c) = cells[tets[t]][c];
      return in.good() || in.eof();
    }
  }
  return false;
}
} // namespace

int main(int argc, char* argv[])
{
  std::string path = std::string(argc > 1 ? argv[1] : ".") + "/rockerarm.mesh";
  double target = 12.0;
  if (argc > 3)
  {
    path = argv[3];
    target = argc > 4 ? std::atof(argv[4]) : 20.0;
  }
  TetMesh mesh;
  if (path.size() > 4 && path.substr(path.size() - 4) == ".vtk")
  {
    PCH_CHECK(ReadLegacyVtkTets(path, mesh));
  }
  else
  {
    MeditMesh medit;
    const Status read = ReadMeditFile(path, medit);
    if (!read)
    {
      std::cerr << read.Message() << "\n";
      return 1;
    }
    mesh.Vertices = medit.Vertices;
    mesh.Cells = medit.TetCells;
  }
  // Some files store negatively oriented tets: VTK order is a contract of the core, so fix it
  // here (outside the timing).
  int flipped = 0;
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    if (TetSignedVolume(mesh.Vertices, mesh.Cells, t) < 0.0)
    {
      std::swap(mesh.Cells(t, 2), mesh.Cells(t, 3));
      ++flipped;
    }
  }
  std::cout << path << ": " << mesh.Vertices.rows() << " vertices, " << mesh.Cells.rows()
            << " tets (" << flipped << " re-oriented)\n";

  const FrameFieldParameters parameters;
  FrameFieldResult result;
  const std::clock_t cpuStart = std::clock();
  const auto start = std::chrono::steady_clock::now();
  const Status status = ComputeFrameField(mesh, CutFaces(), parameters, result);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  if (!status)
  {
    std::cerr << status.Message() << "\n";
    return 1;
  }
  std::cout << "time " << seconds << " s wall, " << cpu << " s CPU (target " << target
            << " s): initial field " << result.InitialFieldSeconds << ", matching "
            << result.MatchingSeconds << ", L-BFGS " << result.OptimizationSeconds << " ("
            << result.FrameIterations << " iterations"
            << (result.Converged ? "" : ", NOT converged") << "), measures "
            << result.MeasureSeconds << "\n"
            << "energy " << result.InitialFrameEnergy << " -> " << result.FrameEnergy
            << ", final |g| " << result.FinalGradientNorm << "\n"
            << "boundary alignment error " << result.InitialBoundaryAlignmentError << " -> "
            << result.BoundaryAlignmentError << " degrees\n"
            << "singular edges " << result.InitialSingularEdgeCount << " (initial) -> "
            << result.SingularEdgeCount << ", interior " << result.InteriorSingularEdgeCount
            << ", max depth " << result.MaxSingularEdgeDepth << " of the diagonal\n";
  PCH_CHECK(result.Converged);
  PCH_CHECK(result.FrameEnergy <= result.InitialFrameEnergy);
  PCH_CHECK(result.BoundaryAlignmentError < 15.0);
  PCH_CHECK(result.MaxSingularEdgeDepth <= 0.03);
  PCH_CHECK(seconds < 5.0 * target);
  return PCH_TEST_RESULT();
}
