// SPDX-License-Identifier: BSD-3-Clause
// ComputePolycubeCreases (PolycubeCreases.h): a cube's surface has 12 creases, each a monotone
// path from corner to corner along the axis of neither of its charts; pushing one crease vertex
// past the end of its edge makes that crease, and only that one, turn back by exactly the
// overshoot; shaving it gives the faces of its two charts around the vertex it runs back to
// one label, and leaves a monotone cube alone. CreaseStretch: a cube's edges keep their length
// (1); squashing the cube along z to a tenth leaves the four vertical edges at 0.1, the only
// squashed ones.
#include "PolycubeCharts.h"
#include "PolycubeCreases.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"

#include <cmath>
#include <iostream>

using namespace polycubehex;

namespace
{
bool IsCubeCorner(const Points& x, int v)
{
  return (x.row(v).cwiseAbs().array() > 1.0 - 1e-12).all();
}
} // namespace

int main()
{
  const int n = 2;
  TetMesh cube = polycubehex_test::CubeGrid(n);
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(cube.Vertices.rows()), cube.Cells, topology);
  const Triangles& faces = topology.BoundaryFaces;
  const Triangles adjacency = ComputeFaceAdjacency(static_cast<int>(cube.Vertices.rows()), faces);
  const PolycubeCharts charts = ComputePolycubeCharts(
    cube.Vertices, faces, adjacency, PolycubeFaceLabels(cube.Vertices, faces));
  PCH_CHECK(charts.Count() == 6);

  const std::vector<PolycubeCrease> creases =
    ComputePolycubeCreases(cube.Vertices, faces, adjacency, charts);
  PCH_CHECK(creases.size() == 12);
  for (const PolycubeCrease& crease : creases)
  {
    const int axisA = charts.ChartLabel[static_cast<size_t>(crease.ChartA)] / 2;
    const int axisB = charts.ChartLabel[static_cast<size_t>(crease.ChartB)] / 2;
    PCH_CHECK(axisA != axisB && crease.Axis != axisA && crease.Axis != axisB);
    PCH_CHECK(static_cast<int>(crease.Vertices.size()) == n + 1);
    PCH_CHECK(IsCubeCorner(cube.Vertices, crease.Vertices.front()));
    PCH_CHECK(IsCubeCorner(cube.Vertices, crease.Vertices.back()));
    PCH_CHECK(std::abs(crease.NetLength - 2.0) < 1e-12);
    PCH_CHECK(crease.TurnBack < 1e-12);
  }
  int above = -1;
  PCH_CHECK(MaxCreaseTurnBack(creases, 1e-9, &above) < 1e-12 && above == 0);

  // Stretch: the cube against itself, then squashed along z (the charts keep their labels).
  double smallest = 0.0;
  PCH_CHECK(CountSquashedCreases(cube.Vertices, creases, 0.25, 0.0, &smallest) == 0);
  PCH_CHECK(std::abs(smallest - 1.0) < 1e-12);
  Points squashed = cube.Vertices;
  squashed.col(2) *= 0.1;
  const std::vector<PolycubeCrease> flat =
    ComputePolycubeCreases(squashed, faces, adjacency, charts);
  PCH_CHECK(flat.size() == 12);
  for (const PolycubeCrease& crease : flat)
  {
    const double expected = crease.Axis == 2 ? 0.1 : 1.0;
    PCH_CHECK(std::abs(CreaseStretch(cube.Vertices, crease) - expected) < 1e-12);
  }
  const int squashedCount = CountSquashedCreases(cube.Vertices, flat, 0.25, 0.0, &smallest);
  std::cout << "squashed creases " << squashedCount << ", smallest stretch " << smallest
            << std::endl;
  PCH_CHECK(squashedCount == 4);
  PCH_CHECK(std::abs(smallest - 0.1) < 1e-12);
  // Creases shorter in the input than the length asked for are not counted.
  PCH_CHECK(CountSquashedCreases(cube.Vertices, flat, 0.25, 2.5, &smallest) == 0);
  PCH_CHECK(smallest == 1.0);
  // One crease at a time: the four along z are squashed, at 0.1, and only while long enough.
  int flagged = 0;
  for (const PolycubeCrease& crease : flat)
  {
    double stretch = -1.0;
    const bool isSquashed = IsSquashedCrease(cube.Vertices, crease, 0.25, 0.0, &stretch);
    PCH_CHECK(isSquashed == (crease.Axis == 2));
    PCH_CHECK(std::abs(stretch - (crease.Axis == 2 ? 0.1 : 1.0)) < 1e-12);
    PCH_CHECK(!IsSquashedCrease(cube.Vertices, crease, 0.25, 2.5));
    flagged += isSquashed ? 1 : 0;
  }
  PCH_CHECK(flagged == 4);
  // A closed path has no net length to compare: never squashed.
  PolycubeCrease loop = flat.front();
  loop.Vertices.push_back(loop.Vertices.front());
  PCH_CHECK(!IsSquashedCrease(cube.Vertices, loop, 0.25, 0.0));

  // The middle vertex of the crease x = y = 1 goes to z = 1.3, 0.3 past the corner at z = 1:
  // the path z = -1, 1.3, 1 runs 2.6 for a net 2, so it turns back 0.3.
  Points moved = cube.Vertices;
  int middle = -1;
  for (Eigen::Index v = 0; v < moved.rows(); ++v)
  {
    if (std::abs(moved(v, 0) - 1.0) < 1e-12 && std::abs(moved(v, 1) - 1.0) < 1e-12 &&
      std::abs(moved(v, 2)) < 1e-12)
    {
      middle = static_cast<int>(v);
    }
  }
  PCH_CHECK(middle >= 0);
  moved(middle, 2) = 1.3;
  const std::vector<PolycubeCrease> bent = ComputePolycubeCreases(moved, faces, adjacency, charts);
  PCH_CHECK(bent.size() == 12);
  const double largest = MaxCreaseTurnBack(bent, 1e-9, &above);
  std::cout << "turn-back after the move " << largest << " on " << above << " crease(s)"
            << std::endl;
  PCH_CHECK(std::abs(largest - 0.3) < 1e-12);
  PCH_CHECK(above == 1);
  for (const PolycubeCrease& crease : bent)
  {
    if (crease.TurnBack > 1e-9)
    {
      PCH_CHECK(crease.Axis == 2);
      PCH_CHECK(crease.Vertices[1] == middle);
      PCH_CHECK(std::abs(crease.NetLength - 2.0) < 1e-12);
    }
  }

  // Shaving: the monotone cube has nothing to shave; on the bent one the corner the crease runs
  // back to (z = 1, behind z = 1.3) has the faces of the crease's two charts around it, which
  // all take one of the two labels.
  std::vector<int> labels = PolycubeFaceLabels(cube.Vertices, faces);
  const std::vector<int> original = labels;
  PCH_CHECK(ShaveTurnedBackCreases(cube.Vertices, faces, charts, creases, 1e-9, labels) == 0);
  PCH_CHECK(labels == original);
  const int shaved = ShaveTurnedBackCreases(moved, faces, charts, bent, 1e-9, labels);
  std::cout << "shaved " << shaved << " face(s)" << std::endl;
  PCH_CHECK(shaved > 0);
  for (const PolycubeCrease& crease : bent)
  {
    if (crease.TurnBack <= 1e-9)
    {
      continue;
    }
    const int corner = crease.Vertices.back();
    int labelSeen = -1;
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
    {
      const int chart = charts.FaceChart[static_cast<size_t>(f)];
      const bool atCorner = (faces.row(f).array() == corner).any();
      if (atCorner && (chart == crease.ChartA || chart == crease.ChartB))
      {
        PCH_CHECK(labelSeen < 0 || labels[static_cast<size_t>(f)] == labelSeen);
        labelSeen = labels[static_cast<size_t>(f)];
      }
    }
    PCH_CHECK(labelSeen == charts.ChartLabel[static_cast<size_t>(crease.ChartA)] ||
      labelSeen == charts.ChartLabel[static_cast<size_t>(crease.ChartB)]);
  }
  return 0;
}
