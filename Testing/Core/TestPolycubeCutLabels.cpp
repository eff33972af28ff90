// SPDX-License-Identifier: BSD-3-Clause
// Labels of a closed-form polycube across a cut's loop (MatchLabelsAcrossCuts,
// CleanUpCutMeshLabels). The boundary of a cube is opened along a loop of its edges: every face on
// one side of the loop uses copies of the loop's vertices, moved by a translation (the cut's
// t_c, transition the identity).
//  - A loop along the creases (the rim of the top face): across every loop edge the labels differ
//    and both agree with their normals. That is a chart boundary of M along the loop, and no face
//    may be forced to its partner's label: it would be a one-face chart perpendicular to its label
//    (the kitten's closed-form polycube had six such, and 56 vertices left off their planes).
//  - A loop across the creases (around the middle): a face next to the loop labelled like the
//    neighbouring side, as a crease crossing the loop inside an edge leaves it, takes its
//    partner's label back.
//  - The same loop with the upper half turned by 90 degrees about z (a twisted cut): a small
//    chart next to the loop that carries its lower partner's label untransformed (as a collapse
//    relabelling may leave it) is a mismatch, not part of its partner's chart, and the clean-up
//    gives every face its own side's label back (on fertility, gluing such charts across the
//    cut folded 373 faces).
#include "PolycubeCharts.h"
#include "PolycubeCutMesh.h"
#include "TetGeometry.h"

#include "TestAssert.h"
#include "TestMeshGenerators.h"

#include <cmath>
#include <iostream>
#include <vector>

using namespace polycubehex;

namespace
{
/// The boundary of a cube opened along the loop of boundary vertices for which `onLoop` holds;
/// the faces for which `plusFace` holds (by centroid) use copies of the loop vertices, and every
/// vertex of theirs is moved by `shift`.
struct OpenedCube
{
  Points X;
  Triangles Faces;
  Triangles Adjacency;
  std::vector<int> Identity;
  std::vector<CopyRelation> Copies;
  std::vector<Eigen::Matrix3i> Transitions{ Eigen::Matrix3i::Identity() };
};

template <typename OnLoop, typename PlusFace>
OpenedCube OpenCube(int n,
  OnLoop onLoop,
  PlusFace plusFace,
  const Eigen::Vector3d& shift,
  const Eigen::Matrix3i& turn = Eigen::Matrix3i::Identity())
{
  const TetMesh cube = polycubehex_test::CubeGrid(n);
  TetTopology topology;
  const int vertexCount = static_cast<int>(cube.Vertices.rows());
  ComputeTetTopology(vertexCount, cube.Cells, topology);
  OpenedCube out;
  out.Faces = topology.BoundaryFaces;
  std::vector<int> copyOf(static_cast<size_t>(vertexCount), -1);
  std::vector<bool> moved(static_cast<size_t>(vertexCount), false);
  out.Identity.resize(static_cast<size_t>(vertexCount));
  for (int v = 0; v < vertexCount; ++v)
  {
    out.Identity[static_cast<size_t>(v)] = v;
  }
  std::vector<Eigen::Vector3d> extra;
  for (Eigen::Index f = 0; f < out.Faces.rows(); ++f)
  {
    const Eigen::Vector3d centroid = (cube.Vertices.row(out.Faces(f, 0)) +
      cube.Vertices.row(out.Faces(f, 1)) + cube.Vertices.row(out.Faces(f, 2))).transpose() / 3.0;
    if (!plusFace(centroid))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const int v = out.Faces(f, k);
      if (!onLoop(cube.Vertices.row(v).transpose().eval()))
      {
        moved[static_cast<size_t>(v)] = true;
        continue;
      }
      if (copyOf[static_cast<size_t>(v)] < 0)
      {
        copyOf[static_cast<size_t>(v)] = vertexCount + static_cast<int>(extra.size());
        extra.push_back(turn.cast<double>() * cube.Vertices.row(v).transpose() + shift);
        out.Identity.push_back(v);
        out.Copies.push_back({ v, copyOf[static_cast<size_t>(v)], 0 });
      }
      out.Faces(f, k) = copyOf[static_cast<size_t>(v)];
    }
  }
  out.X.resize(vertexCount + static_cast<Eigen::Index>(extra.size()), 3);
  for (int v = 0; v < vertexCount; ++v)
  {
    out.X.row(v) = cube.Vertices.row(v);
    if (moved[static_cast<size_t>(v)])
    {
      out.X.row(v) = (turn.cast<double>() * cube.Vertices.row(v).transpose() + shift).transpose();
    }
  }
  for (size_t i = 0; i < extra.size(); ++i)
  {
    out.X.row(vertexCount + static_cast<Eigen::Index>(i)) = extra[i].transpose();
  }
  out.Transitions = { turn };
  out.Adjacency = ComputeFaceAdjacency(
    static_cast<int>(out.X.rows()), IdentityFaces(out.Faces, out.Identity));
  return out;
}

