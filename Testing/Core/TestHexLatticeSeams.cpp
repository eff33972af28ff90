// SPDX-License-Identifier: BSD-3-Clause
// Seamless lattice extraction on cut polycubes (Fang et al. 2016 §4.3). Square-section rings are
// opened at one station (BuildPolycubeCutMesh) and given analytic lattice positions: the ring
// unrolled into a bar, station index -> x, cross-section -> (y, z), the plus copies at the
// closing station at x = length (t = (length, 0, 0)), or, for the ring whose section turns by a
// quarter once around, with the section turned back (t and Pi a quarter turn about x). The seams
// are found from geometry (FindPolycubeSeams) and the extraction must give every cube once and
// every vertex once, a valid closed hex mesh, positive hexes; then the padding layer and the
// smoothing on the same meshes.
#include "CubeSymmetry.h"
#include "HexLatticeExtraction.h"
#include "HexLatticePadding.h"
#include "HexMeshValidity.h"
#include "HexScaledJacobian.h"
#include "HexSmoothing.h"
#include "IntegerRounding.h"
#include "PolycubeCutMesh.h"
#include "PolycubeSeams.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <vector>

using namespace polycubehex;

namespace
{
constexpr int FaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

/// A cut polycube ready for extraction.
struct CutRing
{
  Points Original; ///< #V by 3 on M_c (copies share their input point)
  Points Lattice;  ///< #V by 3 lattice positions
  Tets Cells;
  Tets Labels; ///< -1 on cut faces and interior faces
  ChartPlanes Charts;
  PolycubeSeams Seams;
  int Stations = 0;
  int Section = 0; ///< lattice units across the section
  int Length = 0;  ///< lattice units along the ring
};

int LabelOf(const Eigen::Vector3d& normal)
{
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  return 2 * axis + (normal[axis] > 0.0 ? 0 : 1);
}

/// A ring of n x n section cells (each split in 4 triangles), `stations` stations around,
/// twisted by a quarter turn once around or not; `scale` lattice units per section cell and per
/// station.
bool MakeCutRing(int n, int stations, bool twisted, int scale, CutRing& ring)
{
  std::vector<int> quarter;
  const polycubehex_test::Planar square = polycubehex_test::MakeSquare(n, quarter);
  const int nv = static_cast<int>(square.Points.size());
  auto place = [&](int l, const Eigen::Vector2d& p)
  {
    const double theta = 2.0 * polycubehex_test::Pi * l / stations;
    const double twist = twisted ? 0.5 * polycubehex_test::Pi * l / stations : 0.0;
    const Eigen::Vector2d s = Eigen::Rotation2Dd(twist) * p;
    const double rho = 3.0 - 0.8 * s(0); // (station, s) right-handed
    return Eigen::Vector3d(rho * std::cos(theta), rho * std::sin(theta), 0.8 * s(1));
  };
  const TetMesh input =
    polycubehex_test::Sweep(square, stations, true, twisted ? quarter : std::vector<int>(), place);
  const int tetCount = static_cast<int>(input.Cells.rows());
  const int perLayer = tetCount / stations;

  // The cut: the section at station 0; the tets of the last layer are on its plus side.
  PolycubeCuts cuts;
  cuts.FaceCut.setConstant(tetCount, 4, -1);
  cuts.FaceSide.setZero(tetCount, 4);
  std::vector<int> inverseQuarter(static_cast<size_t>(nv));
  for (int p = 0; p < nv; ++p)
  {
    inverseQuarter[static_cast<size_t>(quarter[static_cast<size_t>(p)])] = p;
  }
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      bool atZero = true;
      for (int i = 0; i < 3; ++i)
      {
        atZero = atZero && input.Cells(t, FaceTable[k][i]) < nv;
      }
      if (atZero)
      {
        cuts.FaceCut(t, k) = 0;
        cuts.FaceSide(t, k) = t / perLayer == stations - 1 ? 1 : -1;
      }
    }
  }
  // Pi: the map from the minus side's section coordinates to the plus side's, the inverse
  // quarter turn of the section (y, z) = (p0, p1) when twisted.
  Eigen::Matrix3i pi = Eigen::Matrix3i::Identity();
  if (twisted)
  {
    pi << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  }
  cuts.Transitions.push_back(pi);
  PolycubeCutMesh cut;
  if (!BuildPolycubeCutMesh(input, cuts, cut))
  {
    return false;
  }
  const int vertexCount = static_cast<int>(cut.CopiedVertex.size());
  ring = CutRing();
  ring.Stations = stations;
  ring.Section = scale * n;
  ring.Length = scale * stations;
  ring.Cells = cut.Cells;
  ring.Original.resize(vertexCount, 3);
  for (int v = 0; v < vertexCount; ++v)
  {
    ring.Original.row(v) = input.Vertices.row(cut.CopiedVertex[static_cast<size_t>(v)]);
  }
  // Lattice positions per tet corner: the bar's x is the station (the last layer's top is the
  // station `stations`), the section coordinates are those of the tet's layer (untwisted).
  ring.Lattice.setZero(vertexCount, 3);
  auto section = [&](int point)
  {
    const Eigen::Vector2d& p = square.Points[static_cast<size_t>(point)];
    return Eigen::Vector2d(0.5 * scale * n * (p(0) + 1.0), 0.5 * scale * n * (p(1) + 1.0));
  };
  for (int t = 0; t < tetCount; ++t)
  {
    const int layer = t / perLayer;
    for (int i = 0; i < 4; ++i)
    {
      const int w = input.Cells(t, i);
      int station = w / nv;
      int point = w % nv;
      if (layer == stations - 1 && station == 0)
      {
        station = stations;
        point = twisted ? inverseQuarter[static_cast<size_t>(point)] : point;
      }
      const Eigen::Vector2d s = section(point);
      ring.Lattice.row(ring.Cells(t, i)) << scale * station, s(0), s(1);
    }
  }
  // Labels from the lattice normals; the cut faces get theirs only for ComputeChartPlanes, which
  // wants every boundary face labelled, and their charts are dropped afterwards.
  Tets labelsWithCuts = Tets::Constant(tetCount, 4, -1);
  ring.Labels = Tets::Constant(tetCount, 4, -1);
  {
    // Boundary faces of M_c: faces without a neighbour.
    std::map<std::array<int, 3>, int> count;
    for (int t = 0; t < tetCount; ++t)
    {
      for (int k = 0; k < 4; ++k)
      {
        std::array<int, 3> f = { ring.Cells(t, FaceTable[k][0]),
          ring.Cells(t, FaceTable[k][1]),
          ring.Cells(t, FaceTable[k][2]) };
        std::sort(f.begin(), f.end());
        ++count[f];
      }
    }
    for (int t = 0; t < tetCount; ++t)
    {
      for (int k = 0; k < 4; ++k)
      {
        std::array<int, 3> f = { ring.Cells(t, FaceTable[k][0]),
          ring.Cells(t, FaceTable[k][1]),
          ring.Cells(t, FaceTable[k][2]) };
        std::sort(f.begin(), f.end());
        if (count[f] != 1)
        {
          continue;
        }
        const Eigen::Vector3d a = ring.Lattice.row(ring.Cells(t, FaceTable[k][0])).transpose();
        const Eigen::Vector3d b = ring.Lattice.row(ring.Cells(t, FaceTable[k][1])).transpose();
        const Eigen::Vector3d c = ring.Lattice.row(ring.Cells(t, FaceTable[k][2])).transpose();
        const int label = LabelOf((b - a).cross(c - a));
        labelsWithCuts(t, k) = label;
        if (cuts.FaceCut(t, k) < 0)
        {
          ring.Labels(t, k) = label;
        }
      }
    }
  }
  if (!ComputeChartPlanes(ring.Lattice, ring.Cells, labelsWithCuts, ring.Charts))
  {
    return false;
  }
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (cuts.FaceCut(t, k) >= 0)
      {
        ring.Charts.FaceChart(t, k) = -1;
      }
    }
  }
  const Eigen::Vector3d translation = twisted ? Eigen::Vector3d(ring.Length, 0.0, ring.Section)
                                              : Eigen::Vector3d(ring.Length, 0.0, 0.0);
  return FindPolycubeSeams(
    ring.Original, ring.Lattice, ring.Cells, ring.Labels, { pi }, { translation }, ring.Seams)
    .Ok();
}

