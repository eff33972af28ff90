// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkTetrahedralizeFilter
 * @brief Quality tetrahedral mesh of the solid bounded by a closed triangle surface (TetGen).
 *
 * Input: a vtkPolyData of triangles. Exactly coincident points are merged first (OBJ and STL
 * readers duplicate them); then the surface must be closed, 2-manifold (at edges and at
 * vertices), consistently oriented, free of degenerate triangles and of self-intersections, or
 * the filter fails with an error naming the problem and the first offending edges or vertices.
 * Nested components bound voids, which stay empty. Triangles with an angle below 1 degree
 * (needles and caps) are meshed but reported in a warning, since TetGen refines around them into
 * many small tets (synthetic decimated surfaces of 3000 triangles gave 140k-390k tets) and the
 * polycube cannot flatten them cleanly.
 *
 * Output: a vtkUnstructuredGrid of VTK_TETRA cells with positive volume (VTK's node order). The
 * first points are the merged input points, in order, followed by TetGen's Steiner points. Field
 * data is passed from the input, plus the string array `TetrahedralizeSwitches`: the TetGen
 * switches that were run (e.g. "pq2Q"), so that `tetgen -pq2Q` reproduces the mesh.
 *
 * TetGen is AGPL-3+; without it in the build (CMake option POLYCUBEHEX_USE_TETGEN off) the
 * filter always fails with an error saying so.
 */
#ifndef vtkTetrahedralizeFilter_h
#define vtkTetrahedralizeFilter_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class POLYCUBEHEXFILTERS_EXPORT vtkTetrahedralizeFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkTetrahedralizeFilter* New();
  vtkTypeMacro(vtkTetrahedralizeFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Upper bound on each tet's circumradius over its shortest edge (TetGen -q): smaller gives
  /// rounder and more tets. Default: 2.0; range [1.0, 10] (TetGen may not stop below ~1.1).
  vtkSetClampMacro(RadiusEdgeRatio, double, 1.0, 10.0);
  vtkGetMacro(RadiusEdgeRatio, double);
  ///@}

  ///@{
  /// Upper bound on each tet's volume, in the input's units (TetGen -a; approximate: tets may
  /// exceed it by ~10%, more next to large boundary triangles with PreserveBoundary).
  /// Default: 0 (no bound); range [0, VTK_DOUBLE_MAX].
  vtkSetClampMacro(MaxTetVolume, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaxTetVolume, double);
  ///@}

  ///@{
  /// Approximate number of tets wanted, turned into a volume bound from the enclosed volume
  /// (the stricter bound wins when MaxTetVolume is also set). It cannot go below the count the
  /// surface's own resolution needs. Default: 0 (no target); range [0, VTK_INT_MAX].
  vtkSetClampMacro(TargetTetCount, int, 0, VTK_INT_MAX);
  vtkGetMacro(TargetTetCount, int);
  ///@}

  ///@{
  /// Keep the input triangles as the boundary faces of the tets, adding no point on the
  /// boundary (TetGen -Y). Default: off (TetGen may split boundary triangles for quality).
  vtkSetMacro(PreserveBoundary, bool);
  vtkGetMacro(PreserveBoundary, bool);
  vtkBooleanMacro(PreserveBoundary, bool);
  ///@}

protected:
  vtkTetrahedralizeFilter() = default;
  ~vtkTetrahedralizeFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double RadiusEdgeRatio = 2.0;
  double MaxTetVolume = 0.0;
  int TargetTetCount = 0;
  bool PreserveBoundary = false;

private:
  vtkTetrahedralizeFilter(const vtkTetrahedralizeFilter&) = delete;
  void operator=(const vtkTetrahedralizeFilter&) = delete;
};

#endif
