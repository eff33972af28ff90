// SPDX-License-Identifier: BSD-3-Clause
// The frame field of Fang et al. 2016 §3 on meshes generated here: a rotated cube (every frame
// aligned with the faces, no singular edge), a cylinder and a round torus (aligned within 10
// degrees, singular edges reported with their depth), the torus cut open (identity transition),
// a square torus twisted by a quarter turn and cut (a quarter-turn transition about the tangent),
// and refusals of bad input.
#include "CubeSymmetry.h"
#include "FrameField.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

using namespace polycubehex;
using polycubehex_test::CubeGrid;
using polycubehex_test::MakeDisk;
using polycubehex_test::MakeSquare;
using polycubehex_test::Planar;
using polycubehex_test::Sweep;

namespace
{
const double Pi = 3.14159265358979323846;

// The faces between the last layer and layer 0 of a periodic sweep as one cut: minus side in
// the last layer, plus side in layer 0.
CutFaces SeamCut(const TetMesh& mesh, int nv, int trianglesPerLayer, int layers)
{
  CutFaces cuts;
  cuts.Ids.setConstant(mesh.Cells.rows(), 4, -1);
  cuts.Sides.setZero(mesh.Cells.rows(), 4);
  for (int t = 0; t < mesh.Cells.rows(); ++t)
  {
    const int layer = t / (3 * trianglesPerLayer);
    if (layer != 0 && layer != layers - 1)
    {
      continue;
    }
    for (int k = 0; k < 4; ++k)
    {
      bool onSeam = true;
      for (int c = 0; c < 3; ++c)
      {
        onSeam = onSeam && mesh.Cells(t, TetFaceTable[k][c]) < nv;
      }
      if (onSeam)
      {
        cuts.Ids(t, k) = 0;
        cuts.Sides(t, k) = layer == 0 ? 1 : -1;
      }
    }
  }
  return cuts;
}

bool Run(const char* name,
  const TetMesh& mesh,
  const CutFaces& cuts,
  const FrameFieldParameters& parameters,
  FrameFieldResult& result)
{
  const auto start = std::chrono::steady_clock::now();
  const Status status = ComputeFrameField(mesh, cuts, parameters, result);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!status)
  {
    std::cerr << name << ": " << status.Message() << "\n";
    return false;
  }
  std::cout << name << ": " << mesh.Cells.rows() << " tets, " << seconds << " s (initial "
            << result.InitialFieldSeconds << " s, L-BFGS " << result.OptimizationSeconds << " s, "
            << result.FrameIterations << " iterations"
            << (result.Converged ? "" : ", not converged") << "), energy "
            << result.InitialFrameEnergy << " -> " << result.FrameEnergy << ", |g| "
            << result.FinalGradientNorm << "\n  alignment error "
            << result.InitialBoundaryAlignmentError << " -> " << result.BoundaryAlignmentError
            << " deg, singular edges " << result.InitialSingularEdgeCount << " -> "
            << result.SingularEdgeCount << " (interior " << result.InteriorSingularEdgeCount
            << ", max depth " << result.MaxSingularEdgeDepth << " of the diagonal)\n";
  return true;
}

Eigen::Matrix3d FrameOf(const FrameFieldResult& result, int t)
{
  Eigen::Matrix3d r;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      r(a, b) = result.Frames(t, 3 * a + b);
  return r;
}
} // namespace

