// SPDX-License-Identifier: BSD-3-Clause
// placePaddingCopies (HexPaddingPlacement.h): on a padded grid of cubes whose inner copies were
// put in skewed places (as a distorted polycube map leaves them), the placement raises the
// padding hexes' mean scaled Jacobian and the number of valid hexes, never lowers any hex's
// minimum around a copy, moves only the inner copies, and refuses malformed padding; where the
// blends leave a poor hex, the walk off the blend segment raises the minimum; and the joint
// optimisation of the copies raises the mean of the hexes around them further, without a copy's
// hexes losing their minimum or gaining an inverted hex.
#include "HexPadding.h"
#include "HexPaddingPlacement.h"
#include "HexScaledJacobian.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

using namespace polycubehex;

namespace
{
/// The grid padded, each inner copy moved 1/3 towards the centre and then jittered.
HexMesh SkewedPaddedGrid(int n, double jitter, int& paddingHexCount)
{
  HexMesh mesh = polycubehex_test::HexCubeGrid(n);
  const int hexCount = static_cast<int>(mesh.Cells.rows());
  const Eigen::RowVector3d centre = Eigen::RowVector3d::Constant(0.5 * n);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-jitter, jitter);
  const Points before = mesh.Vertices;
  HexPaddingResult padding;
  const Status status = addPaddingLayer(
    mesh,
    [&](int v)
    {
      const Eigen::RowVector3d p = before.row(v);
      return Eigen::RowVector3d(p + (centre - p).normalized() / 3.0 +
        Eigen::RowVector3d(noise(random), noise(random), noise(random)));
    },
    padding);
  PCH_CHECK(status);
  paddingHexCount = static_cast<int>(mesh.Cells.rows()) - hexCount;
  return mesh;
}

double PaddingMean(const HexMesh& mesh, int paddingHexCount)
{
  const Eigen::VectorXd q = ComputeHexScaledJacobians(mesh);
  return q.tail(paddingHexCount).mean();
}
} // namespace

