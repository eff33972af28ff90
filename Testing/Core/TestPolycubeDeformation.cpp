// SPDX-License-Identifier: BSD-3-Clause
// ComputePolycube (uniform guidance): a cube stays a cube, a rotated cube is turned back onto
// the axes, a genus-1 ring becomes a valid polycube, a tet that would be flattened is split, and
// bad inputs are refused with a message.
#include "PolycubeCharts.h"
#include "PolycubeDeformation.h"
#include "PolycubeEnergy.h"
#include "PolycubeRotation.h"
#include "TestAssert.h"
#include "TetEdgeSplit.h"
#include "TetGeometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

using namespace polycubehex;

namespace
{

constexpr double Pi = 3.14159265358979323846;

/// A structured grid of nx x ny x nz cells mapped by `map` from [0,1]^3, each cell split into the
/// six Kuhn tets (conforming). With periodicZ the last layer of cells joins the first one.
TetMesh MakeGridMesh(int nx,
  int ny,
  int nz,
  bool periodicZ,
  const std::function<Eigen::RowVector3d(double, double, double)>& map)
{
  TetMesh mesh;
  const int layers = periodicZ ? nz : nz + 1;
  auto id = [&](int i, int j, int k)
  { return (k % layers) * (nx + 1) * (ny + 1) + j * (nx + 1) + i; };
  mesh.Vertices.resize((nx + 1) * (ny + 1) * layers, 3);
  for (int k = 0; k < layers; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        mesh.Vertices.row(id(i, j, k)) = map(
          static_cast<double>(i) / nx, static_cast<double>(j) / ny, static_cast<double>(k) / nz);
      }
    }
  }
  const int paths[6][3] = {
    { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
  };
  std::vector<std::array<int, 4>> tets;
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        for (const auto& path : paths)
        {
          int c[3] = { i, j, k };
          std::array<int, 4> tet;
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++c[path[s]];
            tet[static_cast<size_t>(s) + 1] = id(c[0], c[1], c[2]);
          }
          tets.push_back(tet);
        }
      }
    }
  }
  mesh.Cells.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      mesh.Cells(static_cast<Eigen::Index>(t), c) = tets[t][static_cast<size_t>(c)];
    }
    if (TetSignedVolume(mesh.Vertices, mesh.Cells, static_cast<int>(t)) < 0.0)
    {
      std::swap(
        mesh.Cells(static_cast<Eigen::Index>(t), 0), mesh.Cells(static_cast<Eigen::Index>(t), 1));
    }
  }
  return mesh;
}

TetMesh MakeCube(int n)
{
  return MakeGridMesh(
    n, n, n, false, [](double a, double b, double c) { return Eigen::RowVector3d(a, b, c); });
}

