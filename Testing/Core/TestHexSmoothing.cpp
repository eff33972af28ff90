// SPDX-License-Identifier: BSD-3-Clause
// smoothHexMesh on a cube lattice whose charts are the cube's six faces: the directions each
// kind of vertex may move in; on a lattice with a bulged top the sweeps for the mean raise the
// mean beyond the converged Laplacian's without lowering the minimum; a jiggled lattice whose
// minimum scaled Jacobian the sweeps leave low is lifted further by the polish of the worst
// hexes, which never lowers it, keeps the boundary on the cube and the corners in place; a
// perfect lattice stays perfect.
#include "HexScaledJacobian.h"
#include "HexSmoothing.h"
#include "HexSurfaceProjection.h"
#include "HexVertexMoves.h"

#include "TestAssert.h"
#include "TestHexLattice.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace polycubehex;
using polycubehex::testing::Lattice;
using polycubehex::testing::MakeLattice;
using polycubehex::testing::SurfaceError;

namespace
{
/// Interior vertices move along the three axes, face vertices in their face's plane, edge
/// vertices along their edge, corners not at all.
void TestDirections()
{
  Lattice lattice = MakeLattice(3);
  const HexSurfaceProjection projection(lattice.Surface, lattice.VertexCharts, lattice.Mesh, 0.0);
  HexVertexMoves moves(lattice.Mesh, projection);
  PCH_CHECK(moves.Directions(lattice.Id(1, 2, 1)).size() == 3);
  const auto face = moves.Directions(lattice.Id(1, 2, 0)); // on z = 0
  PCH_CHECK(face.size() == 2);
  for (const Eigen::Vector3d& d : face)
  {
    PCH_CHECK_NEAR(d.z(), 0.0, 1e-12);
    PCH_CHECK_NEAR(d.norm(), 1.0, 1e-12);
  }
  PCH_CHECK_NEAR(face[0].dot(face[1]), 0.0, 1e-12);
  const auto edge = moves.Directions(lattice.Id(1, 0, 0)); // on y = 0, z = 0
  PCH_CHECK(edge.size() == 1);
  PCH_CHECK_NEAR(std::fabs(edge[0].x()), 1.0, 1e-12);
  PCH_CHECK(moves.Directions(lattice.Id(0, 0, 0)).empty());
  PCH_CHECK(moves.CurveNeighbours(lattice.Id(1, 0, 0)).size() == 2);
}

/// Every vertex but the corners jiggled within where its charts allow it, by up to `amount`
/// hex edges per free coordinate.
void Jiggle(Lattice& lattice, double amount, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-amount / lattice.N, amount / lattice.N);
  for (int v = 0; v < lattice.Mesh.Vertices.rows(); ++v)
  {
    const std::vector<int>& charts = lattice.VertexCharts[static_cast<size_t>(v)];
    for (int axis = 0; axis < 3; ++axis)
    {
      bool held = false;
      for (int chart : charts)
      {
        held = held || chart / 2 == axis;
      }
      if (!held)
      {
        lattice.Mesh.Vertices(v, axis) += offset(random);
      }
    }
  }
}

/// A lattice whose top face bulges (z scaled by 1 + 0.5 sin(pi x) sin(pi y)): the Laplacian's
/// resting place (evenly spaced vertices) is not where the mean scaled Jacobian is highest.
/// After the Laplacian sweeps have converged, the sweeps with the steps for the mean
/// (MeanSearchSweeps) raise the mean further without lowering the minimum, and keep the five
/// flat faces' vertices on their planes.
void TestMeanSearchRaisesTheMean()
{
  Lattice laplacian = MakeLattice(6);
  for (int v = 0; v < laplacian.Mesh.Vertices.rows(); ++v)
  {
    const double x = laplacian.Mesh.Vertices(v, 0);
    const double y = laplacian.Mesh.Vertices(v, 1);
    laplacian.Mesh.Vertices(v, 2) *= 1.0 + 0.5 * std::sin(M_PI * x) * std::sin(M_PI * y);
  }
  laplacian.Surface.Vertices = laplacian.Mesh.Vertices;
  Lattice searched = laplacian;
  HexSmoothingParameters params;
  params.SoftFeatureAngle = 0.0;
  params.PolishPasses = 0;
  HexSmoothingParameters without = params;
  without.MeanSearchSweeps = 0;
  HexSmoothingResult laplacianResult;
  HexSmoothingResult searchedResult;
  PCH_CHECK(smoothHexMesh(
    laplacian.Mesh, laplacian.VertexCharts, laplacian.Surface, without, laplacianResult));
  PCH_CHECK(
    smoothHexMesh(searched.Mesh, searched.VertexCharts, searched.Surface, params, searchedResult));
  std::cout << "bulged lattice: SJ mean " << laplacianResult.MeanBefore << " -> Laplacian "
            << laplacianResult.MeanAfter << " in " << laplacianResult.Sweeps
            << " sweeps, then the steps for the mean " << searchedResult.MeanAfter << " in "
            << searchedResult.Sweeps - laplacianResult.Sweeps << " more; min "
            << laplacianResult.MinAfter << " / " << searchedResult.MinAfter << std::endl;
  PCH_CHECK(laplacianResult.Sweeps < without.Iterations); // the Laplacian had converged
  PCH_CHECK(searchedResult.MeanAfter > laplacianResult.MeanAfter + 1e-3);
  PCH_CHECK(searchedResult.MinAfter >= laplacianResult.MinAfter);
  PCH_CHECK_NEAR(searchedResult.MeanAfter, ComputeHexScaledJacobians(searched.Mesh).mean(), 1e-12);
  double error = 0.0;
  for (int v = 0; v < searched.Mesh.Vertices.rows(); ++v)
  {
    for (int chart : searched.VertexCharts[static_cast<size_t>(v)])
    {
      if (chart != 5) // the bulged top
      {
        const double plane = chart % 2 == 0 ? 0.0 : 1.0;
        error = std::max(error, std::fabs(searched.Mesh.Vertices(v, chart / 2) - plane));
      }
    }
  }
  PCH_CHECK(error < 1e-9);
}

