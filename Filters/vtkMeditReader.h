// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMeditReader
 * @brief Reads MEDIT `.mesh` files (Vertices, Edges, Triangles, Quadrilaterals, Tetrahedra,
 * Hexahedra) into a vtkUnstructuredGrid.
 *
 * By default the output holds the volume cells (tetrahedra and hexahedra) only; with
 * ReadSurfaceElements on it also holds the edges (lines), triangles and quadrilaterals.
 * Indices are 1-based in the file, references are ignored, other keywords are skipped with a
 * warning, and a malformed file fails with an error naming the keyword and the entity.
 */
#ifndef vtkMeditReader_h
#define vtkMeditReader_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class POLYCUBEHEXFILTERS_EXPORT vtkMeditReader : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkMeditReader* New();
  vtkTypeMacro(vtkMeditReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The `.mesh` file to read. Default: none.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Also output the surface elements (edges, triangles, quadrilaterals). Default: off.
  vtkSetMacro(ReadSurfaceElements, bool);
  vtkGetMacro(ReadSurfaceElements, bool);
  vtkBooleanMacro(ReadSurfaceElements, bool);
  ///@}

  /// True when the file starts like a MEDIT mesh (its first keyword is MeshVersionFormatted).
  static int CanReadFile(const char* fileName);

protected:
  vtkMeditReader();
  ~vtkMeditReader() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;
  bool ReadSurfaceElements = false;

private:
  vtkMeditReader(const vtkMeditReader&) = delete;
  void operator=(const vtkMeditReader&) = delete;
};

#endif