double Diagonal(const Points& x)
{
  return (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
}

/// Checks shared by every successful result: shapes, labels against the final normals, planes,
/// connected charts, positive tets.
void CheckValidPolycube(const PolycubeResult& r, const char* name)
{
  std::cout << name << ": " << r.Positions.rows() << " vertices, " << r.Cells.rows()
            << " tets, residual " << r.Residual << ", rounds " << r.Rounds << ", charts "
            << r.ChartCount << ", corners " << r.CornerCount << ", inverted " << r.InvertedTetCount
            << ", presplit " << r.PresplitEdgeCount << ", split " << r.SplitEdgeCount << "+"
            << r.SplitTetCount << ", " << r.TotalSeconds << " s" << std::endl;
  for (const auto& warning : r.Warnings)
  {
    std::cout << "  warning: " << warning << std::endl;
  }
  const Eigen::Index n = r.Positions.rows();
  PCH_CHECK(static_cast<Eigen::Index>(r.OriginalPointId.size()) == n);
  PCH_CHECK(r.OriginalPoints.rows() == n);
  PCH_CHECK(static_cast<Eigen::Index>(r.OriginalCellId.size()) == r.Cells.rows());
  PCH_CHECK(r.FaceLabels.rows() == r.Cells.rows());
  PCH_CHECK(r.InvertedTetCount == 0);
  PCH_CHECK(r.Converged);
  const double diagonal = Diagonal(r.Positions);

  int inverted = 0;
  for (Eigen::Index t = 0; t < r.Cells.rows(); ++t)
  {
    inverted += TetSignedVolume(r.Positions, r.Cells, static_cast<int>(t)) > 0.0 ? 0 : 1;
  }
  PCH_CHECK(inverted == 0);

  // Every boundary face lies on its chart's plane and its normal is its label's direction.
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(n), r.Cells, topology);
  PCH_CHECK(topology.BoundaryFaces.rows() == r.BoundaryFaces.rows());
  int wrongLabels = 0;
  double planeError = 0.0;
  for (Eigen::Index f = 0; f < r.BoundaryFaces.rows(); ++f)
  {
    const int label = r.BoundaryFaceLabel[static_cast<size_t>(f)];
    const int chart = r.ChartId[static_cast<size_t>(f)];
    const Eigen::Vector3d p0 = r.Positions.row(r.BoundaryFaces(f, 0)).transpose();
    const Eigen::Vector3d normal =
      (r.Positions.row(r.BoundaryFaces(f, 1)).transpose() - p0)
        .cross(r.Positions.row(r.BoundaryFaces(f, 2)).transpose() - p0);
    wrongLabels += PolycubeLabelOfNormal(normal) == label ? 0 : 1;
    for (int c = 0; c < 3; ++c)
    {
      planeError = std::max(planeError,
        std::abs(r.Positions(r.BoundaryFaces(f, c), label / 2) -
          r.ChartPlane[static_cast<size_t>(chart)]));
    }
    // The tet's face label table agrees.
    PCH_CHECK(r.FaceLabels(topology.BoundaryFaceTet[static_cast<size_t>(f)],
                topology.BoundaryFaceLocal[static_cast<size_t>(f)]) >= 0);
  }
  PCH_CHECK(wrongLabels == 0);
  if (r.UnflattenedVertexCount == 0)
  {
    PCH_CHECK(planeError <= 1e-9 * diagonal);
  }

  // Charts are connected: a flood fill inside each chart reaches all its faces.
  const Triangles adjacency = ComputeFaceAdjacency(static_cast<int>(n), r.BoundaryFaces);
  const PolycubeCharts charts =
    ComputePolycubeCharts(r.Positions, r.BoundaryFaces, adjacency, r.BoundaryFaceLabel);
  PCH_CHECK(charts.Count() == r.ChartCount);
  std::vector<int> seen(static_cast<size_t>(r.ChartCount), -1);
  bool consistent = true;
  for (Eigen::Index f = 0; f < r.BoundaryFaces.rows(); ++f)
  {
    // Same partition up to renumbering.
    int& mapped = seen[static_cast<size_t>(r.ChartId[static_cast<size_t>(f)])];
    if (mapped < 0)
    {
      mapped = charts.FaceChart[static_cast<size_t>(f)];
    }
    consistent = consistent && mapped == charts.FaceChart[static_cast<size_t>(f)];
  }
  PCH_CHECK(consistent);
  PCH_CHECK(r.CornerCount == CountPolycubeCorners(static_cast<int>(n), r.BoundaryFaces, r.ChartId));
}

