// SPDX-License-Identifier: BSD-3-Clause
// Hard coordinate relations (CoordinateRelations): copies across a cut with a rotation and an
// unknown translation, a chart plane closing a loop (an equation on the translation), a half
// turn (a coordinate fixed by the translation), fixed values, and contradictions.
#include "CoordinateRelations.h"
#include "TestAssert.h"

#include <Eigen/Core>

#include <iostream>

using namespace polycubehex;

namespace
{
/// Relates vertex `plus` to vertex `minus` by x_plus = pi x_minus + t (t = extras 3c..3c+2).
void Transition(CoordinateRelations& relations, int minus, int plus, const Eigen::Matrix3i& pi, int cut)
{
  for (int a = 0; a < 3; ++a)
  {
    for (int b = 0; b < 3; ++b)
    {
      if (pi(a, b) != 0)
      {
        relations.Relate(3 * plus + a, 3 * minus + b, pi(a, b), { { 3 * cut + a, 1.0 } });
      }
    }
  }
}

Eigen::Vector3d Vertex(const Eigen::VectorXd& x, int v)
{
  return x.segment<3>(3 * v);
}
} // namespace

int main(int, char*[])
{
  Eigen::Matrix3i quarter; // a quarter turn about z: x -> y
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;

  // No relation: one variable per coordinate, x = y.
  {
    CoordinateRelations relations(4, 0, {});
    VariableReduction reduction;
    PCH_CHECK(relations.Build(reduction).Ok());
    PCH_CHECK(reduction.VariableCount() == 12);
    const Eigen::VectorXd y = Eigen::VectorXd::Random(12);
    PCH_CHECK((reduction.Expand(y) - y).norm() < 1e-15);
  }

  // A copy across a cut: x_1 = Pi x_0 + t, t free. Variables: vertex 0, vertex 2, and t.
  {
    CoordinateRelations relations(3, 3, { 0, 1, 2 });
    Transition(relations, 0, 1, quarter, 0);
    VariableReduction reduction;
    PCH_CHECK(relations.Build(reduction).Ok());
    PCH_CHECK(reduction.VariableCount() == 9);
    PCH_CHECK(reduction.B.nonZeros() == 12); // one per coordinate, plus t in vertex 1's three
    const Eigen::VectorXd y = Eigen::VectorXd::Random(9);
    const Eigen::VectorXd x = reduction.Expand(y);
    const Eigen::Vector3d t = relations.Extras(y);
    PCH_CHECK((Vertex(x, 1) - (quarter.cast<double>() * Vertex(x, 0) + t)).norm() < 1e-14);
    // Restrict recovers the variables of an x that satisfies the relations.
    PCH_CHECK((reduction.Expand(reduction.Restrict(x)) - x).norm() < 1e-12);
  }

  // A chart plane that crosses the cut: x_0 and x_1 (its copy) and x_2 on one plane z = const,
  // and x_2 also on it: the plane forces t_z = 0, t_x and t_y stay free.
  {
    CoordinateRelations relations(3, 3, { 0, 1, 2 });
    Transition(relations, 0, 1, Eigen::Matrix3i::Identity(), 0);
    relations.Relate(3 * 2 + 2, 3 * 0 + 2, 1.0);
    relations.Relate(3 * 2 + 2, 3 * 1 + 2, 1.0);
    VariableReduction reduction;
    PCH_CHECK(relations.Build(reduction).Ok());
    PCH_CHECK(relations.ClosedLoopCount() == 1);
    const Eigen::VectorXd y = Eigen::VectorXd::Random(reduction.VariableCount());
    const Eigen::VectorXd x = reduction.Expand(y);
    const Eigen::Vector3d t = relations.Extras(y);
    PCH_CHECK(std::abs(t(2)) < 1e-15);
    PCH_CHECK(std::abs(t(0)) > 0.0 && std::abs(t(1)) > 0.0);
    PCH_CHECK((Vertex(x, 1) - (Vertex(x, 0) + t)).norm() < 1e-14);
    PCH_CHECK(std::abs(x(8) - x(2)) < 1e-15 && std::abs(x(8) - x(5)) < 1e-15);
  }

  // A half turn about z with a plane x = const through both copies: x_1 = -x_0 + t_x and
  // x_1 = x_0 give x_0 = t_x / 2.
  {
    Eigen::Matrix3i half;
    half << -1, 0, 0, 0, -1, 0, 0, 0, 1;
    CoordinateRelations relations(2, 3, { 0, 1, 2 });
    Transition(relations, 0, 1, half, 0);
    relations.Relate(3 * 1 + 0, 3 * 0 + 0, 1.0);
    VariableReduction reduction;
    PCH_CHECK(relations.Build(reduction).Ok());
    const Eigen::VectorXd y = Eigen::VectorXd::Random(reduction.VariableCount());
    const Eigen::VectorXd x = reduction.Expand(y);
    const Eigen::Vector3d t = relations.Extras(y);
    PCH_CHECK(std::abs(x(0) - 0.5 * t(0)) < 1e-14 && std::abs(x(3) - x(0)) < 1e-14);
    PCH_CHECK((Vertex(x, 1) - (half.cast<double>() * Vertex(x, 0) + t)).norm() < 1e-14);
  }

  // Fixed values travel through the relations: x_0 = 2 and x_1 = x_0 + t with x_1 = 5: t = 3.
  {
    CoordinateRelations relations(2, 3, { 0, 1, 2 });
    Transition(relations, 0, 1, Eigen::Matrix3i::Identity(), 0);
    relations.Fix(0, 2.0);
    relations.Fix(3, 5.0);
    VariableReduction reduction;
    PCH_CHECK(relations.Build(reduction).Ok());
    const Eigen::VectorXd y = Eigen::VectorXd::Random(reduction.VariableCount());
    const Eigen::VectorXd x = reduction.Expand(y);
    PCH_CHECK(std::abs(x(0) - 2.0) < 1e-14 && std::abs(x(3) - 5.0) < 1e-14);
    PCH_CHECK(std::abs(relations.Extras(y)(0) - 3.0) < 1e-14);
  }

  // Contradictions are refused with a message: two values for one coordinate.
  {
    CoordinateRelations relations(2, 0, {});
    relations.Relate(0, 3, 1.0);
    relations.Fix(0, 1.0);
    relations.Fix(3, 2.0);
    VariableReduction reduction;
    const Status status = relations.Build(reduction);
    PCH_CHECK(!status.Ok());
    std::cout << "refused: " << status.Message() << "\n";
    PCH_CHECK(!relations.Relate(0, 6, 1.0)); // out of range
  }
  return PCH_TEST_RESULT();
}