int main()
{
  int paddingHexCount = 0;
  const HexMesh skewed = SkewedPaddedGrid(4, 0.12, paddingHexCount);
  PCH_CHECK(paddingHexCount == 6 * 4 * 4);
  const Eigen::VectorXd before = ComputeHexScaledJacobians(skewed);

  HexMesh placed = skewed;
  HexPaddingPlacementResult result;
  PCH_CHECK(placePaddingCopies(placed, paddingHexCount, HexPaddingPlacementParameters(), result));
  const Eigen::VectorXd after = ComputeHexScaledJacobians(placed);
  std::cout << "padding hexes' mean SJ " << result.MeanBefore << " -> " << result.MeanAfter
            << ", min at the copies " << result.MinBefore << " -> " << result.MinAfter << ", "
            << result.MovedCount << " copies moved; mesh min " << before.minCoeff() << " -> "
            << after.minCoeff() << ", inverted " << (before.array() <= 0.0).count() << " -> "
            << (after.array() <= 0.0).count() << std::endl;

  // Better padding hexes, and no hex around a copy lost its minimum.
  PCH_CHECK_NEAR(result.MeanBefore, PaddingMean(skewed, paddingHexCount), 1e-12);
  PCH_CHECK_NEAR(result.MeanAfter, PaddingMean(placed, paddingHexCount), 1e-12);
  PCH_CHECK(result.MeanAfter > result.MeanBefore + 0.02);
  PCH_CHECK(result.MinAfter >= result.MinBefore);
  PCH_CHECK(after.minCoeff() >= before.minCoeff());
  PCH_CHECK((after.array() <= 0.0).count() <= (before.array() <= 0.0).count());
  PCH_CHECK(result.MovedCount > 0);

  // Only the inner copies (the padding hexes' top faces) moved.
  std::vector<bool> isCopy(static_cast<size_t>(placed.Vertices.rows()), false);
  const int first = static_cast<int>(placed.Cells.rows()) - paddingHexCount;
  for (int h = first; h < placed.Cells.rows(); ++h)
  {
    for (int k = 4; k < 8; ++k)
    {
      isCopy[static_cast<size_t>(placed.Cells(h, k))] = true;
    }
  }
  int movedOthers = 0;
  for (int v = 0; v < placed.Vertices.rows(); ++v)
  {
    if (!isCopy[static_cast<size_t>(v)] && placed.Vertices.row(v) != skewed.Vertices.row(v))
    {
      ++movedOthers;
    }
  }
  PCH_CHECK(movedOthers == 0);

  // A second placement from the result changes little: it starts from the same mapped points.
  {
    HexMesh again = skewed;
    HexPaddingPlacementParameters params;
    params.Sweeps = 6;
    HexPaddingPlacementResult more;
    PCH_CHECK(placePaddingCopies(again, paddingHexCount, params, more));
    PCH_CHECK(more.MeanAfter >= result.MeanAfter - 1e-3);
  }

  // The walk (after the blends) reaches places off the segment between the mapped and the
  // pushed point: with copies jittered sideways and a thin push, no blend undoes the jitter, and
  // the walk raises the smallest scaled Jacobian at the copies (towards its cap) without giving
  // up more than a little of the mean.
  {
    int count = 0;
    const HexMesh rough = SkewedPaddedGrid(4, 0.3, count);
    HexPaddingPlacementParameters blendsOnly;
    blendsOnly.Thickness = 0.05;
    blendsOnly.SearchSweeps = 0;
    blendsOnly.OptimizationIterations = 0;
    HexPaddingPlacementParameters walk = blendsOnly;
    walk.SearchSweeps = HexPaddingPlacementParameters().SearchSweeps;
    walk.SearchBelow = 0.6; // above what the blends reach here
    HexMesh withBlends = rough;
    HexMesh withWalk = rough;
    HexPaddingPlacementResult blended, walked;
    PCH_CHECK(placePaddingCopies(withBlends, count, blendsOnly, blended));
    PCH_CHECK(placePaddingCopies(withWalk, count, walk, walked));
    const Eigen::VectorXd q0 = ComputeHexScaledJacobians(rough);
    const Eigen::VectorXd q1 = ComputeHexScaledJacobians(withBlends);
    const Eigen::VectorXd q2 = ComputeHexScaledJacobians(withWalk);
    std::cout << "jittered copies, thin push: min at the copies " << walked.MinBefore << ", blends "
              << blended.MinAfter << ", walk " << walked.MinAfter << "; inverted "
              << (q0.array() <= 0.0).count() << ", " << (q1.array() <= 0.0).count() << ", "
              << (q2.array() <= 0.0).count() << "; padding mean " << blended.MeanAfter << ", "
              << walked.MeanAfter << std::endl;
    PCH_CHECK(walked.MinAfter > blended.MinAfter + 0.05);
    PCH_CHECK(q2.minCoeff() >= q1.minCoeff());
    PCH_CHECK((q2.array() <= 0.0).count() <= (q1.array() <= 0.0).count());
    PCH_CHECK(walked.MeanAfter >= blended.MeanAfter - 0.06); // 0.712 -> 0.665 here
  }

  // The joint optimisation after the search: the hexes at the copies gain in mean, no copy's
  // hexes lose their minimum or gain an inverted hex, and it reports what it kept.
  {
    int count = 0;
    const HexMesh rough = SkewedPaddedGrid(4, 0.25, count);
    HexPaddingPlacementParameters searchOnly;
    searchOnly.OptimizationIterations = 0;
    HexMesh searched = rough;
    HexMesh optimised = rough;
    HexPaddingPlacementResult r0, r1;
    PCH_CHECK(placePaddingCopies(searched, count, searchOnly, r0));
    PCH_CHECK(placePaddingCopies(optimised, count, HexPaddingPlacementParameters(), r1));
    const Eigen::VectorXd q0 = ComputeHexScaledJacobians(searched);
    const Eigen::VectorXd q1 = ComputeHexScaledJacobians(optimised);
    std::cout << "joint optimisation: mean " << q0.mean() << " -> " << q1.mean() << ", min "
              << q0.minCoeff() << " -> " << q1.minCoeff() << ", " << r1.OptimizedCount
              << " copies kept moved after " << r1.OptimizationIterations << " iterations"
              << std::endl;
    PCH_CHECK(r0.OptimizedCount == 0 && r0.OptimizationIterations == 0);
    PCH_CHECK(r1.OptimizedCount > 0 && r1.OptimizationIterations > 0);
    PCH_CHECK(q1.mean() > q0.mean() + 0.005);
    PCH_CHECK(q1.minCoeff() >= q0.minCoeff());
    PCH_CHECK((q1.array() <= 0.0).count() <= (q0.array() <= 0.0).count());
    // Per copy: the smallest scaled Jacobian of its hexes did not go down.
    std::vector<double> before(static_cast<size_t>(rough.Vertices.rows()), 2.0);
    std::vector<double> after = before;
    for (int h = 0; h < rough.Cells.rows(); ++h)
    {
      for (int k = 0; k < 8; ++k)
      {
        const size_t v = static_cast<size_t>(rough.Cells(h, k));
        before[v] = std::min(before[v], q0[h]);
        after[v] = std::min(after[v], q1[h]);
      }
    }
    int lost = 0;
    for (size_t v = 0; v < before.size(); ++v)
    {
      lost += after[v] < before[v] - 1e-12 &&
          optimised.Vertices.row(static_cast<int>(v)) != searched.Vertices.row(static_cast<int>(v))
        ? 1
        : 0;
    }
    PCH_CHECK(lost == 0);
  }

  // Without padding (0 padding hexes) nothing moves.
  {
    HexMesh grid = polycubehex_test::HexCubeGrid(2);
    const Points positions = grid.Vertices;
    HexPaddingPlacementResult none;
    PCH_CHECK(placePaddingCopies(grid, 0, HexPaddingPlacementParameters(), none));
    PCH_CHECK(none.MovedCount == 0);
    PCH_CHECK(grid.Vertices == positions);
  }

  // Malformed input is refused.
  {
    HexMesh bad = skewed;
    HexPaddingPlacementResult r;
    PCH_CHECK(!placePaddingCopies(bad, static_cast<int>(bad.Cells.rows()) + 1, {}, r));
    PCH_CHECK(!placePaddingCopies(bad, -1, {}, r));
    // Two boundary vertices claiming one inner copy.
    HexMesh shared = skewed;
    const int h = static_cast<int>(shared.Cells.rows()) - 1;
    shared.Cells(h, 5) = shared.Cells(h, 4);
    PCH_CHECK(!placePaddingCopies(shared, paddingHexCount, {}, r));
  }
  return polycubehex_test::FailureCount();
}