void TestPolishLiftsTheWorstHexes()
{
  const int n = 6;
  Lattice plain = MakeLattice(n);
  Jiggle(plain, 0.4, 3);
  Lattice polished = plain;
  const Points start = plain.Mesh.Vertices;
  const double jiggled = ComputeHexScaledJacobians(plain.Mesh).minCoeff();

  // Two sweeps leave the lattice far from its cubes, as the real meshes' worst hexes are.
  HexSmoothingParameters params;
  params.Iterations = 2;
  params.SoftFeatureAngle = 0.0;
  params.SweepsAfterPolish = 0; // so that only the polish differs
  params.MeanSearchSweeps = 0;
  HexSmoothingParameters without = params;
  without.PolishPasses = 0;
  HexSmoothingResult plainResult;
  HexSmoothingResult polishedResult;
  PCH_CHECK(smoothHexMesh(plain.Mesh, plain.VertexCharts, plain.Surface, without, plainResult));
  PCH_CHECK(
    smoothHexMesh(polished.Mesh, polished.VertexCharts, polished.Surface, params, polishedResult));
  const Eigen::VectorXd quality = ComputeHexScaledJacobians(polished.Mesh);
  std::cout << "jiggled lattice: SJ min " << jiggled << ", after 2 sweeps " << plainResult.MinAfter
            << ", polished " << polishedResult.MinAfter << " in " << polishedResult.PolishPasses
            << " passes; mean " << plainResult.MeanAfter << " / " << polishedResult.MeanAfter
            << std::endl;

  PCH_CHECK(plainResult.PolishPasses == 0);
  PCH_CHECK(plainResult.MinAfter >= jiggled);
  // The same sweeps first, then a polish that lifts the minimum and never lowers it.
  PCH_CHECK_NEAR(polishedResult.MinBeforePolish, plainResult.MinAfter, 1e-12);
  PCH_CHECK(polishedResult.PolishPasses >= 1);
  PCH_CHECK(polishedResult.MinAfter > plainResult.MinAfter + 0.02);
  PCH_CHECK(polishedResult.MinAfter > 0.9); // back to near cubes
  PCH_CHECK_NEAR(polishedResult.MinAfter, quality.minCoeff(), 1e-12);
  PCH_CHECK_NEAR(polishedResult.MeanAfter, quality.mean(), 1e-12);
  // The boundary stays on the cube, the corners in place.
  PCH_CHECK(SurfaceError(polished, polished.Mesh.Vertices) < 1e-9);
  for (int i : { 0, n })
  {
    for (int j : { 0, n })
    {
      for (int k : { 0, n })
      {
        const int v = polished.Id(i, j, k);
        PCH_CHECK(polished.Mesh.Vertices.row(v) == start.row(v));
      }
    }
  }
}

