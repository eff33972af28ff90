// SPDX-License-Identifier: BSD-3-Clause
// The chiral cube group: 24 distinct signed permutations with det +1, closed under products,
// identity first, inverses; best matching recovers a cube rotation applied to a frame.
#include "CubeSymmetry.h"
#include "TestAssert.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <set>
#include <vector>

using namespace polycubehex;

int main(int, char*[])
{
  // 24 distinct elements, each a signed permutation with determinant +1.
  std::set<std::vector<int>> distinct;
  for (int g = 0; g < CubeRotationCount; ++g)
  {
    const Eigen::Matrix3i& m = CubeRotation(g);
    PCH_CHECK(m.cast<double>().determinant() == 1.0);
    PCH_CHECK((m.transpose() * m) == Eigen::Matrix3i::Identity());
    PCH_CHECK(m.cwiseAbs().sum() == 3);
    PCH_CHECK(CubeRotationIndex(m) == g);
    distinct.insert(std::vector<int>(m.data(), m.data() + 9));
  }
  PCH_CHECK(distinct.size() == 24);
  PCH_CHECK(CubeRotation(0) == Eigen::Matrix3i::Identity());

  // Closed under multiplication, with the product table and inverses consistent.
  int classCount[5] = { 0, 0, 0, 0, 0 };
  for (int a = 0; a < CubeRotationCount; ++a)
  {
    for (int b = 0; b < CubeRotationCount; ++b)
    {
      const Eigen::Matrix3i product = CubeRotation(a) * CubeRotation(b);
      const int index = CubeRotationIndex(product);
      PCH_CHECK(index >= 0);
      PCH_CHECK(CubeRotationProduct(a, b) == index);
    }
    PCH_CHECK(CubeRotationProduct(a, CubeRotationInverse(a)) == 0);
    ++classCount[static_cast<int>(ClassifyCubeRotation(a))];
  }
  // The conjugacy classes of the octahedral rotation group: 1 + 6 + 3 + 8 + 6.
  PCH_CHECK(classCount[0] == 1);
  PCH_CHECK(classCount[1] == 6);
  PCH_CHECK(classCount[2] == 3);
  PCH_CHECK(classCount[3] == 8);
  PCH_CHECK(classCount[4] == 6);
  PCH_CHECK(CubeRotationIndex(Eigen::Matrix3i::Zero()) == -1);
  Eigen::Matrix3i reflection = Eigen::Matrix3i::Identity();
  reflection(0, 0) = -1;
  PCH_CHECK(CubeRotationIndex(reflection) == -1);

  // Best matching: B = Pi_g A (slightly perturbed) gives back g with a small error.
  const Eigen::Matrix3d a =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  const Eigen::Matrix3d wobble =
    Eigen::AngleAxisd(0.05, Eigen::Vector3d(0.3, -1.0, 0.2).normalized()).toRotationMatrix();
  for (int g = 0; g < CubeRotationCount; ++g)
  {
    const Eigen::Matrix3d b = CubeRotationMatrix(g) * a * wobble;
    double error = -1.0;
    PCH_CHECK(BestCubeRotation(a, b, &error) == g);
    PCH_CHECK_NEAR(error, (CubeRotationMatrix(g) * a - b).squaredNorm(), 1e-12);
    PCH_CHECK(error < 0.01);
  }
  return PCH_TEST_RESULT();
}
