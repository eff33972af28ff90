// SPDX-License-Identifier: BSD-3-Clause
// The l1-polycube energy (9)-(13): its analytic gradient against central differences with every
// term on, and the normal difference (12) across a cut's loop, which compares the minus face's
// normal turned by the cut's transition with the plus face's normal (Fang et al. §4.2).
#include "PolycubeEnergy.h"

#include "TestAssert.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace polycubehex;

namespace
{
const int LocalFaces[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

/// Two disjoint positive tets: B (vertices 4..7) is A (0..3) turned by `rotation` and moved by
/// `offset`. Boundary faces: A's four, then B's four, in the same local order.
void TwoTets(const Eigen::Matrix3d& rotation, Points& rest, Tets& cells, Triangles& faces)
{
  Points a(4, 3);
  a << 0.0, 0.0, 0.0, 1.0, 0.1, 0.0, 0.2, 0.9, 0.1, 0.1, 0.2, 0.8;
  rest.resize(8, 3);
  rest.topRows(4) = a;
  for (int v = 0; v < 4; ++v)
  {
    rest.row(4 + v) = (rotation * a.row(v).transpose()).transpose() + Eigen::RowVector3d(3, 0, 0);
  }
  cells.resize(2, 4);
  cells << 0, 1, 2, 3, 4, 5, 6, 7;
  faces.resize(8, 3);
  for (int t = 0; t < 2; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        faces(4 * t + k, c) = cells(t, LocalFaces[k][c]);
      }
    }
  }
}

Eigen::Matrix3d QuarterTurnZ()
{
  Eigen::Matrix3d r;
  r << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return r;
}

std::vector<FacePairAcrossCut> MatchingPairs(const Eigen::Matrix3d& transition)
{
  std::vector<FacePairAcrossCut> pairs;
  for (int k = 0; k < 4; ++k)
  {
    FacePairAcrossCut pair;
    pair.MinusFace = k;
    pair.PlusFace = 4 + k;
    pair.Transition = transition;
    pairs.push_back(pair);
  }
  return pairs;
}

double Difference(const PolycubeEnergy& energy, const Eigen::VectorXd& x)
{
  PolycubeEnergyTerms terms;
  energy.Evaluate(x.data(), terms);
  return terms.Difference;
}
} // namespace

int main()
{
  Points rest;
  Tets cells;
  Triangles faces;
  TwoTets(QuarterTurnZ(), rest, cells, faces);
  Eigen::VectorXd x(24);
  for (int v = 0; v < 8; ++v)
  {
    x.segment<3>(3 * v) = rest.row(v).transpose();
  }

  // Across a cut whose transition is the turn that relates the two tets, matching faces have
  // equal transformed normals: the pairs add nothing. With the identity they add a lot.
  const PolycubeEnergy none(rest, cells, faces);
  const PolycubeEnergy turned(rest, cells, faces, MatchingPairs(QuarterTurnZ()));
  const PolycubeEnergy unturned(rest, cells, faces, MatchingPairs(Eigen::Matrix3d::Identity()));
  PolycubeEnergyWeights weights;
  weights.NormalDifference = 1.0;
  for (const PolycubeEnergy* energy : { &none, &turned, &unturned })
  {
    const_cast<PolycubeEnergy*>(energy)->SetWeights(weights);
  }
  std::cout << "difference: no pairs " << Difference(none, x) << ", turned pairs "
            << Difference(turned, x) << ", identity pairs " << Difference(unturned, x) << "\n";
  PCH_CHECK_NEAR(Difference(turned, x), Difference(none, x), 1e-14);
  PCH_CHECK(Difference(unturned, x) > Difference(none, x) + 0.1);

  // The gradient of every term together, at a deformed configuration, against central
  // differences; the Hessian assembles (the pattern holds the pairs across the cut).
  PolycubeEnergy energy(rest, cells, faces, MatchingPairs(QuarterTurnZ()));
  weights.Alignment = 0.7;
  weights.AlignmentEpsilon = 0.05;
  weights.NormalDifference = 0.9;
  weights.Area = 0.5;
  weights.Barrier = 0.3;
  weights.BarrierThreshold = 0.5;
  energy.SetWeights(weights);
  Eigen::VectorXd y = x;
  for (int i = 0; i < y.size(); ++i)
  {
    y(i) += 0.05 * std::sin(1.7 * i + 0.3);
  }
  Eigen::SparseMatrix<double> hessian = energy.Pattern().ZeroMatrix();
  auto checkGradient = [&](const char* name)
  {
    PolycubeEnergyTerms terms;
    Eigen::VectorXd gradient(y.size());
    hessian = energy.Pattern().ZeroMatrix();
    PCH_CHECK(energy.EvaluateDerivatives(y.data(), terms, gradient, &hessian));
    double worst = 0.0;
    double largest = 0.0;
    const double h = 1e-6;
    for (int i = 0; i < y.size(); ++i)
    {
      Eigen::VectorXd plus = y;
      Eigen::VectorXd minus = y;
      plus(i) += h;
      minus(i) -= h;
      PolycubeEnergyTerms tp;
      PolycubeEnergyTerms tm;
      energy.Evaluate(plus.data(), tp);
      energy.Evaluate(minus.data(), tm);
      const double numeric = (tp.Total - tm.Total) / (2.0 * h);
      worst = std::max(worst, std::abs(numeric - gradient(i)));
      largest = std::max(largest, std::abs(gradient(i)));
    }
    std::cout << name << " gradient: worst difference " << worst << " of " << largest << "\n";
    PCH_CHECK(largest > 1e-3);
    PCH_CHECK(worst < 1e-6 * std::max(1.0, largest));
  };
  checkGradient("l1 alignment:");
  // With alignment labels (the crease repair's deformation) each labelled face leaves out its
  // label's axis; -1 keeps the l1 term. Same check, and the faces of the unturned tet A, whose
  // first face (0, 1, 3) faces mostly -y, align better labelled -Y than +X.
  energy.SetAlignmentLabels({ 3, 2, 4, -1, 1, 3, 5, 0 });
  checkGradient("label alignment:");
  auto alignmentOf = [&](int label)
  {
    energy.SetAlignmentLabels({ label, -1, -1, -1, -1, -1, -1, -1 });
    PolycubeEnergyTerms t;
    energy.Evaluate(x.data(), t);
    return t.Alignment;
  };
  PCH_CHECK(alignmentOf(3) < alignmentOf(0));
  PCH_CHECK(alignmentOf(3) < alignmentOf(-1));
  energy.SetAlignmentLabels({});
  checkGradient("l1 alignment again:");
  // The Gauss-Newton Hessian is symmetric and couples the vertices of faces across the cut.
  const Eigen::MatrixXd dense = Eigen::MatrixXd(hessian);
  PCH_CHECK((dense - dense.transpose()).cwiseAbs().maxCoeff() < 1e-12);
  const Eigen::Matrix3d coupling = dense.block(0, 12, 3, 3);
  PCH_CHECK(coupling.cwiseAbs().maxCoeff() > 0.0);
  return polycubehex_test::FailureCount();
}
