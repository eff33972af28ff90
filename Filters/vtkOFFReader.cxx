// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOFFReader.h"

#include "OffFormat.h"
#include "PolycubeHexConversion.h"

#include <vtkCellArray.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <vector>

vtkStandardNewMacro(vtkOFFReader);

vtkOFFReader::vtkOFFReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkOFFReader::~vtkOFFReader()
{
  this->SetFileName(nullptr);
}

int vtkOFFReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // 1. Get the output.
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  // 2. Read and check the file.
  polycubehex::OffMesh mesh;
  const polycubehex::Status status =
    polycubehex::ReadOffFile(this->FileName ? this->FileName : "", mesh);
  if (!status)
  {
    vtkErrorMacro(<< "Cannot read OFF file '" << (this->FileName ? this->FileName : "")
                  << "': " << status.Message());
    return 0;
  }
  this->UpdateProgress(0.8);

  // 3. Convert.
  output->SetPoints(polycubehex::ToVtkPoints(mesh.Vertices));
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (std::size_t f = 0; f + 1 < mesh.FaceOffsets.size(); ++f)
  {
    ids.assign(mesh.FaceIndices.begin() + mesh.FaceOffsets[f],
      mesh.FaceIndices.begin() + mesh.FaceOffsets[f + 1]);
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  output->SetPolys(polys);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
