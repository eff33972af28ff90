// SPDX-License-Identifier: BSD-3-Clause
// The closed-form polycube (Fang et al. §4.1-4.2) end to end in the core: cuts (ComputeHandleCuts),
// the frame field with its transitions (ComputeFrameField), then ComputePolycube on the cut mesh
// with x_plus = Pi x_minus + t hard. A torus and a square ring twisted by a quarter turn (the
// paper's Figure 14) both become polycubes with no corner, which no uncut polycube can be (at
// least 16 on a torus).
#include "ClosedFormStages.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"

#include <Eigen/Geometry>

#include <iostream>

using namespace polycubehex;
using polycubehex_test::ClosedForm;

namespace
{
/// The properties every closed-form polycube must have.
void CheckPolycube(const TetMesh& mesh, const PolycubeCuts& cuts, const PolycubeResult& out)
{
  const double diagonal =
    (mesh.Vertices.colwise().maxCoeff() - mesh.Vertices.colwise().minCoeff()).norm();
  PCH_CHECK(out.Converged);
  PCH_CHECK(out.InvertedTetCount == 0 && out.MinVolumeRatio > 0.0);
  PCH_CHECK(out.MaxPlaneDeviation < 1e-9 * diagonal);
  PCH_CHECK(out.CornerCount == 0);
  PCH_CHECK(out.CutTranslations.rows() == cuts.Count());
  // The output is the cut mesh: more vertices than the input, each copying an input vertex.
  PCH_CHECK(out.Positions.rows() > mesh.Vertices.rows());
  // Every pair of copies across a cut face satisfies x_plus = Pi x_minus + t exactly: tets on
  // both sides of a cut face hold copies of the same input vertices.
  double worst = 0.0;
  int pairs = 0;
  for (Eigen::Index t = 0; t < out.Cells.rows(); ++t)
  {
    const int parent = out.OriginalCellId[static_cast<size_t>(t)];
    for (int k = 0; k < 4; ++k)
    {
      if (cuts.FaceCut(parent, k) < 0 || cuts.FaceSide(parent, k) > 0 || parent != t)
      {
        continue; // the minus side of a cut face of an unsplit tet
      }
      const int cut = cuts.FaceCut(parent, k);
      const Eigen::Matrix3d pi = cuts.Transitions[static_cast<size_t>(cut)].cast<double>();
      for (int i = 0; i < 3; ++i)
      {
        const int minus = out.Cells(t, TetFaceTable[k][i]);
        const int input = out.OriginalPointId[static_cast<size_t>(minus)];
        for (Eigen::Index v = 0; v < out.Positions.rows(); ++v)
        {
          if (v != minus && out.OriginalPointId[static_cast<size_t>(v)] == input)
          {
            const Eigen::Vector3d image = pi * out.Positions.row(minus).transpose() +
              out.CutTranslations.row(cut).transpose();
            worst = std::max(worst, (out.Positions.row(v).transpose() - image).norm());
            ++pairs;
          }
        }
      }
    }
  }
  std::cout << "  " << pairs << " copy pairs checked, worst |x+ - (Pi x- + t)| " << worst << "\n";
  PCH_CHECK(pairs > 0);
  PCH_CHECK(worst < 1e-9 * diagonal);
}
} // namespace

int main(int, char*[])
{
  // A solid torus: one cut, identity transition; the polycube is a straight square bar whose
  // ends are glued by the translation t along it.
  {
    const TetMesh mesh = polycubehex_test::SweptTorus(2.0, 0.8, 0, 3, 24);
    PolycubeCuts cuts;
    PolycubeResult out;
    PCH_CHECK(ClosedForm("torus", mesh, cuts, out));
    PCH_CHECK(cuts.Count() == 1);
    if (out.CutTranslations.rows() == 1)
    {
      PCH_CHECK(cuts.Transitions[0] == Eigen::Matrix3i::Identity());
      PCH_CHECK(out.ChartCount == 4);
      // The bar is about as long as the torus's core circle (2 pi R = 12.6).
      const double length = out.CutTranslations.row(0).norm();
      PCH_CHECK(length > 8.0 && length < 16.0);
      CheckPolycube(mesh, cuts, out);
    }
  }

  // A square ring whose section turns by a quarter once around: one cut whose transition is a
  // quarter turn about the ring's direction; the four sides are one face that runs four times
  // around, so the polycube is again a bar without corners, its ends glued by a quarter turn.
  {
    const TetMesh mesh = polycubehex_test::TwistedSquareRing();
    PolycubeCuts cuts;
    PolycubeResult out;
    PCH_CHECK(ClosedForm("twisted square ring", mesh, cuts, out));
    PCH_CHECK(cuts.Count() == 1);
    if (out.CutTranslations.rows() == 1)
    {
      PCH_CHECK(cuts.Transitions[0] != Eigen::Matrix3i::Identity());
      CheckPolycube(mesh, cuts, out);
    }
  }

  // Refusals: cuts without frames, and cut arrays that do not describe cut faces.
  {
    const TetMesh mesh = polycubehex_test::SweptTorus(2.0, 0.8, 0, 2, 12);
    PolycubeCuts cuts;
    cuts.FaceCut.setConstant(mesh.Cells.rows(), 4, -1);
    cuts.FaceSide.setZero(mesh.Cells.rows(), 4);
    cuts.Transitions.push_back(Eigen::Matrix3i::Identity());
    PolycubeResult out;
    Status status = ComputePolycube(mesh, PolycubeParameters(), out, {}, {}, &cuts);
    std::cout << "refused: " << status.Message() << "\n";
    PCH_CHECK(!status.Ok());
    std::vector<Eigen::Matrix3d> frames(static_cast<size_t>(mesh.Cells.rows()), Eigen::Matrix3d::Identity());
    cuts.FaceCut(0, 0) = 0; // one side only
    cuts.FaceSide(0, 0) = -1;
    status = ComputePolycube(mesh, PolycubeParameters(), out, {}, frames, &cuts);
    std::cout << "refused: " << status.Message() << "\n";
    PCH_CHECK(!status.Ok());
  }
  return PCH_TEST_RESULT();
}
