// SPDX-License-Identifier: BSD-3-Clause
// Conversions between VTK data sets and the core's mesh types. Private to the module: the
// core types carry Eigen, which must never reach a wrapped header.
#ifndef PolycubeHexConversion_h
#define PolycubeHexConversion_h

#include "MeshTypes.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkDataSet;
class vtkPointSet;
class vtkPoints;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace polycubehex
{

/// Copies the points of any point set into a #V by 3 matrix.
Points ToPoints(vtkPoints* points);
/// A new vtkPoints (double precision) holding `points`.
vtkSmartPointer<vtkPoints> ToVtkPoints(const Points& points);

/// Triangles of `surface` (polygons must all be triangles; lines, vertices and strips refused).
/// Returns false and explains why in `why` when the input is not a triangle surface.
bool ToSurfaceMesh(vtkPolyData* surface, SurfaceMesh& mesh, std::string& why);

/// Tetrahedra of `grid` (every cell must be a VTK_TETRA). Returns false with a reason otherwise.
bool ToTetMesh(vtkDataSet* grid, TetMesh& mesh, std::string& why);

/// Hexahedra of `grid` (every cell must be a VTK_HEXAHEDRON). Returns false with a reason otherwise.
bool ToHexMesh(vtkDataSet* grid, HexMesh& mesh, std::string& why);

vtkSmartPointer<vtkUnstructuredGrid> ToUnstructuredGrid(const TetMesh& mesh);
vtkSmartPointer<vtkUnstructuredGrid> ToUnstructuredGrid(const HexMesh& mesh);
vtkSmartPointer<vtkPolyData> ToPolyData(const SurfaceMesh& mesh);

} // namespace polycubehex

#endif
