// SPDX-License-Identifier: BSD-3-Clause
// Object File Format (`.off`) polygon surfaces, as shipped with libigl's and Princeton's data.
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <string>
#include <vector>

namespace polycubehex
{

/// A polygon surface: face f has the vertex indices FaceIndices[FaceOffsets[f] .. FaceOffsets[f+1]).
struct OffMesh
{
  Points Vertices;                 ///< #V by 3
  std::vector<int> FaceOffsets{ 0 }; ///< #F + 1 offsets into FaceIndices
  std::vector<int> FaceIndices;    ///< 0-based vertex indices, face after face
};

/// Parses OFF text: an optional header `OFF` (also `COFF`, `NOFF`, `CNOFF`, whose extra
/// per-vertex values are skipped), the counts `#V #F #E`, the vertices, then each face as
/// `n i_1 ... i_n` followed by optional colour values up to the end of its line. Malformed
/// text gives a failure naming the entity (`vertex 12`, `face 7`).
Status ReadOff(const std::string& text, OffMesh& mesh);
Status ReadOffFile(const std::string& path, OffMesh& mesh);

} // namespace polycubehex