/// The clean-up settings of the closed-form polycube (ComputePolycube): no boundary-turn rule,
/// since a chart's boundary loops are broken where they cross a cut.
PolycubeChartCleanup CutMeshCleanup()
{
  PolycubeChartCleanup cleanup;
  cleanup.MinBoundaryTurns = 0;
  return cleanup;
}

int Mismatches(const OpenedCube& cube, const std::vector<int>& labels)
{
  int count = 0;
  for (const auto& pair : FacesAcrossCuts(cube.Faces, cube.Adjacency, cube.Copies))
  {
    count += TransformLabel(cube.Transitions[static_cast<size_t>(pair[2])],
               labels[static_cast<size_t>(pair[0])]) != labels[static_cast<size_t>(pair[1])]
      ? 1
      : 0;
  }
  return count;
}

/// Charts of the cut mesh itself (connectivity of M_c, as the flattening sees them) with fewer
/// than three faces.
int SmallCutMeshCharts(const OpenedCube& cube, const std::vector<int>& labels)
{
  const PolycubeCharts charts = ComputePolycubeCharts(cube.X,
    cube.Faces,
    ComputeFaceAdjacency(static_cast<int>(cube.X.rows()), cube.Faces),
    labels);
  std::vector<int> tally(static_cast<size_t>(charts.Count()), 0);
  for (int c : charts.FaceChart)
  {
    ++tally[static_cast<size_t>(c)];
  }
  int small = 0;
  for (int t : tally)
  {
    small += t < 3 ? 1 : 0;
  }
  return small;
}

void TestLoopAlongCreases()
{
  // The rim of the top face z = 1; the top is the plus side, lifted by the translation.
  const OpenedCube cube = OpenCube(
    4,
    [](const Eigen::Vector3d& p)
    { return p.z() > 0.999 && (std::abs(p.x()) > 0.999 || std::abs(p.y()) > 0.999); },
    [](const Eigen::Vector3d& c) { return c.z() > 0.999; },
    Eigen::Vector3d(0.1, -0.2, 0.3));
  const std::vector<int> normalLabels = PolycubeFaceLabels(cube.X, cube.Faces);
  const auto across = FacesAcrossCuts(cube.Faces, cube.Adjacency, cube.Copies);
  PCH_CHECK(across.size() == 16); // 4 edges of the rim, 4 segments each
  PCH_CHECK(Mismatches(cube, normalLabels) == 16);
  PCH_CHECK(SmallCutMeshCharts(cube, normalLabels) == 0);

  // No face can give way without becoming a one-face chart across its normal.
  std::vector<int> labels = normalLabels;
  const int matched =
    MatchLabelsAcrossCuts(across, cube.X, cube.Faces, cube.Adjacency, cube.Transitions, labels);
  std::cout << "loop along creases: matching changed " << matched << " faces, "
            << SmallCutMeshCharts(cube, labels) << " charts of M_c with < 3 faces\n";
  PCH_CHECK(matched == 0);
  PCH_CHECK(labels == normalLabels);

  labels = normalLabels;
  CleanUpCutMeshLabels(
    cube.X, cube.Faces, cube.Adjacency, cube.Copies, cube.Transitions, CutMeshCleanup(), labels);
  PCH_CHECK(labels == normalLabels);
  PCH_CHECK(SmallCutMeshCharts(cube, labels) == 0);
}

