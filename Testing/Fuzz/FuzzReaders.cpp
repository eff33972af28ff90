// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target for the MEDIT (.mesh) and OFF (.off) parsers of the core: any byte string
// must give either a mesh whose indices are all in range or a failure with a message, never a
// crash, a hang or a sanitizer report. The first byte chooses the parser, so one corpus serves
// both.
#include "MeditFormat.h"
#include "OffFormat.h"

#include <cstdint>
#include <cstdlib>
#include <string>

namespace
{
template<typename Cells>
void CheckIndices(const Cells& cells, long vertexCount)
{
  if (cells.size() > 0 && (cells.minCoeff() < 0 || cells.maxCoeff() >= vertexCount))
  {
    std::abort(); // a parser accepted an index out of range
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 0)
  {
    polycubehex::MeditMesh mesh;
    const polycubehex::Status status = polycubehex::ReadMedit(text, mesh);
    if (status)
    {
      const long vertexCount = static_cast<long>(mesh.Vertices.rows());
      CheckIndices(mesh.EdgeCells, vertexCount);
      CheckIndices(mesh.TriangleCells, vertexCount);
      CheckIndices(mesh.QuadCells, vertexCount);
      CheckIndices(mesh.TetCells, vertexCount);
      CheckIndices(mesh.HexCells, vertexCount);
    }
    else if (status.Message().empty())
    {
      std::abort(); // a failure must say why
    }
  }
  else
  {
    polycubehex::OffMesh mesh;
    const polycubehex::Status status = polycubehex::ReadOff(text, mesh);
    if (!status && status.Message().empty())
    {
      std::abort();
    }
    if (status)
    {
      for (int index : mesh.FaceIndices)
      {
        if (index < 0 || index >= mesh.Vertices.rows())
        {
          std::abort();
        }
      }
    }
  }
  return 0;
}
