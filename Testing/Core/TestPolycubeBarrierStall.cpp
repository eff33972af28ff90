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

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

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
  PCH_CHECK(!automatic.Result.Retried);
  PCH_CHECK(automatic.Result.StarvedHalvingsPerIteration ==
    PolycubeParameters().StarvedHalvingsPerIteration);

  // The retry (SquashedRetryStretch): forced here by a bound every stretch is below, it runs
  // the other starvation setting and keeps the result with the larger smallest stretch (then
  // fewer vertices off their planes), as the two settings give when run alone.
  PolycubeParameters alone;
  alone.Flatten = false;
  alone.SquashedRetryStretch = 0.0;
  alone.StarvedHalvingsPerIteration = 1e9; // never widens
  PolycubeResult narrow;
  PCH_CHECK(ComputePolycube(mesh, alone, narrow).Ok());
  alone.StarvedHalvingsPerIteration = 0.0; // widens after the first round
  PolycubeResult wide;
  PCH_CHECK(ComputePolycube(mesh, alone, wide).Ok());
  PCH_CHECK(!narrow.Retried && !wide.Retried);
  PolycubeParameters retried = alone;
  retried.StarvedHalvingsPerIteration = 1e9;
  retried.FrameGuidedStarvedHalvingsPerIteration = 0.0; // the other setting of the retry
  retried.SquashedRetryStretch = 2.0;                   // every stretch is at most 1
  std::vector<double> reported;
  PolycubeResult kept;
  PCH_CHECK(ComputePolycube(mesh,
    retried,
    kept,
    [&reported](double f)
    {
      reported.push_back(f);
      return true;
    }).Ok());
  PCH_CHECK(kept.Retried);
  const bool wideBetter = wide.MinCreaseStretch > narrow.MinCreaseStretch ||
    (wide.MinCreaseStretch == narrow.MinCreaseStretch &&
      wide.UnflattenedVertexCount < narrow.UnflattenedVertexCount);
  const PolycubeResult& expected = wideBetter ? wide : narrow;
  std::cout << "retry: stretch " << narrow.MinCreaseStretch << " (never widened) and "
            << wide.MinCreaseStretch << " (widened), kept " << kept.MinCreaseStretch
            << " with starvation setting " << kept.StarvedHalvingsPerIteration << std::endl;
  PCH_CHECK(kept.StarvedHalvingsPerIteration == (wideBetter ? 0.0 : 1e9));
  PCH_CHECK(kept.MinCreaseStretch == expected.MinCreaseStretch);
  PCH_CHECK(kept.Rounds == expected.Rounds);
  PCH_CHECK(kept.Positions.rows() == expected.Positions.rows() &&
    (kept.Positions - expected.Positions).cwiseAbs().maxCoeff() == 0.0);
  // Progress never goes back, and ends at 1.
  PCH_CHECK(!reported.empty() && reported.back() == 1.0);
  PCH_CHECK(std::is_sorted(reported.begin(), reported.end()));
  // An abort during the retry is an abort, not a fallback to the first result.
  PolycubeResult aborted;
  const Status stopped = ComputePolycube(mesh, retried, aborted, [](double f) { return f < 0.8; });
  PCH_CHECK(!stopped.Ok() && stopped.Message().find("aborted") != std::string::npos);
  return PCH_TEST_RESULT();
}
