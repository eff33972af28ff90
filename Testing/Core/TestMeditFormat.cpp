// SPDX-License-Identifier: BSD-3-Clause
// The MEDIT parser: free layout, skipped keywords, and a clear error for every malformed file.
#include "MeditFormat.h"
#include "TestAssert.h"

#include <sstream>

using polycubehex::MeditMesh;
using polycubehex::ReadMedit;

namespace
{
// A unit tetrahedron and a unit cube hexahedron sharing no vertex; `Dimension` and `3` on
// separate lines as in cinolib's files, an unsupported keyword, comments, wrapped lines.
const char* const ValidText = R"(MeshVersionFormatted 1
# a comment
Dimension
3
Vertices
12
0 0 0 1   1 0 0 1   0 1 0 1   0 0 1 1
2 0 0 0  3 0 0 0  3 1 0 0  2 1 0 0
2 0 1 0  3 0 1 0  3 1 1 0  2 1 1 0
Corners 2 1 2
Triangles 1
1 2 3 7
Tetrahedra
1
1 2 3 4 0
Hexahedra 1
5 6 7 8 9 10 11 12 0
End
)";

bool FailsMentioning(const std::string& text, const std::string& words)
{
  MeditMesh mesh;
  const polycubehex::Status status = ReadMedit(text, mesh);
  if (status)
  {
    std::cerr << "accepted a malformed file; expected an error about '" << words << "'\n";
    return false;
  }
  std::cout << "refused as expected: " << status.Message() << "\n";
  return status.Message().find(words) != std::string::npos;
}

std::string Replace(std::string text, const std::string& from, const std::string& to)
{
  text.replace(text.find(from), from.size(), to);
  return text;
}
} // namespace

int main(int, char*[])
{
  // A valid file, in free layout.
  {
    MeditMesh mesh;
    std::vector<std::string> warnings;
    const polycubehex::Status status = ReadMedit(ValidText, mesh, &warnings);
    PCH_CHECK(status.Ok());
    PCH_CHECK(mesh.Vertices.rows() == 12);
    PCH_CHECK(mesh.TetCells.rows() == 1 && mesh.HexCells.rows() == 1);
    PCH_CHECK(mesh.TriangleCells.rows() == 1);
    PCH_CHECK(mesh.TetCells(0, 3) == 3); // 1-based in the file
    PCH_CHECK(mesh.HexCells(0, 0) == 4 && mesh.HexCells(0, 7) == 11);
    PCH_CHECK_NEAR(mesh.Vertices(6, 1), 1.0, 0.0);
    PCH_CHECK(warnings.size() == 1 && warnings[0].find("Corners") != std::string::npos);

    // Written and read again, nothing changes.
    std::ostringstream out;
    PCH_CHECK(polycubehex::WriteMedit(out, mesh).Ok());
    MeditMesh again;
    PCH_CHECK(ReadMedit(out.str(), again).Ok());
    PCH_CHECK(again.Vertices == mesh.Vertices);
    PCH_CHECK(again.TetCells == mesh.TetCells && again.HexCells == mesh.HexCells);
    PCH_CHECK(again.TriangleCells == mesh.TriangleCells);
  }

  // Malformed files: each refused with the keyword and the entity named.
  const std::string valid = ValidText;
  PCH_CHECK(FailsMentioning("", "empty"));
  PCH_CHECK(FailsMentioning("solid foo\nfacet normal 0 0 1\n", "MeshVersionFormatted"));
  PCH_CHECK(FailsMentioning(valid.substr(0, valid.find("1 2 3 4 0") + 5), "Tetrahedra"));
  PCH_CHECK(FailsMentioning(valid.substr(0, valid.find("3 1 1 0")), "Vertices: declares 12"));
  PCH_CHECK(FailsMentioning(valid.substr(0, valid.find("11 12 0")), "Hexahedra: "));
  PCH_CHECK(FailsMentioning(Replace(valid, "Tetrahedra\n1\n", "Tetrahedra\n2\n"), "tetrahedron 2"));
  PCH_CHECK(FailsMentioning(Replace(valid, "Tetrahedra\n1\n", "Tetrahedra\n99999999\n"), "declares"));
  PCH_CHECK(FailsMentioning(Replace(valid, "1 2 3 4 0", "1 2 3 40 0"), "references vertex 40"));
  PCH_CHECK(FailsMentioning(Replace(valid, "1 2 3 4 0", "1 2 3 0 0"), "tetrahedron 1 of 1"));
  PCH_CHECK(FailsMentioning(Replace(valid, "1 2 3 4 0", "1 2 3 -4 0"), "1-based"));
  PCH_CHECK(FailsMentioning(Replace(valid, "0 1 0 1", "0 nan 0 1"), "vertex 3 of 12"));
  PCH_CHECK(FailsMentioning(Replace(valid, "0 1 0 1", "0 inf 0 1"), "non-finite"));
  PCH_CHECK(FailsMentioning(Replace(valid, "Vertices\n12", "Vertices\n-3"), "Vertices"));
  PCH_CHECK(FailsMentioning(Replace(valid, "Dimension\n3", "Dimension\n2"), "Dimension"));
  PCH_CHECK(FailsMentioning(Replace(valid, "Hexahedra 1", "Hexahedra 1.5"), "Hexahedra"));
  return PCH_TEST_RESULT();
}
