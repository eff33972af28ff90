// SPDX-License-Identifier: BSD-3-Clause
// Energy (1): the analytic gradient against central differences, with a cut; the cut term (3)
// vanishes for frames matched by a cube rotation, and the whole energy does not change when the
// plus side is re-expressed by a cube rotation; the minimiser reaches the gradient tolerance and
// aborts on request.
#include "CubeSymmetry.h"
#include "FrameFieldEnergy.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace polycubehex;
using polycubehex_test::CubeGrid;

namespace
{
double Centroid(const TetMesh& mesh, int t, int axis)
{
  double c = 0.0;
  for (int v = 0; v < 4; ++v)
    c += 0.25 * mesh.Vertices(mesh.Cells(t, v), axis);
  return c;
}
} // namespace

int main(int, char*[])
{
  // A 4^3 cube cut by the plane x = 0 (not a handle cut, but the energy does not care).
  TetMesh mesh = CubeGrid(4);
  mesh.Vertices.col(1) *= 1.3; // not a cube, so that no term is symmetric by accident
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, topology);
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  Tets faceCut = Tets::Constant(tetCount, 4, -1);
  Tets faceSide = Tets::Zero(tetCount, 4);
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      bool onPlane = topology.Neighbors(t, k) >= 0;
      for (int c = 0; c < 3; ++c)
        onPlane = onPlane && mesh.Vertices(mesh.Cells(t, TetFaceTable[k][c]), 0) == 0.0;
      if (onPlane)
      {
        faceCut(t, k) = 0;
        faceSide(t, k) = Centroid(mesh, t, 0) > 0.0 ? 1 : -1;
      }
    }
  }
  const FrameFieldEnergy energy(mesh, topology, faceCut, faceSide, FrameFieldEnergyWeights());
  PCH_CHECK(energy.CutFaceCount() == 32); // 16 squares of the plane, 2 triangles each
  PCH_CHECK(energy.SmoothFaceCount() > 0);
  PCH_CHECK(energy.NormalPairCount() > 0);

  // Random matrices near random rotations.
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  std::vector<double> x(static_cast<size_t>(energy.VariableCount()));
  for (int t = 0; t < tetCount; ++t)
  {
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
    for (int c = 0; c < 9; ++c)
      x[9 * t + c] = r(c / 3, c % 3) + 0.1 * normal(rng);
  }
  std::vector<double> gradient(x.size());
  energy.Evaluate(x.data(), gradient.data());
  double worst = 0.0;
  double largest = 0.0;
  for (size_t i = 0; i < x.size(); i += 7)
  {
    const double h = 1e-6;
    std::vector<double> xp = x;
    std::vector<double> xm = x;
    xp[i] += h;
    xm[i] -= h;
    const double numeric =
      (energy.Evaluate(xp.data(), nullptr) - energy.Evaluate(xm.data(), nullptr)) / (2.0 * h);
    worst = std::max(worst, std::fabs(numeric - gradient[i]));
    largest = std::max(largest, std::fabs(gradient[i]));
  }
  std::cout << "gradient: worst difference " << worst << " of " << largest << "\n";
  PCH_CHECK(worst < 1e-7 * std::max(1.0, largest / 1e-3));

  // Re-express the plus side (x > 0) by a cube rotation: smoothness, cut and orthogonality
  // terms do not change.
  FrameFieldEnergyTerms before;
  energy.Evaluate(x.data(), nullptr, &before);
  std::vector<double> turned = x;
  const Eigen::Matrix3d pi = CubeRotationMatrix(13);
  for (int t = 0; t < tetCount; ++t)
  {
    if (Centroid(mesh, t, 0) <= 0.0)
      continue;
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> r(turned.data() + 9 * t);
    r = (pi * r).eval();
  }
  FrameFieldEnergyTerms after;
  energy.Evaluate(turned.data(), nullptr, &after);
  PCH_CHECK_NEAR(after.Smoothness, before.Smoothness, 1e-12);
  PCH_CHECK_NEAR(after.Cut, before.Cut, 1e-12);
  PCH_CHECK_NEAR(after.Orthogonality, before.Orthogonality, 1e-12);
  // The l1 norm is itself cube-symmetric and (5) skips edges on the cut, so the whole energy is
  // blind to the choice of representative on one side of a cut.
  PCH_CHECK_NEAR(after.Alignment, before.Alignment, 1e-12);
  PCH_CHECK_NEAR(after.Total, before.Total, 1e-12);

  // One rotation everywhere, turned by Pi on the plus side: the cut and smoothness terms vanish.
  const Eigen::Matrix3d base =
    Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  std::vector<double> matched(x.size());
  for (int t = 0; t < tetCount; ++t)
  {
    const Eigen::Matrix3d r = Centroid(mesh, t, 0) > 0.0 ? Eigen::Matrix3d(pi * base) : base;
    for (int c = 0; c < 9; ++c)
      matched[9 * t + c] = r(c / 3, c % 3);
  }
  FrameFieldEnergyTerms terms;
  energy.Evaluate(matched.data(), nullptr, &terms);
  PCH_CHECK(terms.Cut < 1e-14);
  PCH_CHECK(terms.Smoothness < 1e-14);
  PCH_CHECK(terms.Orthogonality < 1e-14);

  // The minimiser: from the random start to a gradient below the tolerance, lower energy.
  FrameFieldMinimization summary;
  const double initial = energy.Evaluate(x.data(), nullptr);
  const Status status = MinimizeFrameFieldEnergy(energy, x, 1e-5, 5000, summary);
  PCH_CHECK(status.Ok());
  std::cout << "minimised " << initial << " -> " << summary.FinalEnergy << " in "
            << summary.Iterations << " iterations, |g| " << summary.FinalGradientNorm << "\n";
  PCH_CHECK(summary.Converged);
  PCH_CHECK(summary.FinalGradientNorm <= 1e-5);
  PCH_CHECK(summary.FinalEnergy < initial);
  PCH_CHECK_NEAR(summary.FinalEnergy, energy.Evaluate(x.data(), nullptr), 1e-15);

  // Abort through the progress callback.
  std::vector<double> y = matched;
  const Status aborted =
    MinimizeFrameFieldEnergy(energy, y, 0.0, 100, summary, [](double) { return false; });
  PCH_CHECK(!aborted.Ok());
  PCH_CHECK(y == matched);
  return PCH_TEST_RESULT();
}
