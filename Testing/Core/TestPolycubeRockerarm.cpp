// SPDX-License-Identifier: BSD-3-Clause
// ComputePolycube (uniform guidance) on the shipped rockerarm (30.8k tets, genus 1): converged
// before flattening, no inverted tet, corners in the range of the l1 baseline (Fang et al. 2016,
// Table 1: 88), charts on their planes. Prints the timing (the acceptance target is 25 s).
// Then the closed form (cuts, frame field, polycube on the cut mesh): its charts' planes are
// read back from the positions, and only the vertices the snap released may be off them.
// Both: the per-vertex defect flags agree with the counts (rockerarm's l1 polycube has vertices
// off their planes and a squashed edge, so the flags are exercised).
#include "ClosedFormStages.h"
#include "MeditFormat.h"
#include "PolycubeDeformation.h"
#include "TestAssert.h"

#include <iostream>
#include <string>

using namespace polycubehex;

namespace
{
/// The flags of `r.VertexDefects` must say where its counts are: exactly the off-plane vertices
/// carry the off-plane flag, and a crease flag is set where (and only where) such creases exist.
void CheckDefectFlags(const PolycubeResult& r, const char* what)
{
  PCH_CHECK(static_cast<Eigen::Index>(r.VertexDefects.size()) == r.Positions.rows());
  int offPlane = 0;
  int turnedBack = 0;
  int squashed = 0;
  for (int flags : r.VertexDefects)
  {
    PCH_CHECK(flags >= 0 && flags < 8);
    offPlane += (flags & PolycubeVertexDefect::OffChartPlane) ? 1 : 0;
    turnedBack += (flags & PolycubeVertexDefect::OnTurnedBackCrease) ? 1 : 0;
    squashed += (flags & PolycubeVertexDefect::OnSquashedCrease) ? 1 : 0;
  }
  std::cout << what << ": flagged vertices off-plane " << offPlane << ", on turned-back edges "
            << turnedBack << ", on squashed edges " << squashed
            << " (counts: " << r.UnflattenedVertexCount << " off-plane, " << r.TurnedBackCreaseCount
            << " turned-back edges, " << r.SquashedCreaseCount << " squashed edges)" << std::endl;
  PCH_CHECK(offPlane == r.UnflattenedVertexCount);
  // An edge has at least two vertices.
  PCH_CHECK((turnedBack >= 2) == (r.TurnedBackCreaseCount > 0));
  PCH_CHECK((squashed >= 2) == (r.SquashedCreaseCount > 0));
  PCH_CHECK(turnedBack == 0 || r.TurnedBackCreaseCount > 0);
  PCH_CHECK(squashed == 0 || r.SquashedCreaseCount > 0);
  // Each kind of defect is also said in a warning, exactly when there is one.
  const auto warns = [&](const char* words)
  {
    for (const auto& warning : r.Warnings)
    {
      if (warning.find(words) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  };
  PCH_CHECK(warns("vertices stay off their chart planes") == (r.UnflattenedVertexCount > 0));
  PCH_CHECK(warns("run back along their axis") == (r.TurnedBackCreaseCount > 0));
  PCH_CHECK(warns("less than a quarter of their input length") == (r.SquashedCreaseCount > 0));
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string data = argc > 1 ? argv[1] : "Data";
  MeditMesh medit;
  const Status read = ReadMeditFile(data + "/rockerarm.mesh", medit);
  PCH_CHECK(read.Ok());
  if (!read)
  {
    std::cerr << read.Message() << std::endl;
    return PCH_TEST_RESULT();
  }
  TetMesh mesh;
  mesh.Vertices = medit.Vertices;
  mesh.Cells = medit.TetCells;

  PolycubeResult r;
  const Status status = ComputePolycube(mesh, PolycubeParameters(), r);
  PCH_CHECK(status.Ok());
  if (!status)
  {
    std::cerr << status.Message() << std::endl;
    return PCH_TEST_RESULT();
  }
  std::cout << "rockerarm: " << r.TotalSeconds << " s (rotation " << r.RotationSeconds
            << ", optimisation " << r.OptimizationSeconds << ", labels " << r.LabelingSeconds
            << ", flattening " << r.FlatteningSeconds << "), rounds " << r.Rounds << ", residual "
            << r.Residual << ", charts " << r.ChartCount << ", corners " << r.CornerCount
            << ", inverted " << r.InvertedTetCount << ", min volume ratio " << r.MinVolumeRatio
            << ", off-plane vertices " << r.UnflattenedVertexCount << " (max "
            << r.MaxPlaneDeviation << ")" << std::endl;
  for (const auto& warning : r.Warnings)
  {
    std::cout << "  warning: " << warning << std::endl;
  }
  PCH_CHECK(r.Converged);
  PCH_CHECK(r.Residual < 1e-3);
  PCH_CHECK(r.InvertedTetCount == 0);
  PCH_CHECK(r.CornerCount >= 8 && r.CornerCount <= 150);
  // Charts are planar to the flattening penalty's tolerance everywhere, exactly almost everywhere.
  const double diagonal =
    (mesh.Vertices.colwise().maxCoeff() - mesh.Vertices.colwise().minCoeff()).norm();
  std::cout << "released at the snap " << r.ReleasedVertexCount << ", plane deviation / diagonal "
            << r.MaxPlaneDeviation / diagonal << std::endl;
  PCH_CHECK(r.MaxPlaneDeviation < 1e-6 * diagonal);
  PCH_CHECK(r.UnflattenedVertexCount < r.Positions.rows() / 100);
  PCH_CHECK(r.UnflattenedVertexCount <= r.ReleasedVertexCount);
  CheckDefectFlags(r, "rockerarm");

  PolycubeCuts cuts;
  PolycubeResult closed;
  PCH_CHECK(polycubehex_test::ClosedForm("rockerarm", mesh, cuts, closed));
  std::cout << "rockerarm, closed form: corners " << closed.CornerCount << ", off-plane vertices "
            << closed.UnflattenedVertexCount << ", released " << closed.ReleasedVertexCount
            << ", plane deviation / diagonal " << closed.MaxPlaneDeviation / diagonal << std::endl;
  PCH_CHECK(closed.Converged);
  PCH_CHECK(closed.InvertedTetCount == 0);
  // A plane read back as the mean of its chart's coordinates moved off the exact value the
  // chart shares whenever a vertex was released: 182 vertices counted off, 10 released.
  PCH_CHECK(closed.UnflattenedVertexCount <= closed.ReleasedVertexCount);
  PCH_CHECK(closed.UnflattenedVertexCount < closed.Positions.rows() / 100);
  CheckDefectFlags(closed, "rockerarm, closed form");
  return PCH_TEST_RESULT();
}
