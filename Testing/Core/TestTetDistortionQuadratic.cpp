// SPDX-License-Identifier: BSD-3-Clause
// The quadratic form of the tet distortion energy against the direct sum over the tets: the
// energy and its gradient agree at the start, near it and far from it, and the energy at the
// start is the direct sum's to the last digits (why the form is taken about the start).
#include "TetDistortionQuadratic.h"

#include "TestAssert.h"

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

using namespace polycubehex;

namespace
{
struct Problem
{
  Points Start;
  Tets Cells;
  std::vector<Eigen::Matrix<double, 4, 3>> Gradients;
  std::vector<Eigen::Matrix3d> Targets;
  std::vector<double> Weights;
};

/// `count` tets on a pool of vertices with random shape gradients, targets and weights (the
/// identities hold for any of them; a vertex shared by several tets tests the assembly).
Problem RandomProblem(int vertexCount, int count, std::mt19937& random)
{
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uniform_int_distribution<int> vertex(0, vertexCount - 1);
  Problem problem;
  problem.Start = Points::NullaryExpr(vertexCount, 3, [&]() { return 10.0 * uniform(random); });
  problem.Cells.resize(count, 4);
  for (int t = 0; t < count; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      problem.Cells(t, k) = vertex(random);
    }
    problem.Gradients.push_back(
      Eigen::Matrix<double, 4, 3>::NullaryExpr([&]() { return uniform(random); }));
    problem.Targets.push_back(Eigen::Matrix3d::NullaryExpr([&]() { return uniform(random); }));
    problem.Weights.push_back(0.5 + 0.5 * uniform(random));
  }
  return problem;
}

/// The direct sum and its gradient.
double DirectEnergy(const Problem& problem, const Points& x, Points& gradient)
{
  double energy = 0.0;
  gradient = Points::Zero(x.rows(), 3);
  for (int t = 0; t < static_cast<int>(problem.Cells.rows()); ++t)
  {
    Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 4; ++i)
    {
      jacobian += x.row(problem.Cells(t, i)).transpose() * problem.Gradients[t].row(i);
    }
    const Eigen::Matrix3d difference = jacobian - problem.Targets[t];
    energy += problem.Weights[t] * difference.squaredNorm();
    for (int i = 0; i < 4; ++i)
    {
      gradient.row(problem.Cells(t, i)) += 2.0 * problem.Weights[t] *
        (difference * problem.Gradients[t].row(i).transpose()).transpose();
    }
  }
  return energy;
}

void TestAgreesWithDirectSum()
{
  std::mt19937 random(7);
  const Problem problem = RandomProblem(30, 80, random);
  const TetDistortionQuadratic form(
    problem.Start, problem.Cells, problem.Gradients, problem.Targets, problem.Weights);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double scale : { 0.0, 1e-6, 1e-2, 1.0, 100.0 })
  {
    const Points x =
      problem.Start + scale * Points::NullaryExpr(30, 3, [&]() { return uniform(random); });
    Points direct;
    const double expected = DirectEnergy(problem, x, direct);
    Points gradient;
    const double energy = form.Evaluate(x, &gradient);
    std::cout << "displacement " << scale << ": energy " << energy << " direct " << expected
              << ", gradient difference " << (gradient - direct).cwiseAbs().maxCoeff() << std::endl;
    PCH_CHECK(std::fabs(energy - expected) <= 1e-11 * expected);
    PCH_CHECK((gradient - direct).cwiseAbs().maxCoeff() <= 1e-10 * direct.cwiseAbs().maxCoeff());
    PCH_CHECK(form.Evaluate(x) == energy); // the energy does not depend on asking for the gradient
  }
  // At the start the form returns the direct sum itself, term by term.
  Points unused;
  PCH_CHECK(form.Evaluate(problem.Start) == DirectEnergy(problem, problem.Start, unused));
}

/// Near its optimum the energy is tiny beside the terms it is the difference of (|J|^2 of every
/// tet): a map 1e-6 off targets of size 100. A step that changes the energy by a tenth of itself
/// must still come out right to 1e-3, as a line search needs; about the origin the form kept
/// only the last of sixteen digits here (checked: that version fails this test).
void TestSmallStepsAreResolved()
{
  std::mt19937 random(11);
  Problem problem = RandomProblem(30, 80, random);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  problem.Start = 100.0 * problem.Start.array() + 1000.0;
  for (size_t t = 0; t < problem.Gradients.size(); ++t)
  {
    // Shape gradients of a real tet sum to zero (a translation does not change its Jacobian).
    Eigen::Matrix<double, 4, 3>& g = problem.Gradients[t];
    g.rowwise() -= g.colwise().mean();
    Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 4; ++i)
    {
      jacobian += problem.Start.row(problem.Cells(static_cast<int>(t), i)).transpose() * g.row(i);
    }
    problem.Targets[t] =
      jacobian + 1e-6 * Eigen::Matrix3d::NullaryExpr([&]() { return uniform(random); });
  }
  const TetDistortionQuadratic form(
    problem.Start, problem.Cells, problem.Gradients, problem.Targets, problem.Weights);
  Points gradient;
  const double energy = DirectEnergy(problem, problem.Start, gradient);
  // Along -gradient, changing the energy by about a tenth of itself.
  const Points moved = problem.Start - 0.1 * energy / gradient.squaredNorm() * gradient;
  Points unused;
  const double direct = DirectEnergy(problem, moved, unused) - energy;
  const double change = form.Evaluate(moved) - form.Evaluate(problem.Start);
  std::cout << "small step: energy " << energy << " (form " << form.Evaluate(problem.Start)
            << "), change " << change << ", direct " << direct << std::endl;
  PCH_CHECK(direct < 0.0);
  PCH_CHECK(std::fabs(form.Evaluate(problem.Start) - energy) <= 1e-6 * energy);
  PCH_CHECK(std::fabs(change - direct) <= 1e-3 * std::fabs(direct));
}
} // namespace

int main()
{
  TestAgreesWithDirectSum();
  TestSmallStepsAreResolved();
  return polycubehex_test::FailureCount();
}