void TestCube()
{
  const TetMesh cube = MakeCube(4);
  PolycubeParameters params;
  PolycubeResult r;
  const Status status = ComputePolycube(cube, params, r);
  PCH_CHECK(status.Ok());
  if (!status)
  {
    std::cerr << status.Message() << std::endl;
    return;
  }
  CheckValidPolycube(r, "cube");
  PCH_CHECK_NEAR(r.Residual, 0.0, 1e-9);
  PCH_CHECK(r.ChartCount == 6);
  PCH_CHECK(r.CornerCount == 8);
  PCH_CHECK(r.Rounds == 0); // already a polycube: not deformed
  // Its edges keep their length along their axes.
  PCH_CHECK(r.SquashedCreaseCount == 0);
  PCH_CHECK_NEAR(r.MinCreaseStretch, 1.0, 1e-6);
  // ... and no vertex is flagged as defective.
  PCH_CHECK(static_cast<Eigen::Index>(r.VertexDefects.size()) == r.Positions.rows());
  PCH_CHECK(
    std::all_of(r.VertexDefects.begin(), r.VertexDefects.end(), [](int f) { return f == 0; }));
  // The cube stays where it was (up to the symmetry the initial rotation may pick: none).
  PCH_CHECK((r.InitialRotation - Eigen::Matrix3d::Identity()).norm() < 1e-9);
  const Eigen::Index n = cube.Vertices.rows();
  PCH_CHECK((r.Positions.topRows(n) - cube.Vertices).cwiseAbs().maxCoeff() < 1e-6);
  for (Eigen::Index v = 0; v < r.Positions.rows(); ++v)
  {
    PCH_CHECK(r.OriginalPointId[static_cast<size_t>(v)] == (v < n ? static_cast<int>(v) : -1));
  }
}

void TestRotatedCube()
{
  TetMesh cube = MakeCube(4);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(30.0 * Pi / 180.0, Eigen::Vector3d(1.0, 2.0, 3.0).normalized())
      .toRotationMatrix();
  cube.Vertices = cube.Vertices * rotation.transpose();
  const TetMesh input = cube;
  PolycubeParameters params;
  params.AlignInitialRotation = true;
  PolycubeResult r;
  const Status status = ComputePolycube(input, params, r);
  PCH_CHECK(status.Ok());
  if (!status)
  {
    std::cerr << status.Message() << std::endl;
    return;
  }
  CheckValidPolycube(r, "rotated cube");
  PCH_CHECK(r.Residual < 1e-6);
  PCH_CHECK(r.ChartCount == 6);
  PCH_CHECK(r.CornerCount == 8);
  // The found rotation undoes the input's up to a cube symmetry: R * rotation is a signed
  // permutation.
  const Eigen::Matrix3d product = r.InitialRotation * rotation;
  PCH_CHECK((product.cwiseAbs().rowwise().maxCoeff().array() - 1.0).abs().maxCoeff() < 1e-6);
  // The result is axis-aligned: its area-weighted l1 norm of normals is 1.
  PCH_CHECK_NEAR(
    AreaWeightedL1Norm(r.Positions, r.BoundaryFaces, Eigen::Matrix3d::Identity()), 1.0, 1e-9);
  for (Eigen::Index v = 0; v < input.Vertices.rows(); ++v)
  {
    PCH_CHECK((r.OriginalPoints.row(v) - input.Vertices.row(v)).norm() == 0.0);
  }
}

