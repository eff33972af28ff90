// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkFrameFieldFilter
 * @brief A smooth, boundary-aligned frame field with no internal singularity and one cube
 * transition per cut (Fang et al. 2016, §3).
 *
 * Input: a tet mesh, optionally with the cell arrays `CutFaces` and `CutSide` of
 * vtkHandleCutFilter. Steps: a boundary-aligned octahedral field in spherical harmonics
 * (§3.2), matched along a minimum spanning tree of the dual graph of the cut mesh, optimised
 * with energy (1) by L-BFGS (Ceres), polar-decomposed; then per cut the best of the 24 cube
 * rotations (eq. 6).
 *
 * Output port 0: the tets with cell arrays `Frame` (9 values, row-major rotation, rows = axes),
 * `FrameU`, `FrameV`, `FrameW`, and field arrays `CutTransitions` (9 ints per cut),
 * `SingularEdgeCount`, `InteriorSingularEdgeCount`, `BoundaryAlignmentError` (degrees),
 * `FrameEnergy`, `FrameIterations`. Output port 1: glyph points (tet centres, subsampled to at
 * most MaximumGlyphCount) with point arrays `FrameU`, `FrameV`, `FrameW`. Output port 2: the
 * singular edges (lines) with cell arrays `SingularityType` and `SingularEdgeDepth`.
 */
#ifndef vtkFrameFieldFilter_h
#define vtkFrameFieldFilter_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class POLYCUBEHEXFILTERS_EXPORT vtkFrameFieldFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkFrameFieldFilter* New();
  vtkTypeMacro(vtkFrameFieldFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Boundary alignment against smoothness in the initial field (dimensionless; §5.2 of the
  /// paper compares two values). Lower: straighter field. Default 30, in (0, 1e6].
  vtkSetClampMacro(BoundaryAlignmentWeight, double, 1e-6, 1e6);
  vtkGetMacro(BoundaryAlignmentWeight, double);
  ///@}

  ///@{
  /// On a mesh with cuts, the initial field's weight for a first, tightly aligned attempt, so
  /// that the field can turn with the boundary around the handles (the cut transitions take up
  /// the turn, and the polycube needs fewer corners: 3holes 32 -> 16, rockerarm 62 -> 52).
  /// BoundaryAlignmentWeight is the fallback, run when that field keeps singular edges (kitten);
  /// the field with fewer is kept, and its weight goes to the field `InitialAlignmentWeight`.
  /// Meshes without cuts use BoundaryAlignmentWeight. Default 1000, in [0, 1e6]; 0 turns the
  /// aligned attempt off.
  vtkSetClampMacro(CutMeshBoundaryAlignmentWeight, double, 0.0, 1e6);
  vtkGetMacro(CutMeshBoundaryAlignmentWeight, double);
  ///@}

  ///@{
  /// w_a of eq. (1), the l1 normal alignment. Default 0.1, at least 0.
  vtkSetClampMacro(AlignmentWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AlignmentWeight, double);
  ///@}

  ///@{
  /// w_d of eq. (1), the normal difference. Default 0.01, at least 0.
  vtkSetClampMacro(NormalDifferenceWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(NormalDifferenceWeight, double);
  ///@}

  ///@{
  /// Boundary edges whose face normals are more than this apart (degrees) are left out of the
  /// normal difference: there the faces belong on different axes. Default 45; 180 keeps every
  /// edge, as the paper.
  vtkSetClampMacro(NormalDifferenceMaxAngle, double, 0.0, 180.0);
  vtkGetMacro(NormalDifferenceMaxAngle, double);
  ///@}

  ///@{
  /// w_R of eq. (1), the orthogonality penalty. Default 1, positive.
  vtkSetClampMacro(OrthogonalityWeight, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(OrthogonalityWeight, double);
  ///@}

  ///@{
  /// eps of the smoothed l1 norm sqrt(u^2 + eps). Default 1e-3, positive.
  vtkSetClampMacro(L1Epsilon, double, 1e-12, 1.0);
  vtkGetMacro(L1Epsilon, double);
  ///@}

  ///@{
  /// L-BFGS stops when the gradient norm is below this. Default 1e-5, at least 0.
  vtkSetClampMacro(GradientTolerance, double, 0.0, 1.0);
  vtkGetMacro(GradientTolerance, double);
  ///@}

  ///@{
  /// Iteration cap of L-BFGS; 0 keeps the matched initial field. Default 1000, in [0, 100000].
  vtkSetClampMacro(MaxIterations, int, 0, 100000);
  vtkGetMacro(MaxIterations, int);
  ///@}

  ///@{
  /// Most glyph points on output 1 (every k-th tet centre); 0 keeps all. Default 5000.
  vtkSetClampMacro(MaximumGlyphCount, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumGlyphCount, int);
  ///@}

protected:
  vtkFrameFieldFilter();
  ~vtkFrameFieldFilter() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double BoundaryAlignmentWeight = 30.0;
  double CutMeshBoundaryAlignmentWeight = 1000.0;
  double AlignmentWeight = 0.1;
  double NormalDifferenceWeight = 0.01;
  double NormalDifferenceMaxAngle = 45.0;
  double OrthogonalityWeight = 1.0;
  double L1Epsilon = 1e-3;
  double GradientTolerance = 1e-5;
  int MaxIterations = 1000;
  int MaximumGlyphCount = 5000;

private:
  vtkFrameFieldFilter(const vtkFrameFieldFilter&) = delete;
  void operator=(const vtkFrameFieldFilter&) = delete;
};

#endif
