// SPDX-License-Identifier: BSD-3-Clause
// Test helpers for the closed-form pipeline in the core: the three stages before hex extraction
// (cuts, frame field with transitions, polycube on the cut mesh), and the square ring twisted by
// a quarter turn of the paper's Figure 14.
#pragma once

#include "FrameField.h"
#include "HandleCuts.h"
#include "PolycubeDeformation.h"
#include "TestMeshGenerators.h"

#include <Eigen/Geometry>

#include <cmath>
#include <iostream>

namespace polycubehex_test
{
using namespace polycubehex;

/// Runs the three stages; returns false (with a message) when one refuses.
inline bool ClosedForm(const char* name, const TetMesh& mesh, PolycubeCuts& cuts, PolycubeResult& out)
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

/// A square ring whose section turns by a quarter once around (one cut, a quarter-turn
/// transition): its polycube is a bar without corners, its ends glued by a quarter turn.
inline TetMesh TwistedSquareRing(int layers = 40)
{
  std::vector<int> quarter;
  const Planar square = MakeSquare(4, quarter);
  auto place = [layers](int l, const Eigen::Vector2d& p)
  {
    const double theta = 2.0 * Pi * l / layers;
    const double twist = 0.5 * Pi * l / layers;
    const Eigen::Vector2d s = Eigen::Rotation2Dd(twist) * p;
    const double rho = 2.5 + 0.6 * s(0);
    return Eigen::Vector3d(rho * std::cos(theta), rho * std::sin(theta), 0.6 * s(1));
  };
  return Sweep(square, layers, true, quarter, place);
}

} // namespace polycubehex_test