int main(int, char*[])
{
  const FrameFieldParameters parameters;

  // A cube rotated by 30 degrees about a skew axis. The initial field and the optimised field
  // (paper weights) are exactly the cube's axes: every term's gradient is then a stretch along
  // the axes, which the polar decomposition removes. That holds because (5) skips the cube's
  // sharp edges (NormalDifferenceMaxAngle 45); summed over them as the paper does, (5) pulls the
  // frames at each edge towards each other against the smoothed l1 term, whose slope vanishes at
  // exact alignment, and they settle about 0.1 degree off (measured 1.6e-3).
  {
    TetMesh mesh = CubeGrid(6);
    const Eigen::Matrix3d q =
      Eigen::AngleAxisd(Pi / 6.0, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
    mesh.Vertices = (mesh.Vertices * q.transpose()).eval(); // x' = Q x
    mesh.Vertices.rowwise() += Eigen::RowVector3d(5.0, -2.0, 1.0);
    // The rotated face normals are the columns of Q, so frames should be Pi Q^T.
    auto deviation = [&q](const Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>& frames)
    {
      double worst = 0.0;
      for (int t = 0; t < frames.rows(); ++t)
      {
        Eigen::Matrix3d r;
        for (int a = 0; a < 9; ++a)
          r(a / 3, a % 3) = frames(t, a);
        const int g = BestCubeRotation(r, q.transpose());
        worst = std::max(worst, (CubeRotationMatrix(g) * r - q.transpose()).cwiseAbs().maxCoeff());
      }
      return worst;
    };
    FrameFieldResult result;
    PCH_CHECK(Run("rotated cube, paper weights", mesh, CutFaces(), parameters, result));
    std::cout << "  worst deviation from the cube's axes: initial "
              << deviation(result.InitialFrames) << ", final " << deviation(result.Frames) << "\n";
    PCH_CHECK(deviation(result.InitialFrames) < 1e-6);
    PCH_CHECK(deviation(result.Frames) < 1e-6);
    PCH_CHECK(result.SingularEdgeCount == 0);
    PCH_CHECK(result.BoundaryAlignmentError < 1e-4);
    PCH_CHECK(result.CutTransitions.rows() == 0);
    for (int t = 0; t < result.Frames.rows(); ++t)
    {
      PCH_CHECK_NEAR(FrameOf(result, t).determinant(), 1.0, 1e-9);
    }

    FrameFieldParameters everyEdge = parameters;
    everyEdge.NormalDifferenceMaxAngle = 180.0;
    PCH_CHECK(Run("rotated cube, (5) over every edge", mesh, CutFaces(), everyEdge, result));
    std::cout << "  worst deviation from the cube's axes: initial "
              << deviation(result.InitialFrames) << ", final " << deviation(result.Frames) << "\n";
    PCH_CHECK(deviation(result.InitialFrames) < 1e-6);
    PCH_CHECK(deviation(result.Frames) > 1e-4); // the pull the threshold removes
    PCH_CHECK(deviation(result.Frames) < 5e-3);
    PCH_CHECK(result.SingularEdgeCount == 0);
    PCH_CHECK(result.BoundaryAlignmentError < 0.1);
  }

  // A cylinder: radius 1, height 2.
  {
    const Planar disk = MakeDisk(6);
    const TetMesh mesh = Sweep(disk,
      12,
      false,
      {},
      [](int l, const Eigen::Vector2d& p) { return Eigen::Vector3d(p(0), p(1), 2.0 * l / 12.0); });
    FrameFieldResult result;
    PCH_CHECK(Run("cylinder", mesh, CutFaces(), parameters, result));
    PCH_CHECK(result.BoundaryAlignmentError < 10.0);
    PCH_CHECK(result.Frames.rows() == mesh.Cells.rows());
    for (const SingularEdge& edge : result.SingularEdges)
    {
      PCH_CHECK(edge.Holonomy != 0 && edge.Depth >= 0.0 && edge.Depth < 0.5);
    }
    // Deterministic: a second run gives the same frames bit for bit.
    FrameFieldResult again;
    PCH_CHECK(ComputeFrameField(mesh, CutFaces(), parameters, again).Ok());
    PCH_CHECK(again.Frames == result.Frames);
    // Abort through the progress callback.
    double reached = 0.0;
    const Status aborted = ComputeFrameField(mesh,
      CutFaces(),
      parameters,
      again,
      [&](double f)
      {
        reached = std::max(reached, f);
        return f < 0.4;
      });
    PCH_CHECK(!aborted.Ok());
    PCH_CHECK(reached >= 0.4 && reached < 0.9); // stopped inside L-BFGS
  }

  // A round torus, R = 2, r = 0.7, without and with a cut across the tube.
  {
    const Planar disk = MakeDisk(5);
    const int layers = 36;
    auto place = [layers](int l, const Eigen::Vector2d& p)
    {
      const double theta = 2.0 * Pi * l / layers;
      const double rho = 2.0 + 0.7 * p(0);
      return Eigen::Vector3d(rho * std::cos(theta), rho * std::sin(theta), 0.7 * p(1));
    };
    const TetMesh mesh = Sweep(disk, layers, true, {}, place);
    FrameFieldResult result;
    PCH_CHECK(Run("torus", mesh, CutFaces(), parameters, result));
    PCH_CHECK(result.BoundaryAlignmentError < 10.0);
    // Without cuts only BoundaryAlignmentWeight runs.
    PCH_CHECK(result.AlignedSingularEdgeCount == -1);
    PCH_CHECK(result.InitialAlignmentWeight == parameters.BoundaryAlignmentWeight);
    PCH_CHECK(result.DiscardedSeconds == 0.0);

    const CutFaces cuts = SeamCut(
      mesh, static_cast<int>(disk.Points.size()), static_cast<int>(disk.Triangles.size()), layers);
    PCH_CHECK(Run("torus with a cut", mesh, cuts, parameters, result));
    PCH_CHECK(result.BoundaryAlignmentError < 10.0);
    PCH_CHECK(result.CutTransitions.rows() == 1);
    if (result.CutTransitions.rows() == 1)
    {
      Eigen::Matrix3i pi;
      for (int a = 0; a < 9; ++a)
        pi(a / 3, a % 3) = result.CutTransitions(0, a);
      std::cout << "  transition\n" << pi << "\n";
      PCH_CHECK(pi == Eigen::Matrix3i::Identity());
    }
    // With a cut the tightly aligned field runs first; without singular edges it is kept, and
    // no fallback runs.
    std::cout << "  aligned attempt: " << result.AlignedSingularEdgeCount
              << " singular edges; kept weight " << result.InitialAlignmentWeight << "\n";
    PCH_CHECK(result.AlignedSingularEdgeCount == 0);
    PCH_CHECK(result.InitialAlignmentWeight == parameters.CutMeshBoundaryAlignmentWeight);
    PCH_CHECK(result.DiscardedSeconds == 0.0);

    // Turned off, the cut torus uses BoundaryAlignmentWeight alone.
    FrameFieldParameters straight = parameters;
    straight.CutMeshBoundaryAlignmentWeight = 0.0;
    FrameFieldResult plain;
    PCH_CHECK(Run("torus with a cut, no aligned attempt", mesh, cuts, straight, plain));
    PCH_CHECK(plain.AlignedSingularEdgeCount == -1);
    PCH_CHECK(plain.InitialAlignmentWeight == parameters.BoundaryAlignmentWeight);
    // (The fallback itself is tested on kitten, whose aligned field keeps singular lines:
    // TestClosedFormCorners.)
  }

  // A square torus whose section turns by a quarter turn once around, cut across the tube.
  {
    std::vector<int> quarter;
    const Planar square = MakeSquare(4, quarter);
    const int layers = 40;
    auto place = [layers](int l, const Eigen::Vector2d& p)
    {
      const double theta = 2.0 * Pi * l / layers;
      const double twist = 0.5 * Pi * l / layers;
      const Eigen::Vector2d s = Eigen::Rotation2Dd(twist) * p;
      const double rho = 2.5 + 0.6 * s(0);
      return Eigen::Vector3d(rho * std::cos(theta), rho * std::sin(theta), 0.6 * s(1));
    };
    // Layer `layers` is layer 0 turned by a quarter: point v lands where quarter[v] is.
    const TetMesh mesh = Sweep(square, layers, true, quarter, place);
    const CutFaces cuts = SeamCut(mesh,
      static_cast<int>(square.Points.size()),
      static_cast<int>(square.Triangles.size()),
      layers);
    FrameFieldResult result;
    PCH_CHECK(Run("twisted square torus with a cut", mesh, cuts, parameters, result));
    PCH_CHECK(result.BoundaryAlignmentError < 10.0);
    PCH_CHECK(result.CutTransitions.rows() == 1);
    if (result.CutTransitions.rows() == 1)
    {
      Eigen::Matrix3i pi;
      for (int a = 0; a < 9; ++a)
        pi(a / 3, a % 3) = result.CutTransitions(0, a);
      std::cout << "  transition\n" << pi << "\n";
      const int index = CubeRotationIndex(pi);
      PCH_CHECK(index >= 0 && ClassifyCubeRotation(index) == CubeRotationClass::QuarterTurn);
      // Its axis is the frame axis along the tube's tangent at the seam, +-y there.
      int axis = -1;
      for (int a = 0; a < 3; ++a)
        if (pi(a, a) == 1)
          axis = a;
      double along = 0.0;
      for (int t = 0; t < mesh.Cells.rows(); ++t)
        if (cuts.Ids.row(t).maxCoeff() >= 0 && axis >= 0)
          along = std::max(along, std::fabs(FrameOf(result, t)(axis, 1)));
      PCH_CHECK(along > 0.95);
    }
  }

  // Refusals: inconsistent cut sides, an inverted tet.
  {
    TetMesh mesh = CubeGrid(2);
    FrameFieldResult result;
    CutFaces cuts;
    cuts.Ids.setConstant(mesh.Cells.rows(), 4, -1);
    cuts.Sides.setZero(mesh.Cells.rows(), 4);
    TetTopology topology;
    ComputeTetTopology(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, topology);
    for (int k = 0; k < 4; ++k)
    {
      if (topology.Neighbors(0, k) >= 0)
      {
        cuts.Ids(0, k) = 0;
        cuts.Sides(0, k) = -1; // the tet across it is left uncut
        break;
      }
    }
    Status status = ComputeFrameField(mesh, cuts, parameters, result);
    std::cout << "refused: " << status.Message() << "\n";
    PCH_CHECK(!status);
    std::swap(mesh.Cells(3, 0), mesh.Cells(3, 1));
    status = ComputeFrameField(mesh, CutFaces(), parameters, result);
    std::cout << "refused: " << status.Message() << "\n";
    PCH_CHECK(!status);
  }
  return PCH_TEST_RESULT();
}