/// The section coordinates (in [-1, 1]^2 inside) of a point of the ring, the twist undone.
Eigen::Vector2d SectionOf(const Eigen::RowVector3d& x, int stations, bool twisted)
{
  double theta = std::atan2(x(1), x(0));
  theta = theta < 0.0 ? theta + 2.0 * polycubehex_test::Pi : theta;
  const double twist = twisted ? 0.25 * theta : 0.0;
  const Eigen::Vector2d s((3.0 - std::hypot(x(0), x(1))) / 0.8, x(2) / 0.8);
  (void)stations;
  return Eigen::Rotation2Dd(-twist) * s;
}

double MinTetVolume(const Points& x, const Tets& cells)
{
  double smallest = std::numeric_limits<double>::max();
  for (int t = 0; t < cells.rows(); ++t)
  {
    smallest = std::min(smallest, TetSignedVolume(x, cells, t));
  }
  return smallest;
}

void CheckRing(const char* name, int n, int stations, bool twisted, int scale)
{
  CutRing ring;
  const bool made = MakeCutRing(n, stations, twisted, scale, ring);
  PCH_CHECK(made);
  if (!made)
  {
    return;
  }
  PCH_CHECK(MinTetVolume(ring.Original, ring.Cells) > 0.0);
  PCH_CHECK(MinTetVolume(ring.Lattice, ring.Cells) > 0.0);
  PCH_CHECK(ring.Seams.CutCount() == 1);
  const int expectedHexes = ring.Length * ring.Section * ring.Section;
  const int expectedVertices = ring.Length * (ring.Section + 1) * (ring.Section + 1);

  // Without the seams the bar comes out open at the cut: every vertex of the section twice.
  LatticeHexMesh open;
  PCH_CHECK(extractLatticeHexes(
    ring.Original, ring.Lattice, ring.Cells, ring.Charts, LatticeExtractionParameters(), open));
  PCH_CHECK(open.Mesh.Cells.rows() == expectedHexes);
  PCH_CHECK(
    open.Mesh.Vertices.rows() == expectedVertices + (ring.Section + 1) * (ring.Section + 1));

  LatticeHexMesh out;
  PCH_CHECK(extractLatticeHexes(ring.Original,
    ring.Lattice,
    ring.Cells,
    ring.Charts,
    LatticeExtractionParameters(),
    out,
    {},
    &ring.Seams));
  const int hexCount = static_cast<int>(out.Mesh.Cells.rows());
  const int vertexCount = static_cast<int>(out.Mesh.Vertices.rows());
  std::cout << name << ": " << hexCount << " hexes (expected " << expectedHexes << "), "
            << vertexCount << " vertices (expected " << expectedVertices << "), incomplete "
            << out.IncompleteCubeCount << ", ambiguous corners " << out.AmbiguousCornerCount
            << ", inconsistent seams " << out.InconsistentSeamCount << "\n";
  PCH_CHECK(hexCount == expectedHexes);
  PCH_CHECK(vertexCount == expectedVertices);
  PCH_CHECK(out.IncompleteCubeCount == 0);
  PCH_CHECK(out.InconsistentSeamCount == 0);
  HexMeshValidity validity;
  PCH_CHECK(checkHexMeshValidity(out.Mesh, validity));
  std::cout << "  " << validity.Report << "\n";
  PCH_CHECK(validity.IsValid());
  PCH_CHECK(validity.BoundaryQuadCount == 4 * ring.Length * ring.Section);
  // A closed ring without polycube corners: every boundary vertex has 4 quads.
  PCH_CHECK(validity.IrregularBoundaryVertexCount == 0);
  const Eigen::VectorXd quality = ComputeHexScaledJacobians(out.Mesh);
  std::cout << "  scaled Jacobian min " << quality.minCoeff() << " mean " << quality.mean() << "\n";
  PCH_CHECK(quality.minCoeff() > 0.0);

  // Each corner in the hex's frame is the rotated vertex coordinate plus an integer shift; the
  // twisted ring has hexes with corners seen through the quarter turn.
  PCH_CHECK(out.HexCornerRotations.size() == 8 * static_cast<size_t>(hexCount));
  PCH_CHECK(out.HexOrigins.rows() == hexCount);
  int rotatedCorners = 0;
  int badShifts = 0;
  const int cubeCorners[8][3] = { { 0, 0, 0 },
    { 1, 0, 0 },
    { 1, 1, 0 },
    { 0, 1, 0 },
    { 0, 0, 1 },
    { 1, 0, 1 },
    { 1, 1, 1 },
    { 0, 1, 1 } };
  for (int h = 0; h < hexCount && out.HexCornerRotations.size() == 8 * size_t(hexCount); ++h)
  {
    for (int k = 0; k < 8; ++k)
    {
      const Eigen::Matrix3i& r = out.HexCornerRotations[8 * static_cast<size_t>(h) + k];
      rotatedCorners += r != Eigen::Matrix3i::Identity() ? 1 : 0;
      const Eigen::Vector3d corner = out.HexOrigins.row(h).transpose() +
        Eigen::Vector3d(cubeCorners[k][0], cubeCorners[k][1], cubeCorners[k][2]);
      const Eigen::Vector3d shift =
        corner - r.cast<double>() * out.LatticeVertices.row(out.Mesh.Cells(h, k)).transpose();
      // The shift is 0 or the cut's translation (up to the rotation): always integer, and the
      // same for the corners of one hex seen from one side.
      badShifts += (shift - shift.array().round().matrix()).norm() > 1e-9 ? 1 : 0;
    }
  }
  std::cout << "  corners seen through a rotation: " << rotatedCorners << "\n";
  PCH_CHECK(badShifts == 0);
  PCH_CHECK(twisted ? rotatedCorners > 0 : rotatedCorners == 0);

  // Charts of M for the smoothing: the straight ring's four sides are four charts of M_c
  // already; the twisted ring's four sides continue each other across the seam but also meet
  // along the ring's edges, so they stay four (a chart cannot be told from itself at a feature
  // curve). Either way a boundary vertex counts one chart on a side and two on an edge, on the
  // seam too.
  const std::vector<int> glued = GlueChartsAcrossSeams(ring.Cells, ring.Charts, &ring.Seams);
  std::set<int> realCharts;
  for (int t = 0; t < ring.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (ring.Charts.FaceChart(t, k) >= 0)
      {
        realCharts.insert(glued[static_cast<size_t>(ring.Charts.FaceChart(t, k))]);
      }
    }
  }
  std::cout << "  charts for the smoothing: " << realCharts.size() << "\n";
  PCH_CHECK(realCharts.size() == 4u);
  const std::vector<std::vector<int>> vertexCharts = GluedVertexCharts(out, glued);
  int onOne = 0;
  int onTwo = 0;
  int other = 0;
  int seamCharts = 0; // charts of M_c seen by the vertices on the seam, before merging
  for (int v = 0; v < vertexCount; ++v)
  {
    const size_t count = vertexCharts[static_cast<size_t>(v)].size();
    onOne += count == 1 ? 1 : 0;
    onTwo += count == 2 ? 1 : 0;
    other += count > 2 ? 1 : 0;
    const std::vector<int>& labels = out.VertexChartLabels[static_cast<size_t>(v)];
    std::set<int> distinct(labels.begin(), labels.end());
    other += distinct.size() != count ? 1 : 0;
    seamCharts += out.VertexCharts[static_cast<size_t>(v)].size() > count ? 1 : 0;
  }
  std::cout << "  boundary vertices on 1 / 2 charts: " << onOne << " / " << onTwo
            << "; seen from both sides of the seam with two charts of M_c per chart: " << seamCharts
            << "\n";
  PCH_CHECK(onOne == 4 * (ring.Section - 1) * ring.Length);
  PCH_CHECK(onTwo == 4 * ring.Length);
  PCH_CHECK(other == 0);
  PCH_CHECK(twisted ? seamCharts == 4 * ring.Section : seamCharts == 0);

  // A point behind the cut, found from the minus side: the walk crosses the seam.
  {
    int start = -1;
    const Eigen::Vector3d from(0.0, 0.5 * ring.Section, 0.5 * ring.Section);
    for (int t = 0; t < ring.Cells.rows() && start < 0; ++t)
    {
      bool minusAtZero = false;
      for (int k = 0; k < 4; ++k)
      {
        minusAtZero = minusAtZero || ring.Seams.Side(t, k) < 0;
      }
      for (int i = 0; i < 4 && minusAtZero; ++i)
      {
        if ((ring.Lattice.row(ring.Cells(t, i)).transpose() - from).norm() < 1e-9)
        {
          start = t;
        }
      }
    }
    PCH_CHECK(start >= 0);
    Eigen::RowVector3d image;
    const Eigen::Vector3d behind = from - Eigen::Vector3d(0.5 * scale, 0.0, 0.0);
    const bool found = start >= 0 &&
      MapLatticePoint(ring.Original,
        ring.Lattice,
        ring.Cells,
        ring.Charts,
        start,
        from,
        behind,
        1e-9,
        image,
        &ring.Seams);
    PCH_CHECK(found);
    // Half a station before station 0: at angle -pi / stations on the core circle.
    const double angle = std::atan2(image(1), image(0));
    PCH_CHECK_NEAR(angle, -polycubehex_test::Pi / stations, 1e-9);
    PCH_CHECK(!MapLatticePoint(ring.Original,
      ring.Lattice,
      ring.Cells,
      ring.Charts,
      std::max(start, 0),
      from,
      behind,
      1e-9,
      image));
  }

  // The padding layer: one hex per boundary quad, every copy placed through the tets (across
  // the seam too), the mesh valid and positive.
  LatticeHexMesh padded = out;
  LatticePaddingResult padding;
  PCH_CHECK(addLatticePaddingLayer(
    ring.Original, ring.Lattice, ring.Cells, ring.Charts, 1.0 / 3.0, padded, padding, &ring.Seams));
  PCH_CHECK(padding.PaddingHexCount == validity.BoundaryQuadCount);
  PCH_CHECK(padding.UnmappedVertexCount == 0);
  HexMeshValidity paddedValidity;
  PCH_CHECK(checkHexMeshValidity(padded.Mesh, paddedValidity));
  PCH_CHECK(paddedValidity.IsValid());
  const Eigen::VectorXd paddedQuality = ComputeHexScaledJacobians(padded.Mesh);
  std::cout << "  padded: " << padded.Mesh.Cells.rows() << " hexes, scaled Jacobian min "
            << paddedQuality.minCoeff() << " mean " << paddedQuality.mean() << "\n";
  PCH_CHECK(padded.Mesh.Cells.rows() == hexCount + validity.BoundaryQuadCount);
  PCH_CHECK(paddedQuality.minCoeff() > 0.2);
  // The inner copies of the vertices on the cut are as deep as the others: a third of a unit
  // from each side of the section in the lattice (every frame's section is [0, Section]^2), and
  // inside the ring in the original.
  {
    double shallowest = std::numeric_limits<double>::max();
    double deepest = 0.0;
    int outside = 0;
    for (int v = vertexCount; v < padded.Mesh.Vertices.rows(); ++v)
    {
      const Eigen::RowVector3d u = padded.LatticeVertices.row(v);
      const double depth = std::min({ u(1), ring.Section - u(1), u(2), ring.Section - u(2) });
      shallowest = std::min(shallowest, depth);
      deepest = std::max(deepest, depth);
      const Eigen::Vector2d p = SectionOf(padded.Mesh.Vertices.row(v), stations, twisted);
      outside += p.cwiseAbs().maxCoeff() < 1.0 ? 0 : 1;
    }
    std::cout << "  padding copies at lattice depth " << shallowest << " to " << deepest << "\n";
    PCH_CHECK_NEAR(shallowest, 1.0 / 3.0, 1e-9);
    PCH_CHECK_NEAR(deepest, 1.0 / 3.0, 1e-9);
    PCH_CHECK(outside == 0);
  }

  // Smoothing on the glued charts, the seam's copies as one surface vertex.
  std::vector<std::vector<int>> paddedCharts = vertexCharts;
  paddedCharts.resize(static_cast<size_t>(padded.Mesh.Vertices.rows()));
  const HexSmoothingSurface surface = MakeChartSurface(ring.Original,
    ring.Cells,
    ring.Charts.FaceChart,
    glued,
    SeamVertexIdentity(static_cast<int>(ring.Original.rows()), &ring.Seams));
  HexMesh smoothedMesh = padded.Mesh;
  HexSmoothingResult smoothed;
  PCH_CHECK(smoothHexMesh(smoothedMesh, paddedCharts, surface, HexSmoothingParameters(), smoothed));
  std::cout << "  smoothed: scaled Jacobian min " << smoothed.MinBefore << " -> "
            << smoothed.MinAfter << ", mean " << smoothed.MeanBefore << " -> " << smoothed.MeanAfter
            << " in " << smoothed.Sweeps << " sweeps\n";
  PCH_CHECK(smoothed.MinAfter >= smoothed.MinBefore);
  PCH_CHECK(smoothed.MinAfter > 0.2);
  // Boundary vertices stay on the section's square (up to the chords of the round sides).
  double offSurface = 0.0;
  for (int v = 0; v < vertexCount; ++v)
  {
    if (vertexCharts[static_cast<size_t>(v)].empty())
    {
      continue; // interior
    }
    const Eigen::Vector2d p = SectionOf(smoothedMesh.Vertices.row(v), stations, twisted);
    offSurface = std::max(
      offSurface, 0.8 * std::min(std::abs(1.0 - std::abs(p(0))), std::abs(1.0 - std::abs(p(1)))));
  }
  std::cout << "  boundary vertices off the surface by at most " << offSurface << "\n";
  // The chords of the round sides, and of the twisted ones (a corner of the section moves on
  // a helix, the tets on its chords).
  const double chord = 3.8 * (1.0 - std::cos(polycubehex_test::Pi / stations)) +
    (twisted ? 0.8 * std::sqrt(2.0) * (1.0 - std::cos(0.25 * polycubehex_test::Pi / stations))
             : 0.0);
  PCH_CHECK(offSurface <= chord + 1e-9);
  HexMeshValidity smoothedValidity;
  PCH_CHECK(checkHexMeshValidity(smoothedMesh, smoothedValidity));
  PCH_CHECK(smoothedValidity.IsValid());
}
} // namespace

int main(int, char*[])
{
  CheckRing("straight ring", 2, 12, false, 1);
  CheckRing("straight ring, 2 units per cell", 2, 12, false, 2);
  CheckRing("twisted ring", 4, 16, true, 1);
  CheckRing("twisted ring, 2 units per cell", 2, 12, true, 2);
  return PCH_TEST_RESULT();
}
