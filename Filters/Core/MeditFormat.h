// SPDX-License-Identifier: BSD-3-Clause
// MEDIT `.mesh` files (INRIA's ASCII mesh format, as written by TetGen, MMG and cinolib).
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace polycubehex
{

using Edges = Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// The elements of a MEDIT file that PolycubeHex uses, with 0-based indices. Element order
/// is VTK's: MEDIT hexahedra already use VTK's node order (shared/DESIGN.md section 2).
struct MeditMesh
{
  Points Vertices;      ///< #V by 3
  Edges EdgeCells;      ///< #E by 2
  Triangles TriangleCells; ///< #F by 3
  Quads QuadCells;      ///< #Q by 4
  Tets TetCells;        ///< #T by 4
  Hexes HexCells;       ///< #H by 8
};

/// Parses MEDIT text. Keywords Vertices, Edges, Triangles, Quadrilaterals, Tetrahedra and
/// Hexahedra are read; their reference numbers are ignored; MeshVersionFormatted, Dimension
/// (must be 3) and End are understood; any other keyword is skipped with a warning appended
/// to `warnings` (if given). The layout is free across lines and `#` starts a comment.
/// A malformed file gives a failure naming the keyword and the entity.
Status ReadMedit(const std::string& text, MeditMesh& mesh, std::vector<std::string>* warnings = nullptr);

/// Reads the file at `path` with ReadMedit.
Status ReadMeditFile(
  const std::string& path, MeditMesh& mesh, std::vector<std::string>* warnings = nullptr);

/// Writes `mesh` as MEDIT text (MeshVersionFormatted 2, full double precision, references 0).
Status WriteMedit(std::ostream& out, const MeditMesh& mesh);
Status WriteMeditFile(const std::string& path, const MeditMesh& mesh);

} // namespace polycubehex
