// SPDX-License-Identifier: BSD-3-Clause
// The OFF parser: headers, polygons, colours, and a clear error for malformed files.
#include "OffFormat.h"
#include "TestAssert.h"

#include <string>

using polycubehex::OffMesh;
using polycubehex::ReadOff;

namespace
{
const char* const Tetrahedron = R"(OFF
# a tetrahedron, one face with a colour
4 4 6
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3 255 0 0
3 1 2 3
3 0 3 2
)";

bool FailsMentioning(const std::string& text, const std::string& words)
{
  OffMesh mesh;
  const polycubehex::Status status = ReadOff(text, mesh);
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

int main(int argc, char* argv[])
{
  {
    OffMesh mesh;
    PCH_CHECK(ReadOff(Tetrahedron, mesh).Ok());
    PCH_CHECK(mesh.Vertices.rows() == 4);
    PCH_CHECK(mesh.FaceOffsets.size() == 5 && mesh.FaceIndices.size() == 12);
    PCH_CHECK(mesh.FaceIndices[3] == 0 && mesh.FaceIndices[5] == 3);
  }
  {
    // A quad and a header-less file.
    OffMesh mesh;
    PCH_CHECK(ReadOff("4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", mesh).Ok());
    PCH_CHECK(mesh.FaceOffsets.size() == 2 && mesh.FaceOffsets[1] == 4);
  }
  if (argc > 1)
  {
    OffMesh mesh;
    PCH_CHECK(polycubehex::ReadOffFile(std::string(argv[1]) + "/fertility.off", mesh).Ok());
    PCH_CHECK(mesh.Vertices.rows() == 4494);
    PCH_CHECK(mesh.FaceOffsets.size() == 9001);
  }
  const std::string valid = Tetrahedron;
  PCH_CHECK(FailsMentioning("", "empty"));
  PCH_CHECK(FailsMentioning(valid.substr(0, valid.find("0 0 1")), "vertex 3 of 4"));
  PCH_CHECK(FailsMentioning(valid.substr(0, valid.find("3 1 2 3")), "face 2 of 4"));
  PCH_CHECK(FailsMentioning(Replace(valid, "3 1 2 3", "3 1 2 7"), "references vertex 7"));
  PCH_CHECK(FailsMentioning(Replace(valid, "3 1 2 3", "3 1 2 -1"), "face 2"));
  PCH_CHECK(FailsMentioning(Replace(valid, "3 1 2 3", "5 1 2 3"), "declares 5"));
  PCH_CHECK(FailsMentioning(Replace(valid, "1 0 0\n", "nan 0 0\n"), "non-finite"));
  PCH_CHECK(FailsMentioning(Replace(valid, "4 4 6", "4 x 6"), "counts"));
  PCH_CHECK(FailsMentioning(Replace(valid, "4 4 6", "4 4000000 6"), "more than the file"));
  // Found by the fuzzer (FuzzReaders): a vertex count near 2^63 overflowed a size check.
  PCH_CHECK(FailsMentioning("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n9223372036854775807 0 1 2\n",
    "declares 9223372036854775807 vertices"));
  return PCH_TEST_RESULT();
}
