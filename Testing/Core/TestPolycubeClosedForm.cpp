// SPDX-License-Identifier: BSD-3-Clause
// The closed-form polycube (Fang et al. §4.1-4.2) end to end in the core: cuts (ComputeHandleCuts),
// the frame field with its transitions (ComputeFrameField), then ComputePolycube on the cut mesh
// with x_plus = Pi x_minus + t hard. A torus and a square ring twisted by a quarter turn (the
// paper's Figure 14) both become polycubes with no corner, which no uncut polycube can be (at
// least 16 on a torus).
#include "FrameField.h"
#include "HandleCuts.h"
#include "PolycubeDeformation.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"

#include <Eigen/Geometry>

#include <iostream>

using namespace polycubehex;

namespace
{
/// Runs the three stages; returns false (with a message) when one refuses.
bool ClosedForm(const char* name, const TetMesh& mesh, PolycubeCuts& cuts, PolycubeResult& out)
{
  HandleCutResult handles;
  Status status = ComputeHandleCuts(mesh, HandleCutParameters(), handles);
  if (!status)
  {
    std::cout << name << ": cuts refused: " << status.Message() << "\n";
    return false;
  }
  CutFaces cutFaces;
  cutFaces.Ids = handles.CutFaces;
  cutFaces.Sides = handles.CutSide;
  FrameFieldResult field;
  status = ComputeFrameField(mesh, cutFaces, FrameFieldParameters(), field);
  if (!status)
  {
    std::cout << name << ": frame field refused: " << status.Message() << "\n";
    return false;
  }
  std::vector<Eigen::Matrix3d> frames(static_cast<size_t>(mesh.Cells.rows()));
  for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
  {
    for (int a = 0; a < 9; ++a)
    {
      frames[static_cast<size_t>(t)](a / 3, a % 3) = field.Frames(t, a);
    }
  }
  cuts.FaceCut = handles.CutFaces;
  cuts.FaceSide = handles.CutSide;
  cuts.Transitions.clear();
  for (Eigen::Index c = 0; c < field.CutTransitions.rows(); ++c)
  {
    Eigen::Matrix3i pi;
    for (int a = 0; a < 9; ++a)
    {
      pi(a / 3, a % 3) = field.CutTransitions(c, a);
    }
    cuts.Transitions.push_back(pi);
  }
  status = ComputePolycube(mesh, PolycubeParameters(), out, {}, frames, &cuts);
  if (!status)
  {
    std::cout << name << ": polycube refused: " << status.Message() << "\n";
    return false;
  }
  std::cout << name << ": " << mesh.Cells.rows() << " tets, " << cuts.Count() << " cut(s), "
            << out.CornerCount << " corners, " << out.ChartCount << " charts, residual "
            << out.Residual << ", plane deviation " << out.MaxPlaneDeviation << ", "
            << out.InvertedTetCount << " inverted, min volume ratio " << out.MinVolumeRatio
            << ", t = " << out.CutTranslations << "\n";
  for (const std::string& warning : out.Warnings)
  {
    std::cout << "  warning: " << warning << "\n";
  }
  return true;
}

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
    std::vector<int> quarter;
    const polycubehex_test::Planar square = polycubehex_test::MakeSquare(4, quarter);
    const int layers = 40;
    auto place = [layers](int l, const Eigen::Vector2d& p)
    {
      const double theta = 2.0 * polycubehex_test::Pi * l / layers;
      const double twist = 0.5 * polycubehex_test::Pi * l / layers;
      const Eigen::Vector2d s = Eigen::Rotation2Dd(twist) * p;
      const double rho = 2.5 + 0.6 * s(0);
      return Eigen::Vector3d(rho * std::cos(theta), rho * std::sin(theta), 0.6 * s(1));
    };
    const TetMesh mesh = polycubehex_test::Sweep(square, layers, true, quarter, place);
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
