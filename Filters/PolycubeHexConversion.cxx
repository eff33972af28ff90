// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeHexConversion.h"

#include <vtkCellArray.h>
#include <vtkCellTypes.h>
#include <vtkDataSet.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <sstream>

namespace polycubehex
{
namespace
{
template <int N, typename Matrix>
bool ToCells(vtkDataSet* grid, int cellType, const char* what, Points& vertices, Matrix& cells,
  std::string& why)
{
  if (!grid)
  {
    why = "no input data set";
    return false;
  }
  const vtkIdType cellCount = grid->GetNumberOfCells();
  if (cellCount == 0)
  {
    why = std::string("the input has no cells: expected ") + what;
    return false;
  }
  vertices.resize(grid->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    grid->GetPoint(i, vertices.data() + 3 * i);
  }
  cells.resize(cellCount, N);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cellCount; ++c)
  {
    if (grid->GetCellType(c) != cellType)
    {
      std::ostringstream message;
      message << "cell " << c << " is a "
              << vtkCellTypes::GetClassNameFromTypeId(grid->GetCellType(c))
              << ", but every cell must be a " << what;
      why = message.str();
      return false;
    }
    grid->GetCellPoints(c, ids);
    for (int k = 0; k < N; ++k)
    {
      cells(c, k) = static_cast<int>(ids->GetId(k));
    }
  }
  return true;
}

template <typename Matrix>
vtkSmartPointer<vtkUnstructuredGrid> ToGrid(const Points& vertices, const Matrix& cells, int type)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(ToVtkPoints(vertices));
  grid->Allocate(cells.rows());
  vtkIdType ids[8];
  for (Eigen::Index c = 0; c < cells.rows(); ++c)
  {
    for (Eigen::Index k = 0; k < cells.cols(); ++k)
    {
      ids[k] = cells(c, k);
    }
    grid->InsertNextCell(type, static_cast<vtkIdType>(cells.cols()), ids);
  }
  return grid;
}
} // namespace

Points ToPoints(vtkPoints* points)
{
  Points result(points ? points->GetNumberOfPoints() : 0, 3);
  for (Eigen::Index i = 0; i < result.rows(); ++i)
  {
    points->GetPoint(i, result.data() + 3 * i);
  }
  return result;
}

vtkSmartPointer<vtkPoints> ToVtkPoints(const Points& points)
{
  auto result = vtkSmartPointer<vtkPoints>::New();
  result->SetDataTypeToDouble();
  result->SetNumberOfPoints(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    result->SetPoint(i, points(i, 0), points(i, 1), points(i, 2));
  }
  return result;
}

bool ToSurfaceMesh(vtkPolyData* surface, SurfaceMesh& mesh, std::string& why)
{
  if (!surface || surface->GetNumberOfPolys() == 0)
  {
    why = "the input has no polygons: expected a closed triangle surface";
    return false;
  }
  if (surface->GetNumberOfLines() + surface->GetNumberOfVerts() + surface->GetNumberOfStrips() > 0)
  {
    why = "the input has lines, vertices or triangle strips: expected triangles only "
          "(apply Triangulate and Extract Surface first)";
    return false;
  }
  mesh.Vertices = ToPoints(surface->GetPoints());
  mesh.Faces.resize(surface->GetNumberOfPolys(), 3);
  vtkCellArray* polys = surface->GetPolys();
  vtkNew<vtkIdList> ids;
  for (vtkIdType f = 0; f < polys->GetNumberOfCells(); ++f)
  {
    polys->GetCellAtId(f, ids);
    if (ids->GetNumberOfIds() != 3)
    {
      std::ostringstream message;
      message << "polygon " << f << " has " << ids->GetNumberOfIds()
              << " vertices: expected triangles only (apply Triangulate first)";
      why = message.str();
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      mesh.Faces(f, k) = static_cast<int>(ids->GetId(k));
    }
  }
  return true;
}

bool ToTetMesh(vtkDataSet* grid, TetMesh& mesh, std::string& why)
{
  return ToCells<4>(grid, VTK_TETRA, "tetrahedron", mesh.Vertices, mesh.Cells, why);
}

bool ToHexMesh(vtkDataSet* grid, HexMesh& mesh, std::string& why)
{
  return ToCells<8>(grid, VTK_HEXAHEDRON, "hexahedron", mesh.Vertices, mesh.Cells, why);
}

vtkSmartPointer<vtkUnstructuredGrid> ToUnstructuredGrid(const TetMesh& mesh)
{
  return ToGrid(mesh.Vertices, mesh.Cells, VTK_TETRA);
}

vtkSmartPointer<vtkUnstructuredGrid> ToUnstructuredGrid(const HexMesh& mesh)
{
  return ToGrid(mesh.Vertices, mesh.Cells, VTK_HEXAHEDRON);
}

vtkSmartPointer<vtkPolyData> ToPolyData(const SurfaceMesh& mesh)
{
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(ToVtkPoints(mesh.Vertices));
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index f = 0; f < mesh.Faces.rows(); ++f)
  {
    const vtkIdType ids[3] = { mesh.Faces(f, 0), mesh.Faces(f, 1), mesh.Faces(f, 2) };
    polys->InsertNextCell(3, ids);
  }
  surface->SetPolys(polys);
  return surface;
}

} // namespace polycubehex
