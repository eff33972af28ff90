// SPDX-License-Identifier: BSD-3-Clause
// Degree-4 harmonics of frames: orthonormal basis, q(R) blind to cube symmetries and of constant
// norm, projection recovering random rotations exactly, and the boundary circle of a normal.
#include "CubeSymmetry.h"
#include "OctahedralHarmonics.h"
#include "TestAssert.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

using namespace polycubehex;

namespace
{
Eigen::Matrix3d RandomRotation(std::mt19937& rng)
{
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

// Distance between two frames up to the cube symmetries.
double FrameDistance(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  const int g = BestCubeRotation(a, b);
  return (CubeRotationMatrix(g) * a - b).cwiseAbs().maxCoeff();
}
} // namespace

int main(int, char*[])
{
  const double pi = 3.14159265358979323846;
  // Orthonormality by Monte-Carlo-free quadrature: a fine product rule in (z, phi).
  {
    Eigen::Matrix<double, 9, 9> gram = Eigen::Matrix<double, 9, 9>::Zero();
    const int nz = 200;
    const int nphi = 64;
    for (int a = 0; a < nz; ++a)
    {
      const double z = -1.0 + (a + 0.5) * 2.0 / nz; // midpoint rule in z is exact enough
      const double s = std::sqrt(1.0 - z * z);
      for (int b = 0; b < nphi; ++b)
      {
        const double phi = 2.0 * pi * b / nphi;
        const OctahedralVector y =
          EvaluateDegree4Harmonics(Eigen::Vector3d(s * std::cos(phi), s * std::sin(phi), z));
        gram += (2.0 / nz) * (2.0 * pi / nphi) * y * y.transpose();
      }
    }
    PCH_CHECK((gram - Eigen::Matrix<double, 9, 9>::Identity()).cwiseAbs().maxCoeff() < 1e-3);
  }

  std::mt19937 rng(7);
  // The addition theorem: ||q(R)||^2 = 9/(4 pi) (3 + 6 P4(0)) = 9/(4 pi) * 5.25.
  PCH_CHECK_NEAR(OctahedralNorm(), std::sqrt(9.0 / (4.0 * pi) * 5.25), 1e-12);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Eigen::Matrix3d r = RandomRotation(rng);
    const OctahedralVector q = FrameToOctahedral(r);
    PCH_CHECK_NEAR(q.norm(), OctahedralNorm(), 1e-12);
    const int g = trial % CubeRotationCount;
    PCH_CHECK((FrameToOctahedral(CubeRotationMatrix(g) * r) - q).norm() < 1e-12);

    // Projection: exact for an exact octahedral vector at any positive scale.
    double fit = 0.0;
    const Eigen::Matrix3d back = OctahedralToFrame(0.37 * q, &fit);
    PCH_CHECK(FrameDistance(back, r) < 1e-9);
    PCH_CHECK_NEAR(fit, 1.0, 1e-12);
    PCH_CHECK_NEAR(back.determinant(), 1.0, 1e-12);

    // A perturbed vector projects to a nearby frame with a fit below 1.
    OctahedralVector noise;
    std::normal_distribution<double> normal;
    for (int m = 0; m < 9; ++m)
    {
      noise(m) = normal(rng);
    }
    const Eigen::Matrix3d near = OctahedralToFrame(q + 0.05 * noise.normalized() * q.norm(), &fit);
    PCH_CHECK(FrameDistance(near, r) < 0.1);
    PCH_CHECK(fit < 1.0 && fit > 0.9);
  }
  // The average of two frames 30 degrees apart about z projects to the frame half way.
  {
    const Eigen::Matrix3d a = Eigen::AngleAxisd(0.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d b =
      Eigen::AngleAxisd(pi / 6.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d mid =
      Eigen::AngleAxisd(pi / 12.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d p = OctahedralToFrame(FrameToOctahedral(a) + FrameToOctahedral(b));
    PCH_CHECK(FrameDistance(p, mid) < 1e-9);
  }

  // The circle of frames with one axis along n.
  for (int trial = 0; trial < 20; ++trial)
  {
    const Eigen::Vector3d n = RandomRotation(rng).col(0);
    const NormalAlignedCircle circle = ComputeNormalAlignedCircle(n);
    PCH_CHECK(std::fabs(circle.U.dot(circle.V)) < 1e-12);
    PCH_CHECK(std::fabs(circle.Center.dot(circle.U)) < 1e-12);
    PCH_CHECK(std::fabs(circle.Center.dot(circle.V)) < 1e-12);
    PCH_CHECK_NEAR(circle.U.norm(), circle.V.norm(), 1e-12);
    // A frame with an axis along n, twisted arbitrarily, lies on the circle.
    Eigen::Matrix3d frame = Eigen::AngleAxisd(0.3 * trial, n).toRotationMatrix() *
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitY(), n).toRotationMatrix();
    frame.transposeInPlace(); // rows: the rotated axes, the second one is n
    const OctahedralVector q = FrameToOctahedral(frame);
    const OctahedralVector offPlane = q - circle.Center -
      circle.U * (q.dot(circle.U) / circle.U.squaredNorm()) -
      circle.V * (q.dot(circle.V) / circle.V.squaredNorm());
    PCH_CHECK(offPlane.norm() < 1e-12);
    PCH_CHECK_NEAR((q - circle.Center).norm(), circle.U.norm(), 1e-12);
  }
  return PCH_TEST_RESULT();
}
