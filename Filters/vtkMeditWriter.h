// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMeditWriter
 * @brief Writes a data set of lines, triangles, quadrilaterals, tetrahedra and hexahedra as a
 * MEDIT `.mesh` file.
 *
 * Hexahedra keep VTK's node order (MEDIT's is the same). Any other cell type is an error
 * that names the cell, and nothing is written.
 */
#ifndef vtkMeditWriter_h
#define vtkMeditWriter_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkWriter.h"

class POLYCUBEHEXFILTERS_EXPORT vtkMeditWriter : public vtkWriter
{
public:
  static vtkMeditWriter* New();
  vtkTypeMacro(vtkMeditWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The `.mesh` file to write. Default: none.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkMeditWriter();
  ~vtkMeditWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkMeditWriter(const vtkMeditWriter&) = delete;
  void operator=(const vtkMeditWriter&) = delete;
};

#endif
