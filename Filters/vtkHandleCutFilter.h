// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkHandleCutFilter
 * @brief Cuts a tet mesh along beta_1 surfaces so that it becomes simply connected (Fang et al.
 * 2016, §2): one cut per handle, each a connected, two-sided surface of interior faces whose
 * boundary (its handle loops) lies on the model's boundary or on earlier cuts.
 *
 * The cuts are made one at a time; each is the least-area surface of its cohomology class
 * (minimum cuts in a cyclic cover), and each lowers beta_1 by exactly one, checked by two
 * independent counts. When a step finds no proper cut (a handle one tet thick), the interior
 * edges joining two boundary vertices near it are split at their midpoints and the cuts are
 * recomputed, at most MaxSubdivisionRounds times; a mesh that needs none is left as it is.
 *
 * Output port 0: the input tets, or the subdivided tets (the input's points first, then the
 * midpoints; each tet's cell data copied from its parent, the midpoints' point data
 * interpolated from the input points), with cell arrays `OriginalCellId` (the input tet each
 * tet lies in; the identity without subdivision; kept as it is when the input has one),
 * `CutFaces` (4 ints per tet: the cut id of local face k, -1 if none) and `CutSide` (-1 minus,
 * +1 plus, 0), and field arrays `BettiNumber` (beta_1 of the input), `BoundaryGenus` (one per
 * boundary component), `CutArea` (one per cut) and `SubdividedTetCount` (input tets split). Output
 * port 1: the cut surfaces (triangles oriented from the minus to the plus side) with `CutId`.
 * Output port 2: the handle loops (polylines) with `CutId`.
 */
#ifndef vtkHandleCutFilter_h
#define vtkHandleCutFilter_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class POLYCUBEHEXFILTERS_EXPORT vtkHandleCutFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkHandleCutFilter* New();
  vtkTypeMacro(vtkHandleCutFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Prefer cuts that cross earlier cuts over cuts that end on them from one side (§5.3).
  /// Default on.
  vtkSetMacro(MatchedCuts, bool);
  vtkGetMacro(MatchedCuts, bool);
  vtkBooleanMacro(MatchedCuts, bool);
  ///@}

  ///@{
  /// Re-minimise every class at every step (smaller cuts, slower). Default on.
  vtkSetMacro(RecomputeEachStep, bool);
  vtkGetMacro(RecomputeEachStep, bool);
  vtkBooleanMacro(RecomputeEachStep, bool);
  ///@}

  ///@{
  /// Most minimum-cut rounds per class and step. Default 8, in [1, 100].
  vtkSetClampMacro(MaxMinCutRounds, int, 1, 100);
  vtkGetMacro(MaxMinCutRounds, int);
  ///@}

  ///@{
  /// Most rounds of subdivision when a step finds no proper cut; 0 fails instead. Default 2, in
  /// [0, 10].
  vtkSetClampMacro(MaxSubdivisionRounds, int, 0, 10);
  vtkGetMacro(MaxSubdivisionRounds, int);
  ///@}

protected:
  vtkHandleCutFilter();
  ~vtkHandleCutFilter() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  bool MatchedCuts = true;
  bool RecomputeEachStep = true;
  int MaxMinCutRounds = 8;
  int MaxSubdivisionRounds = 2;

private:
  vtkHandleCutFilter(const vtkHandleCutFilter&) = delete;
  void operator=(const vtkHandleCutFilter&) = delete;
};

#endif