/// FrameField guidance: frames that undo a rotation make the frame fit an axis-aligned cube at
/// once (no l1 round needed); frames of the wrong count or not rotations are refused.
void TestFrameGuidedCube()
{
  TetMesh cube = MakeCube(4);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(25.0 * Pi / 180.0, Eigen::Vector3d(3.0, -1.0, 2.0).normalized())
      .toRotationMatrix();
  cube.Vertices = cube.Vertices * rotation.transpose();
  // R_t maps the input to the polycube: the inverse of the rotation, in every tet.
  const std::vector<Eigen::Matrix3d> frames(
    static_cast<size_t>(cube.Cells.rows()), rotation.transpose());
  PolycubeParameters params;
  PolycubeResult r;
  const Status status = ComputePolycube(cube, params, r, {}, frames);
  PCH_CHECK(status.Ok());
  if (!status)
  {
    std::cerr << status.Message() << std::endl;
    return;
  }
  CheckValidPolycube(r, "frame-guided cube");
  PCH_CHECK(r.FrameFitResidual < 1e-12);
  PCH_CHECK(r.Rounds == 0);
  PCH_CHECK(r.Residual < 1e-9);
  PCH_CHECK(r.ChartCount == 6);
  PCH_CHECK(r.CornerCount == 8);
  PCH_CHECK((r.InitialRotation - rotation.transpose()).norm() < 1e-9);
  PCH_CHECK_NEAR(
    AreaWeightedL1Norm(r.Positions, r.BoundaryFaces, Eigen::Matrix3d::Identity()), 1.0, 1e-9);

  // A frame field that twists the cube by 90 degrees from bottom to top: the fit cannot follow
  // it exactly, but every tet stays positive and the result is still a valid polycube.
  std::vector<Eigen::Matrix3d> twisted(frames.size());
  for (Eigen::Index t = 0; t < cube.Cells.rows(); ++t)
  {
    double z = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      z += MakeCube(4).Vertices(cube.Cells(t, k), 2) / 4.0;
    }
    twisted[static_cast<size_t>(t)] =
      Eigen::AngleAxisd(0.25 * Pi * z, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
      rotation.transpose();
  }
  PolycubeResult twistedResult;
  PCH_CHECK(ComputePolycube(cube, params, twistedResult, {}, twisted).Ok());
  CheckValidPolycube(twistedResult, "twisted frames");
  PCH_CHECK(twistedResult.FrameFitResidual > 1e-3);

  std::vector<Eigen::Matrix3d> tooFew(frames.begin(), frames.end() - 1);
  Status refused = ComputePolycube(cube, params, r, {}, tooFew);
  PCH_CHECK(!refused && refused.Message().find("frames for") != std::string::npos);
  std::vector<Eigen::Matrix3d> scaled(frames);
  scaled[3] *= 2.0;
  refused = ComputePolycube(cube, params, r, {}, scaled);
  PCH_CHECK(!refused && refused.Message().find("not a rotation") != std::string::npos);
}

void TestRing()
{
  // A genus-1 ring: a rectangular cross-section swept around a circle.
  const TetMesh ring = MakeGridMesh(3,
    2,
    32,
    true,
    [](double a, double b, double c)
    {
      const double radius = 1.0 + 0.5 * a;
      const double angle = 2.0 * Pi * c;
      return Eigen::RowVector3d(radius * std::cos(angle), radius * std::sin(angle), 0.4 * b);
    });
  PolycubeParameters params;
  PolycubeResult r;
  const Status status = ComputePolycube(ring, params, r);
  PCH_CHECK(status.Ok());
  if (!status)
  {
    std::cerr << status.Message() << std::endl;
    return;
  }
  CheckValidPolycube(r, "ring");
  // A polycube ring has at least 16 corners (Fang et al. 2016, §1).
  PCH_CHECK(r.CornerCount >= 16);
  PCH_CHECK(r.ChartCount >= 10);
  PCH_CHECK(r.UnflattenedVertexCount == 0);
  // The penalised flattening converged before the snap (the diagnostic reads it).
  std::cout << "ring: flattening deviation " << r.FlattenDeviation << ", halvings "
            << r.FlattenHalvings << std::endl;
  PCH_CHECK(r.FlattenDeviation >= 0.0 && r.FlattenDeviation < 1e-6);

  // The direct solver reaches a valid polycube too.
  params.LinearSolver = PolycubeParameters::LinearSolverType::Direct;
  PolycubeResult direct;
  PCH_CHECK(ComputePolycube(ring, params, direct).Ok());
  CheckValidPolycube(direct, "ring, direct solver");
  PCH_CHECK(direct.CornerCount >= 16);

  // Bit-identical when run again (deterministic reductions, whatever the thread count).
  params.LinearSolver = PolycubeParameters::LinearSolverType::BlockPcg;
  PolycubeResult again;
  PCH_CHECK(ComputePolycube(ring, params, again).Ok());
  PCH_CHECK(again.Positions.rows() == r.Positions.rows() &&
    (again.Positions - r.Positions).cwiseAbs().maxCoeff() == 0.0);
}

