// SPDX-License-Identifier: BSD-3-Clause
// vtkOFFReader on fertility.off and on a broken file.
#include "PolycubeHexTestErrors.h"
#include "TestAssert.h"
#include "vtkOFFReader.h"

#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <fstream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    return 1;
  }
  const std::string data = argv[1];
  const std::string output = argv[2];

  vtkNew<vtkOFFReader> reader;
  reader->SetFileName((data + "/fertility.off").c_str());
  reader->Update();
  vtkPolyData* surface = reader->GetOutput();
  PCH_CHECK(surface->GetNumberOfPoints() == 4494);
  PCH_CHECK(surface->GetNumberOfPolys() == 9000);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(surface);
  mass->Update();
  PCH_CHECK(mass->GetVolume() > 0); // closed and consistently oriented

  const std::string broken = output + "/broken.off";
  {
    std::ofstream out(broken);
    out << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n";
  }
  vtkNew<ErrorCapture> errors;
  vtkNew<vtkOFFReader> bad;
  errors->Watch(bad);
  bad->SetFileName(broken.c_str());
  bad->Update();
  PCH_CHECK(bad->GetOutput()->GetNumberOfPolys() == 0);
  PCH_CHECK(errors->Mentions("face 0 of 1 references vertex 5"));
  return PCH_TEST_RESULT();
}