// The progress bar runs through the polish to 1, in order; an abort asked for during the polish
// stops it: the call fails, and the mesh keeps what was done (no hex worse than before).
void TestPolishProgressAndAbort()
{
  Lattice lattice = MakeLattice(6);
  Jiggle(lattice, 0.4, 3);
  HexSmoothingParameters params;
  params.Iterations = 2;
  params.SoftFeatureAngle = 0.0;
  params.SweepsAfterPolish = 0; // so that nothing but the polish runs after the sweeps
  params.MeanSearchSweeps = 0;
  params.PolishReleaseAngle = 0.0; // one round of two polishes
  params.PolishSharpEdgeAngle = 0.0;
  std::vector<double> fractions;
  HexSmoothingResult result;
  Lattice reported = lattice;
  PCH_CHECK(smoothHexMesh(reported.Mesh,
    reported.VertexCharts,
    reported.Surface,
    params,
    result,
    [&fractions](double f)
    {
      fractions.push_back(f);
      return true;
    }));
  PCH_CHECK(std::is_sorted(fractions.begin(), fractions.end()));
  PCH_CHECK(!fractions.empty() && fractions.back() == 1.0);
  // The sweeps end at 2 / (2 + 2 * 3) of the bar (each polish counts as 3 sweeps); the two
  // polishes report past it.
  const double sweepsEnd = 2.0 / 8.0;
  PCH_CHECK(std::count_if(fractions.begin(),
              fractions.end(),
              [sweepsEnd](double f) { return f > sweepsEnd + 1e-12 && f < 1.0; }) >= 2);

  const double before = ComputeHexScaledJacobians(lattice.Mesh).minCoeff();
  bool askedDuringPolish = false;
  const Status aborted = smoothHexMesh(lattice.Mesh,
    lattice.VertexCharts,
    lattice.Surface,
    params,
    result,
    [&askedDuringPolish, sweepsEnd](double f)
    {
      if (f > sweepsEnd + 1e-12)
      {
        askedDuringPolish = true;
        return false;
      }
      return true;
    });
  PCH_CHECK(!aborted);
  PCH_CHECK(askedDuringPolish);
  PCH_CHECK(aborted.Message().find("aborted") != std::string::npos);
  PCH_CHECK(ComputeHexScaledJacobians(lattice.Mesh).minCoeff() >= before);
}