void TestSplit()
{
  // Edge and centroid splits on their own: halves keep the orientation and the parent index.
  {
    TetMesh cube = MakeCube(1);
    Tets cells = cube.Cells;
    std::vector<int> parent;
    std::vector<std::array<int, 2>> newVertices;
    // The cube's main diagonal (0,0,0)-(1,1,1) is in all six Kuhn tets.
    SplitTetEdges(8, cells, { { 0, 7 } }, parent, newVertices);
    PCH_CHECK(cells.rows() == 12);
    PCH_CHECK(newVertices.size() == 1);
    Points x = cube.Vertices;
    AppendSplitMidpoints(x, newVertices);
    PCH_CHECK((x.row(8) - Eigen::RowVector3d(0.5, 0.5, 0.5)).norm() < 1e-15);
    double volume = 0.0;
    for (Eigen::Index t = 0; t < cells.rows(); ++t)
    {
      const double v = TetSignedVolume(x, cells, static_cast<int>(t));
      PCH_CHECK(v > 0.0);
      volume += v;
      PCH_CHECK(parent[static_cast<size_t>(t)] ==
        (t < 6 ? static_cast<int>(t) : parent[static_cast<size_t>(t)]));
    }
    PCH_CHECK_NEAR(volume, 1.0, 1e-12);
    std::vector<std::array<int, 4>> corners;
    SplitTetsAtCentroid(9, cells, { 3 }, parent, corners);
    PCH_CHECK(cells.rows() == 15);
    AppendSplitCentroids(x, corners);
    for (Eigen::Index t = 0; t < cells.rows(); ++t)
    {
      PCH_CHECK(TetSignedVolume(x, cells, static_cast<int>(t)) > 0.0);
    }
  }

  // A unit cube capped by a wedge tet on its top face: the cap has two boundary faces in the
  // +Z chart and the cube's top diagonal becomes an interior edge with both ends in +Z, so it
  // must be split before flattening (with the pre-split off).
  TetMesh mesh = MakeCube(1);
  const double h = 0.05;
  mesh.Vertices(5, 2) += h; // (1,0,1)
  mesh.Vertices(6, 2) += h; // (0,1,1)
  PCH_CHECK((mesh.Vertices.row(4) - Eigen::RowVector3d(0, 0, 1)).norm() == 0.0);
  PCH_CHECK((mesh.Vertices.row(7) - Eigen::RowVector3d(1, 1, 1)).norm() == 0.0);
  mesh.Cells.conservativeResize(7, 4);
  mesh.Cells.row(6) << 4, 5, 7, 6;
  if (TetSignedVolume(mesh.Vertices, mesh.Cells, 6) < 0.0)
  {
    std::swap(mesh.Cells(6, 2), mesh.Cells(6, 3));
  }
  PCH_CHECK(TetSignedVolume(mesh.Vertices, mesh.Cells, 6) > 0.0);
  PolycubeParameters params;
  params.PresplitBoundaryEdges = false;
  PolycubeResult r;
  const Status status = ComputePolycube(mesh, params, r);
  PCH_CHECK(status.Ok());
  if (!status)
  {
    std::cerr << status.Message() << std::endl;
    return;
  }
  CheckValidPolycube(r, "capped cube");
  PCH_CHECK(r.SplitEdgeCount + r.SplitTetCount >= 1);
  PCH_CHECK(r.Positions.rows() > mesh.Vertices.rows());
  PCH_CHECK(r.Cells.rows() > mesh.Cells.rows());
  for (Eigen::Index v = mesh.Vertices.rows(); v < r.Positions.rows(); ++v)
  {
    PCH_CHECK(r.OriginalPointId[static_cast<size_t>(v)] == -1);
  }
  for (Eigen::Index v = 0; v < mesh.Vertices.rows(); ++v)
  {
    PCH_CHECK(r.OriginalPointId[static_cast<size_t>(v)] == static_cast<int>(v));
  }
  // The first split is the midpoint of the cube's top diagonal (0,0,1)-(1,1,1).
  PCH_CHECK((r.OriginalPoints.row(8) - Eigen::RowVector3d(0.5, 0.5, 1.0)).norm() < 1e-12);
  for (Eigen::Index t = 0; t < r.Cells.rows(); ++t)
  {
    const int parent = r.OriginalCellId[static_cast<size_t>(t)];
    PCH_CHECK(parent >= 0 && parent < 7);
    PCH_CHECK(t >= 7 || parent == static_cast<int>(t));
  }
}

