// SPDX-License-Identifier: BSD-3-Clause
// The stall of the l1 polycube on fertility and elephant, small: a bumpy sphere (an icosphere
// whose radius is modulated, tetrahedralized by TetGen). The bumps make many boundary faces turn
// far, which squashes the tets under them. With the inversion barrier acting only below 10% of a
// tet's volume (BarrierThreshold), tets reach a fraction of a percent of their volume and the
// Newton steps are halved again and again to keep them positive (on the big models this froze
// the residual at 0.039 and 0.0155). With the zone widened to 0.3 (AlignmentBarrierThreshold)
// the barrier's Newton model sees them coming: far fewer shortened steps, every tet kept above
// 10% of its volume, and the residual below the tolerance. The continuation widens the zone only
// once a round is starved (StarvedHalvingsPerIteration): this sphere converges without it, so the
// default leaves its barrier at 0.1 in every round.
#include "PolycubeDeformation.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "Tetrahedralize.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace polycubehex;

namespace
{

struct Run
{
  PolycubeResult Result;
  int InfeasibleTrials = 0;
  double MinVolumeRatio = 0.0; ///< at the end of the continuation
};

/// starved: the halvings per Newton iteration that widen the barrier (0: after the first round
/// with any, a huge value: never).
Run Deform(const TetMesh& mesh, double starved)
{
  PolycubeParameters params;
  params.StarvedHalvingsPerIteration = starved;
  params.Flatten = false; // the stall is in the continuation
  Run run;
  const Status status = ComputePolycube(mesh, params, run.Result);
  PCH_CHECK(status.Ok());
  for (const PolycubeRound& round : run.Result.RoundLog)
  {
    run.InfeasibleTrials += round.InfeasibleTrials;
  }
  run.MinVolumeRatio =
    run.Result.RoundLog.empty() ? 0.0 : run.Result.RoundLog.back().MinVolumeRatio;
  std::cout << "widen above " << starved << " halvings per iteration: rounds " << run.Result.Rounds
            << ", residual " << run.Result.Residual << ", smallest volume ratio "
            << run.MinVolumeRatio << ", line-search halvings to stay positive "
            << run.InfeasibleTrials << ", " << run.Result.TotalSeconds << " s" << std::endl;
  return run;
}

} // namespace

int main(int, char*[])
{
  SurfaceMesh surface = polycubehex_test::Icosphere(3, 1.0);
  for (Eigen::Index v = 0; v < surface.Vertices.rows(); ++v)
  {
    const Eigen::RowVector3d p = surface.Vertices.row(v);
    surface.Vertices.row(v) *= 1.0 +
      0.3 * std::sin(6.0 * p(0) + 0.3) * std::sin(6.0 * p(1) + 0.7) * std::sin(6.0 * p(2) + 1.1);
  }
  TetMesh mesh;
  std::string switches;
  const Status tetrahedralized =
    Tetrahedralize(surface, TetrahedralizeParameters(), mesh, switches);
  if (!tetrahedralized.Ok() &&
    tetrahedralized.Message().find("without TetGen") != std::string::npos)
  {
    std::cout << "built without TetGen: " << tetrahedralized.Message() << std::endl;
    return PCH_TEST_RESULT();
  }
  PCH_CHECK(tetrahedralized.Ok());
  std::cout << "bumpy sphere: " << mesh.Vertices.rows() << " vertices, " << mesh.Cells.rows()
            << " tets" << std::endl;

  const Run late = Deform(mesh, 1e9);
  const Run early = Deform(mesh, 0.0);
  const Run automatic = Deform(mesh, PolycubeParameters().StarvedHalvingsPerIteration);
  PCH_CHECK(PolycubeParameters().AlignmentBarrierThreshold >= 0.3);
  // Widened after the first round, it converges with every tet well away from collapse.
  PCH_CHECK(early.Result.Converged);
  PCH_CHECK(early.Result.Residual < 1e-3);
  PCH_CHECK(early.MinVolumeRatio > 0.1);
  PCH_CHECK(early.Result.RoundLog.size() > 1 &&
    early.Result.RoundLog.back().BarrierThreshold ==
      PolycubeParameters().AlignmentBarrierThreshold);
  // The narrow barrier lets tets collapse to a fraction of a percent of their volume and
  // shortens many more steps.
  PCH_CHECK(late.MinVolumeRatio < 0.1 * early.MinVolumeRatio);
  PCH_CHECK(late.InfeasibleTrials > 2 * early.InfeasibleTrials);
  PCH_CHECK(early.Result.Rounds <= late.Result.Rounds);
  // Not starved: the default keeps the narrow barrier in every round and converges.
  PCH_CHECK(automatic.Result.Converged);
  for (const PolycubeRound& round : automatic.Result.RoundLog)
  {
    PCH_CHECK(round.BarrierThreshold == PolycubeParameters().BarrierThreshold);
  }
  return PCH_TEST_RESULT();
}
