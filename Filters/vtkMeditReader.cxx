// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMeditReader.h"

#include "MeditFormat.h"
#include "PolycubeHexConversion.h"

#include <vtkCellType.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkUnstructuredGrid.h>

#include <fstream>

vtkStandardNewMacro(vtkMeditReader);

namespace
{
template <typename Matrix>
void AppendCells(vtkUnstructuredGrid* grid, const Matrix& cells, int cellType)
{
  vtkIdType ids[8];
  for (Eigen::Index c = 0; c < cells.rows(); ++c)
  {
    for (Eigen::Index k = 0; k < cells.cols(); ++k)
    {
      ids[k] = cells(c, k);
    }
    grid->InsertNextCell(cellType, static_cast<vtkIdType>(cells.cols()), ids);
  }
}
} // namespace

vtkMeditReader::vtkMeditReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkMeditReader::~vtkMeditReader()
{
  this->SetFileName(nullptr);
}

int vtkMeditReader::CanReadFile(const char* fileName)
{
  std::ifstream in(fileName ? fileName : "");
  std::string word;
  while (in >> word && !word.empty() && word[0] == '#')
  {
    std::getline(in, word);
  }
  return word == "MeshVersionFormatted" ? 1 : 0;
}

int vtkMeditReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // 1. Get the output.
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);

  // 2. Read and check the file (the core names the keyword and entity of any error).
  polycubehex::MeditMesh mesh;
  std::vector<std::string> warnings;
  const polycubehex::Status status =
    polycubehex::ReadMeditFile(this->FileName ? this->FileName : "", mesh, &warnings);
  if (!status)
  {
    vtkErrorMacro(<< "Cannot read MEDIT file '" << (this->FileName ? this->FileName : "")
                  << "': " << status.Message());
    return 0;
  }
  for (const std::string& warning : warnings)
  {
    vtkWarningMacro(<< this->FileName << ": " << warning);
  }
  this->UpdateProgress(0.8);

  // 3. Convert: volume cells first, then the surface elements if asked for.
  output->SetPoints(polycubehex::ToVtkPoints(mesh.Vertices));
  output->Allocate(mesh.TetCells.rows() + mesh.HexCells.rows());
  AppendCells(output, mesh.TetCells, VTK_TETRA);
  AppendCells(output, mesh.HexCells, VTK_HEXAHEDRON);
  if (this->ReadSurfaceElements)
  {
    AppendCells(output, mesh.EdgeCells, VTK_LINE);
    AppendCells(output, mesh.TriangleCells, VTK_TRIANGLE);
    AppendCells(output, mesh.QuadCells, VTK_QUAD);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMeditReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadSurfaceElements: " << this->ReadSurfaceElements << "\n";
}