// A lattice whose top face (z = 1) is three charts meeting at its centre: there the vertex is a
// polycube corner on a flat part of the surface. Pushed sideways (still on the face), it makes
// the worst hexes, and only a polish allowed to release it can move it back.
void TestPolishReleasesSoftCorners()
{
  const int n = 4;
  Lattice lattice = MakeLattice(n);
  for (int f = 0; f < lattice.Surface.Faces.rows(); ++f)
  {
    if (lattice.Surface.FaceChart[static_cast<size_t>(f)] != 5)
    {
      continue;
    }
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      centre += lattice.Surface.Vertices.row(lattice.Surface.Faces(f, k)).transpose() / 3.0;
    }
    lattice.Surface.FaceChart[static_cast<size_t>(f)] =
      centre.x() < 0.5 ? 5 : (centre.y() < 0.5 ? 6 : 7);
  }
  for (int v = 0; v < lattice.Mesh.Vertices.rows(); ++v)
  {
    auto& charts = lattice.VertexCharts[static_cast<size_t>(v)];
    charts.erase(std::remove(charts.begin(), charts.end(), 5), charts.end());
  }
  for (int f = 0; f < lattice.Surface.Faces.rows(); ++f)
  {
    const int chart = lattice.Surface.FaceChart[static_cast<size_t>(f)];
    for (int k = 0; k < 3 && chart >= 5; ++k)
    {
      auto& charts = lattice.VertexCharts[static_cast<size_t>(lattice.Surface.Faces(f, k))];
      if (std::find(charts.begin(), charts.end(), chart) == charts.end())
      {
        charts.push_back(chart);
        std::sort(charts.begin(), charts.end());
      }
    }
  }
  const int centre = lattice.Id(n / 2, n / 2, n);
  PCH_CHECK(lattice.VertexCharts[static_cast<size_t>(centre)] == std::vector<int>({ 5, 6, 7 }));
  lattice.Mesh.Vertices(centre, 0) += 0.45 / n;

  HexSmoothingParameters params;
  params.SoftFeatureAngle = 0.0; // no vertex released before the polish
  params.PolishReleaseAngle = 0.0;
  params.PolishSharpEdgeAngle = 0.0;
  HexSmoothingParameters releasing = params;
  releasing.PolishReleaseAngle = 40.0;
  Lattice held = lattice;
  Lattice released = lattice;
  HexSmoothingResult heldResult;
  HexSmoothingResult releasedResult;
  PCH_CHECK(smoothHexMesh(held.Mesh, held.VertexCharts, held.Surface, params, heldResult));
  PCH_CHECK(smoothHexMesh(
    released.Mesh, released.VertexCharts, released.Surface, releasing, releasedResult));
  std::cout << "soft corner pushed aside: SJ min held " << heldResult.MinAfter << ", released "
            << releasedResult.MinAfter << " (" << releasedResult.PolishReleased
            << " vertices released)" << std::endl;
  PCH_CHECK(heldResult.PolishReleased == 0);
  PCH_CHECK(held.Mesh.Vertices.row(centre) == lattice.Mesh.Vertices.row(centre));
  PCH_CHECK(releasedResult.PolishReleased >= 1);
  PCH_CHECK(releasedResult.MinAfter >= heldResult.MinAfter); // the release comes last
  PCH_CHECK(releasedResult.MinAfter > heldResult.MinAfter + 0.05);
  PCH_CHECK(std::fabs(released.Mesh.Vertices(centre, 0) - 0.5) < 0.45 / n / 2);
  PCH_CHECK(std::fabs(released.Mesh.Vertices(centre, 2) - 1.0) < 1e-9); // still on the face

  // The angle: a flat corner is smooth at any angle; a cube corner (normals 54.7 degrees from
  // their mean) only above that, so that 40 degrees keeps it.
  HexSurfaceProjection projection(released.Surface, released.VertexCharts, released.Mesh, 0.0);
  const Eigen::Vector3d corner = released.Mesh.Vertices.row(released.Id(n, n, n)).transpose();
  PCH_CHECK(!projection.SmoothAt(released.Id(n, n, n), corner, 40.0));
  PCH_CHECK(projection.SmoothAt(released.Id(n, n, n), corner, 60.0));
  PCH_CHECK(projection.SmoothAt(centre, released.Mesh.Vertices.row(centre).transpose(), 1.0));

  // Sharp edges: the cube's corner lies on three edges of 90 degrees, so it is free of sharp
  // edges only when 90 degrees is not sharp; the flat corner has none at any angle (0: off).
  const Eigen::Vector3d middle = released.Mesh.Vertices.row(centre).transpose();
  PCH_CHECK(!projection.FreeOfSharpEdgesAt(released.Id(n, n, n), corner, 45.0));
  PCH_CHECK(!projection.FreeOfSharpEdgesAt(released.Id(n, n, n), corner, 89.0));
  PCH_CHECK(projection.FreeOfSharpEdgesAt(released.Id(n, n, n), corner, 91.0));
  PCH_CHECK(projection.FreeOfSharpEdgesAt(centre, middle, 1.0));
  PCH_CHECK(!projection.FreeOfSharpEdgesAt(centre, middle, 0.0));

  // The same release through PolishSharpEdgeAngle alone (the normals' spread test off): the
  // flat corner has no sharp edge, so the polish moves it as before; the cube's corners stay.
  HexSmoothingParameters bySharpness = params;
  bySharpness.PolishSharpEdgeAngle = 45.0;
  Lattice sharpness = lattice;
  HexSmoothingResult sharpnessResult;
  PCH_CHECK(smoothHexMesh(
    sharpness.Mesh, sharpness.VertexCharts, sharpness.Surface, bySharpness, sharpnessResult));
  std::cout << "soft corner pushed aside, released by edge sharpness: SJ min "
            << sharpnessResult.MinAfter << " (" << sharpnessResult.PolishReleased
            << " vertices released)" << std::endl;
  PCH_CHECK(sharpnessResult.PolishReleased >= 1);
  PCH_CHECK(sharpnessResult.MinAfter > heldResult.MinAfter + 0.05);
  PCH_CHECK(sharpness.Mesh.Vertices.row(sharpness.Id(n, n, n)) ==
    lattice.Mesh.Vertices.row(lattice.Id(n, n, n)));
}

void TestPerfectLatticeStays()
{
  Lattice lattice = MakeLattice(4);
  const Points start = lattice.Mesh.Vertices;
  HexSmoothingResult result;
  PCH_CHECK(smoothHexMesh(
    lattice.Mesh, lattice.VertexCharts, lattice.Surface, HexSmoothingParameters(), result));
  PCH_CHECK_NEAR(result.MinAfter, 1.0, 1e-12);
  PCH_CHECK((lattice.Mesh.Vertices - start).cwiseAbs().maxCoeff() < 1e-12);
}

void TestRefusals()
{
  Lattice lattice = MakeLattice(2);
  HexSmoothingResult result;
  std::vector<std::vector<int>> tooFew(3);
  PCH_CHECK(
    !smoothHexMesh(lattice.Mesh, tooFew, lattice.Surface, HexSmoothingParameters(), result));
}
} // namespace

int main(int, char*[])
{
  TestDirections();
  TestMeanSearchRaisesTheMean();
  TestPolishLiftsTheWorstHexes();
  TestPolishProgressAndAbort();
  TestPolishReleasesSoftCorners();
  TestPerfectLatticeStays();
  TestRefusals();
  return PCH_TEST_RESULT();
}
