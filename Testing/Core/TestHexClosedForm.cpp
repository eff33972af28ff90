// SPDX-License-Identifier: BSD-3-Clause
// Seamless hexes from a closed-form polycube (Fang et al. 2016 §4.3): the cut translations are
// rounded to integers together with the chart planes, so that every copy pair across a cut stays
// related by u_plus = Pi u_minus + t with t integer, and the lattice of one side continues into
// the other's. A torus and the quarter-twisted square ring (Figure 14): polycubes without
// corners, which no uncut polycube can mesh.
#include "ClosedFormStages.h"
#include "HexExtraction.h"
#include "HexMeshValidity.h"
#include "PolycubeSeams.h"
#include "TopologyAdjacency.h"
#include "TestAssert.h"

#include <cmath>
#include <iostream>

using namespace polycubehex;

namespace
{
PolycubeTetMesh ToHexInput(const PolycubeCuts& cuts, const PolycubeResult& polycube)
{
  PolycubeTetMesh input;
  input.OriginalVertices = polycube.OriginalPoints;
  input.PolycubeVertices = polycube.Positions;
  input.Cells = polycube.Cells;
  input.FaceLabels = polycube.FaceLabels;
  input.CutRotations = cuts.Transitions;
  for (Eigen::Index c = 0; c < polycube.CutTranslations.rows(); ++c)
  {
    input.CutTranslations.push_back(polycube.CutTranslations.row(c).transpose());
  }
  return input;
}

void CheckSeamlessRounding(const char* name,
  const PolycubeTetMesh& input,
  const HexExtractionResult& result)
{
  // Integer translations, and every copy pair related by them in the rounded lattice.
  PCH_CHECK(result.IntegerCutTranslations.size() == input.CutRotations.size());
  for (const Eigen::Vector3d& t : result.IntegerCutTranslations)
  {
    PCH_CHECK((t - t.array().round().matrix()).norm() == 0.0);
  }
  PolycubeSeams seams;
  PCH_CHECK(FindPolycubeSeams(input.OriginalVertices,
    input.PolycubeVertices,
    input.Cells,
    input.FaceLabels,
    input.CutRotations,
    input.CutTranslations,
    seams)
              .Ok());
  double worst = 0.0;
  for (const SeamCopy& copy : seams.Copies)
  {
    const Eigen::Vector3d minus = result.RoundedPolycube.row(copy.Minus).transpose();
    const Eigen::Vector3d plus = result.RoundedPolycube.row(copy.Plus).transpose();
    const Eigen::Vector3d image =
      seams.Rotations[static_cast<size_t>(copy.Cut)].cast<double>() * minus +
      result.IntegerCutTranslations[static_cast<size_t>(copy.Cut)];
    worst = std::max(worst, (plus - image).norm());
  }
  // Every labelled face on an integer plane.
  double off = 0.0;
  for (Eigen::Index t = 0; t < input.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int label = input.FaceLabels(t, k);
      for (int i = 0; label >= 0 && i < 4; ++i)
      {
        if (TetOppositeFace[i] != k)
        {
          const double u = result.RoundedPolycube(input.Cells(t, i), label / 2);
          off = std::max(off, std::fabs(u - std::round(u)));
        }
      }
    }
  }
  std::cout << name << ": " << seams.Copies.size() << " copy pairs, worst |u+ - (Pi u- + t)| "
            << worst << ", planes off integers by " << off << ", t = "
            << result.IntegerCutTranslations[0].transpose() << ", rounding min volume ratio "
            << result.RoundingMinVolumeRatio << "\n";
  PCH_CHECK(!seams.Copies.empty());
  PCH_CHECK(worst < 1e-9);
  PCH_CHECK(off < 1e-9);
  PCH_CHECK(result.RoundingInvertedTetCount == 0 && result.RoundingMinVolumeRatio > 0.0);
}
} // namespace

int main(int, char*[])
{
  struct Case
  {
    const char* Name;
    TetMesh Mesh;
  };
  Case cases[] = { { "torus", polycubehex_test::SweptTorus(2.0, 0.8, 0, 3, 24) },
    { "twisted square ring", polycubehex_test::TwistedSquareRing() } };
  for (const Case& c : cases)
  {
    PolycubeCuts cuts;
    PolycubeResult polycube;
    PCH_CHECK(polycubehex_test::ClosedForm(c.Name, c.Mesh, cuts, polycube));
    if (polycube.CornerCount != 0 || cuts.Count() != 1)
    {
      PCH_CHECK(false);
      continue;
    }
    const PolycubeTetMesh input = ToHexInput(cuts, polycube);
    // Raw lattice hexes, then the default finish (padding layer and smoothing).
    for (const bool finish : { false, true })
    {
      HexExtractionParameters params;
      params.TargetHexCount = 3000;
      params.Padding = finish;
      params.Smoothing = finish;
      HexExtractionResult result;
      const Status status = extractHexMesh(input, params, result);
      PCH_CHECK(status.Ok());
      if (!status)
      {
        std::cout << c.Name << ": " << status.Message() << "\n";
        continue;
      }
      CheckSeamlessRounding(c.Name, input, result);
      // Seamless: a closed manifold boundary with every quad interior to two hexes, and no
      // corner, so every boundary vertex has four quads (an open seam would leave a boundary
      // ring of valence-3 vertices, a doubled one over-shared quads).
      HexMeshValidity validity;
      PCH_CHECK(checkHexMeshValidity(result.Mesh, validity).Ok());
      std::cout << c.Name << (finish ? " (padding, smoothing)" : " (raw)") << ": "
                << result.HexCount << " hexes, SJ min " << result.ScaledJacobianMin << " mean "
                << result.ScaledJacobianMean << "; " << validity.Report << "\n";
      PCH_CHECK(validity.IsValid());
      PCH_CHECK(validity.IrregularBoundaryVertexCount == 0);
      PCH_CHECK(result.InvertedHexCount == 0);
      // Within 10 % of the target for the lattice; with padding the ring's section is only
      // about four hexes wide, and rounding it by half a hex per side moves the count by more.
      PCH_CHECK(std::abs(result.HexCount - params.TargetHexCount) <=
        (finish ? 0.35 : 0.1) * params.TargetHexCount);
      // The raw lattice follows the map's distortion (the torus's inner side is shorter than
      // its outer side); the finished mesh must be good.
      PCH_CHECK(result.ScaledJacobianMin > (finish ? 0.5 : 0.0));
      for (const std::string& warning : result.Warnings)
      {
        std::cout << "  warning: " << warning << "\n";
      }
    }
  }
  return PCH_TEST_RESULT();
}