void TestEnergyGradient()
{
  // The analytic gradient of every term matches central differences.
  TetMesh mesh = MakeCube(2);
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, topology);
  PolycubeEnergy energy(mesh.Vertices, mesh.Cells, topology.BoundaryFaces);
  PolycubeEnergyWeights weights;
  weights.Alignment = 0.7;
  weights.AlignmentEpsilon = 0.05;
  weights.NormalDifference = 0.3;
  weights.Area = 2.0;
  weights.Barrier = 0.5;
  weights.BarrierThreshold = 1.5;
  energy.SetWeights(weights);
  Points x = mesh.Vertices;
  for (Eigen::Index i = 0; i < x.size(); ++i)
  {
    x.data()[i] += 0.03 * std::sin(1.7 * static_cast<double>(i) + 0.3);
  }
  x = 1.1 * x * Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::VectorXd gradient(x.size());
  PolycubeEnergyTerms terms;
  PCH_CHECK(energy.EvaluateDerivatives(x.data(), terms, gradient, nullptr));
  double error = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i)
  {
    const double step = 1e-6;
    Points plus = x;
    Points minus = x;
    plus.data()[i] += step;
    minus.data()[i] -= step;
    PolycubeEnergyTerms a, b;
    energy.Evaluate(plus.data(), a);
    energy.Evaluate(minus.data(), b);
    error = std::max(error, std::abs((a.Total - b.Total) / (2.0 * step) - gradient(i)));
  }
  PCH_CHECK(error < 1e-6);
}

void TestRefusals()
{
  PolycubeParameters params;
  PolycubeResult r;
  {
    TetMesh empty;
    const Status status = ComputePolycube(empty, params, r);
    PCH_CHECK(!status.Ok());
    PCH_CHECK(status.Message().find("empty") != std::string::npos);
    std::cout << "empty: " << status.Message() << std::endl;
  }
  {
    TetMesh cube = MakeCube(2);
    std::swap(cube.Cells(5, 0), cube.Cells(5, 1));
    const Status status = ComputePolycube(cube, params, r);
    PCH_CHECK(!status.Ok());
    PCH_CHECK(status.Message().find("tet 5") != std::string::npos);
    PCH_CHECK(status.Message().find("non-positive volume") != std::string::npos);
    std::cout << "inverted: " << status.Message() << std::endl;
  }
  {
    TetMesh cube = MakeCube(1);
    cube.Cells(2, 3) = 99;
    const Status status = ComputePolycube(cube, params, r);
    PCH_CHECK(!status.Ok());
    PCH_CHECK(status.Message().find("outside") != std::string::npos);
  }
  {
    // Abort through the progress callback.
    const Status status =
      ComputePolycube(MakeCube(2), params, r, [](double fraction) { return fraction < 0.5; });
    PCH_CHECK(!status.Ok());
    PCH_CHECK(status.Message().find("aborted") != std::string::npos);
  }
}

} // namespace

int main(int, char*[])
{
  TestEnergyGradient();
  TestCube();
  TestRotatedCube();
  TestFrameGuidedCube();
  TestRing();
  TestSplit();
  TestRefusals();
  return PCH_TEST_RESULT();
}
