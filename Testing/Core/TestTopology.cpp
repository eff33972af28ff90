// SPDX-License-Identifier: BSD-3-Clause
// Topology of tet meshes: boundary components, genera and beta_1 by Alexander duality, against
// beta_1 from the dual complex (TopologyHomology), on solids generated here: a swept solid torus,
// a swept hollow torus (a torus with a torus-shaped void), and, with TetGen, a ball, a ball with
// a spherical void and a ball with a torus-shaped void. Non-manifold boundaries are refused with
// a message naming the edge or the vertex.
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"
#include "Tetrahedralize.h"
#include "TopologyAdjacency.h"
#include "TopologyBoundary.h"
#include "TopologyHomology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using polycubehex::SurfaceMesh;
using polycubehex::TetMesh;
using polycubehex_test::Icosphere;
using polycubehex_test::Merge;
using polycubehex_test::SweptTorus;
using polycubehex_test::Torus;

namespace
{
struct Expected
{
  int Beta1;
  std::vector<int> Genus; // sorted
};

void CheckTopology(const std::string& name, const TetMesh& mesh, const Expected& expected)
{
  polycubehex::TetAdjacency adjacency;
  const auto built =
    polycubehex::BuildTetAdjacency(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency);
  PCH_CHECK(built.Ok());
  polycubehex::BoundaryTopology boundary;
  const auto status = polycubehex::ComputeBoundaryTopology(mesh.Cells, adjacency, boundary);
  if (!status)
  {
    std::cerr << name << ": " << status.Message() << std::endl;
  }
  PCH_CHECK(status.Ok());
  std::vector<int> genus = boundary.ComponentGenus;
  std::sort(genus.begin(), genus.end());
  polycubehex::CohomologyBasis basis;
  const auto homology = polycubehex::ComputeCohomologyBasis(mesh.Cells, adjacency, true, basis);
  if (!homology)
  {
    std::cerr << name << ": " << homology.Message() << std::endl;
  }
  PCH_CHECK(homology.Ok());
  std::cout << name << ": " << mesh.Cells.rows() << " tets, boundary components " << genus.size()
            << ", beta1 (genus) " << boundary.Beta1 << ", beta1 (homology) " << basis.Beta1
            << ", beta2 " << boundary.Beta2 << "; after collapse " << basis.RemainingFaceCount
            << " faces in " << basis.SheetCount << " sheets, " << basis.RelationCount
            << " seam relations" << std::endl;
  PCH_CHECK(boundary.Beta1 == expected.Beta1);
  PCH_CHECK(basis.Beta1 == expected.Beta1);
  PCH_CHECK(genus == expected.Genus);
  PCH_CHECK(static_cast<int>(basis.Cocycles.size()) == expected.Beta1);
  for (const auto& cocycle : basis.Cocycles)
  {
    PCH_CHECK(polycubehex::IsCocycle(mesh.Cells, adjacency, cocycle));
  }
}

bool Tetrahedralized(const SurfaceMesh& surface, TetMesh& mesh)
{
  std::string switches;
  polycubehex::TetrahedralizeParameters params;
  const auto status = polycubehex::Tetrahedralize(surface, params, mesh, switches);
  if (!status)
  {
    std::cerr << "Tetrahedralize: " << status.Message() << std::endl;
  }
  return status.Ok();
}

bool FailsMentioning(const TetMesh& mesh, const std::string& words)
{
  polycubehex::TetAdjacency adjacency;
  if (!polycubehex::BuildTetAdjacency(
        static_cast<int>(mesh.Vertices.rows()), mesh.Cells, adjacency))
  {
    return false;
  }
  polycubehex::BoundaryTopology boundary;
  const auto status = polycubehex::ComputeBoundaryTopology(mesh.Cells, adjacency, boundary);
  std::cout << "refused: " << status.Message() << std::endl;
  return !status.Ok() && status.Message().find(words) != std::string::npos;
}
} // namespace

int main(int, char*[])
{
  CheckTopology("swept solid torus", SweptTorus(2.0, 0.5, 0, 3, 24), { 1, { 1 } });
  CheckTopology("swept hollow torus", SweptTorus(2.0, 0.8, 2, 5, 32), { 2, { 1, 1 } });
  CheckTopology("swept thin torus", SweptTorus(2.0, 0.5, 0, 1, 8), { 1, { 1 } });

  TetMesh mesh;
  if (Tetrahedralized(Icosphere(2, 1.0), mesh))
  {
    CheckTopology("ball", mesh, { 0, { 0 } });
  }
  if (Tetrahedralized(Merge(Icosphere(3, 2.0), Icosphere(2, 1.0)), mesh))
  {
    CheckTopology("ball with a spherical void", mesh, { 0, { 0, 0 } });
  }
  if (Tetrahedralized(Merge(Icosphere(3, 2.0), Torus(1.0, 0.35, 32, 12)), mesh))
  {
    CheckTopology("ball with a torus-shaped void", mesh, { 1, { 0, 1 } });
  }
  if (Tetrahedralized(Merge(Torus(2.0, 0.8, 48, 16), Torus(2.0, 0.4, 40, 12)), mesh))
  {
    CheckTopology("hollow torus (TetGen)", mesh, { 2, { 1, 1 } });
  }

  // Two tets sharing only a vertex, then only an edge: non-manifold boundaries.
  TetMesh pinched;
  pinched.Vertices.resize(7, 3);
  pinched.Vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
  pinched.Cells.resize(2, 4);
  pinched.Cells << 0, 1, 2, 3, 0, 4, 6, 5;
  PCH_CHECK(FailsMentioning(pinched, "vertex 0"));
  TetMesh hinge;
  hinge.Vertices.resize(6, 3);
  hinge.Vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1;
  hinge.Cells.resize(2, 4);
  hinge.Cells << 0, 1, 2, 3, 0, 1, 5, 4;
  PCH_CHECK(FailsMentioning(hinge, "edge (0, 1)"));
  return PCH_TEST_RESULT();
}
