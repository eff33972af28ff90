// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkOFFReader
 * @brief Reads Object File Format (`.off`) polygon surfaces into vtkPolyData.
 *
 * Polygons are kept as they are (run Triangulate for a triangle surface). A malformed file
 * fails with an error naming the vertex or face at fault.
 */
#ifndef vtkOFFReader_h
#define vtkOFFReader_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class POLYCUBEHEXFILTERS_EXPORT vtkOFFReader : public vtkPolyDataAlgorithm
{
public:
  static vtkOFFReader* New();
  vtkTypeMacro(vtkOFFReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The `.off` file to read. Default: none.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkOFFReader();
  ~vtkOFFReader() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;

private:
  vtkOFFReader(const vtkOFFReader&) = delete;
  void operator=(const vtkOFFReader&) = delete;
};

#endif