void TestCreaseCrossingInsideAnEdge()
{
  // The loop z = 0 around the middle crosses the four vertical creases at vertices; the upper
  // half is the plus side.
  const OpenedCube cube = OpenCube(
    4,
    [](const Eigen::Vector3d& p)
    {
      return std::abs(p.z()) < 1e-9 && (std::abs(p.x()) > 0.999 || std::abs(p.y()) > 0.999);
    },
    [](const Eigen::Vector3d& c) { return c.z() > 0.0; },
    Eigen::Vector3d(0.0, 0.0, 0.5));
  const std::vector<int> normalLabels = PolycubeFaceLabels(cube.X, cube.Faces);
  const auto across = FacesAcrossCuts(cube.Faces, cube.Adjacency, cube.Copies);
  PCH_CHECK(across.size() == 16);
  PCH_CHECK(Mismatches(cube, normalLabels) == 0);
  // A plus face on +X next to the loop and to the +Y side takes +Y, as when the crease between
  // +X and +Y crossed the loop inside an edge.
  int moved = -1;
  for (const auto& pair : across)
  {
    const int plus = pair[1];
    if (normalLabels[static_cast<size_t>(plus)] != 0)
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (cube.X(cube.Faces(plus, k), 1) > 0.999)
      {
        moved = plus;
      }
    }
  }
  PCH_CHECK(moved >= 0);
  std::vector<int> labels = normalLabels;
  labels[static_cast<size_t>(moved)] = 2;
  PCH_CHECK(Mismatches(cube, labels) == 1);
  std::vector<int> matchedLabels = labels;
  const int matched = MatchLabelsAcrossCuts(
    across, cube.X, cube.Faces, cube.Adjacency, cube.Transitions, matchedLabels);
  PCH_CHECK(matched == 1);
  PCH_CHECK(matchedLabels == normalLabels);
  CleanUpCutMeshLabels(
    cube.X, cube.Faces, cube.Adjacency, cube.Copies, cube.Transitions, CutMeshCleanup(), labels);
  PCH_CHECK(Mismatches(cube, labels) == 0);
  PCH_CHECK(labels == normalLabels);
}
void TestTwistedCut()
{
  // The loop z = 0; the upper half is the plus side, turned by 90 degrees about z: +X -> +Y.
  Eigen::Matrix3i turn;
  turn << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const OpenedCube cube = OpenCube(
    4,
    [](const Eigen::Vector3d& p)
    {
      return std::abs(p.z()) < 1e-9 && (std::abs(p.x()) > 0.999 || std::abs(p.y()) > 0.999);
    },
    [](const Eigen::Vector3d& c) { return c.z() > 0.0; },
    Eigen::Vector3d(0.0, 0.0, 0.5),
    turn);
  const std::vector<int> normalLabels = PolycubeFaceLabels(cube.X, cube.Faces);
  const auto across = FacesAcrossCuts(cube.Faces, cube.Adjacency, cube.Copies);
  PCH_CHECK(across.size() == 16);
  PCH_CHECK(Mismatches(cube, normalLabels) == 0);
  // A plus face next to the loop, away from the vertical creases, and its plus neighbour away
  // from the loop take the label of the minus face across the loop, untransformed.
  std::vector<int> labels = normalLabels;
  int inner = -1;
  for (const auto& pair : across)
  {
    const int minus = pair[0];
    const int plus = pair[1];
    for (int e = 0; e < 3 && inner < 0; ++e)
    {
      const int g = cube.Adjacency(plus, e);
      bool touchesLoop = false;
      for (const auto& other : across)
      {
        touchesLoop = touchesLoop || other[1] == g;
      }
      if (g >= 0 && !touchesLoop && normalLabels[static_cast<size_t>(g)] == normalLabels[static_cast<size_t>(plus)])
      {
        inner = g;
        labels[static_cast<size_t>(plus)] = normalLabels[static_cast<size_t>(minus)];
        labels[static_cast<size_t>(g)] = normalLabels[static_cast<size_t>(minus)];
      }
    }
    if (inner >= 0)
    {
      break;
    }
  }
  PCH_CHECK(inner >= 0);
  PCH_CHECK(Mismatches(cube, labels) >= 1);
  CleanUpCutMeshLabels(
    cube.X, cube.Faces, cube.Adjacency, cube.Copies, cube.Transitions, CutMeshCleanup(), labels);
  int folded = 0;
  for (size_t f = 0; f < labels.size(); ++f)
  {
    folded += labels[f] != normalLabels[f] ? 1 : 0;
  }
  std::cout << "twisted cut: " << Mismatches(cube, labels) << " mismatches, " << folded
            << " faces off their normal's label after the clean-up\n";
  PCH_CHECK(Mismatches(cube, labels) == 0);
  PCH_CHECK(folded == 0);
}
} // namespace

int main()
{
  TestLoopAlongCreases();
  TestCreaseCrossingInsideAnEdge();
  TestTwistedCut();
  return PCH_TEST_RESULT();
}
