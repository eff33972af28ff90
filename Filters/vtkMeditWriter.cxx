// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMeditWriter.h"

#include "MeditFormat.h"
#include "PolycubeHexConversion.h"

#include <vtkCellTypes.h>
#include <vtkDataSet.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointSet.h>

#include <vector>

vtkStandardNewMacro(vtkMeditWriter);

vtkMeditWriter::vtkMeditWriter() = default;

vtkMeditWriter::~vtkMeditWriter()
{
  this->SetFileName(nullptr);
}

int vtkMeditWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkMeditWriter::WriteData()
{
  // 1. Get the input.
  vtkPointSet* input = vtkPointSet::SafeDownCast(this->GetInput());
  if (!input || !this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< (input ? "No file name was set." : "No input point set to write."));
    this->SetErrorCode(1);
    return;
  }

  // 2. Check the cell types and sort the cells by MEDIT keyword.
  std::vector<std::vector<int>> byType[5]; // lines, triangles, quads, tets, hexes
  const int vtkTypes[5] = { VTK_LINE, VTK_TRIANGLE, VTK_QUAD, VTK_TETRA, VTK_HEXAHEDRON };
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    const int type = input->GetCellType(c);
    int slot = 0;
    while (slot < 5 && vtkTypes[slot] != type)
    {
      ++slot;
    }
    if (slot == 5)
    {
      vtkErrorMacro(<< "Cell " << c << " is a " << vtkCellTypes::GetClassNameFromTypeId(type)
                    << ": MEDIT files hold lines, triangles, quadrilaterals, tetrahedra and "
                       "hexahedra only. Nothing was written.");
      this->SetErrorCode(1);
      return;
    }
    input->GetCellPoints(c, ids);
    std::vector<int> cell(ids->GetNumberOfIds());
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      cell[k] = static_cast<int>(ids->GetId(k));
    }
    byType[slot].push_back(std::move(cell));
  }

  // 3. Convert to the core's mesh.
  polycubehex::MeditMesh mesh;
  mesh.Vertices = polycubehex::ToPoints(input->GetPoints());
  auto fill = [](const std::vector<std::vector<int>>& cells, auto& matrix) {
    matrix.resize(static_cast<Eigen::Index>(cells.size()), matrix.cols());
    for (std::size_t c = 0; c < cells.size(); ++c)
    {
      for (Eigen::Index k = 0; k < matrix.cols(); ++k)
      {
        matrix(c, k) = cells[c][k];
      }
    }
  };
  fill(byType[0], mesh.EdgeCells);
  fill(byType[1], mesh.TriangleCells);
  fill(byType[2], mesh.QuadCells);
  fill(byType[3], mesh.TetCells);
  fill(byType[4], mesh.HexCells);

  // 4. Write.
  const polycubehex::Status status = polycubehex::WriteMeditFile(this->FileName, mesh);
  if (!status)
  {
    vtkErrorMacro(<< status.Message());
    this->SetErrorCode(1);
  }
}

void vtkMeditWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
