// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkPolycubeDeformFilter
 * @brief Deforms a tet mesh into a polycube: l1-based normal alignment (Huang et al. 2014) as
 * extended by Fang et al. 2016 (§4.1-4.2).
 *
 * The boundary normals are driven towards the coordinate axes by an area-weighted l1 energy
 * under as-rigid-as-possible distortion, with a continuation on the alignment weight until the
 * polycube residual is below ResidualTolerance. The boundary is then labelled +X,-X,+Y,-Y,+Z,-Z,
 * cleaned up, tets that would be forced flat are split, and each chart is flattened exactly
 * onto its plane with every tet kept positive.
 *
 * Guidance: Uniform is the l1-polycube baseline (no frame field, no cuts). FrameField is the
 * paper's closed form: the l1 stage starts from the map whose gradient best fits the input's
 * `Frame` cell array (vtkFrameFieldFilter's output; eq. 7). When the input has cuts
 * (`CutFaces`, `CutSide` and the field `CutTransitions`), everything runs on the cut mesh: the
 * copies across cut c are tied by x_plus = Pi_c x_minus + t_c (eq. 8) with t_c unknown, in the
 * fit (one linear solve), the l1 stage and the flattening, so that a torus becomes a bar with no
 * corner. Output port 0 is then the cut mesh (points of cut faces duplicated, one copy per side)
 * and the field `CutTranslations` holds t_c, which vtkHexExtractFilter uses to stitch the hexes
 * across the cuts. Automatic (the default) runs FrameField when the input has a frame field
 * (`Frame`, with `CutTransitions` when it has cuts), and Uniform otherwise; it also runs Uniform,
 * with a warning, when the frame field describes no valid map (the frame-guided reconstruction of
 * eq. 7 inverts tets), where FrameField guidance fails with an error.
 *
 * Output port 0: the tets at their polycube positions with point arrays `OriginalPointId`,
 * `OriginalPoints`, cell arrays `PolycubeLabels` and `OriginalCellId` (the input's cell data is
 * carried to split tets), and field data `CornerCount`, `InvertedTetCount`, `PolycubeResidual`,
 * `Guidance`, `ChartCount`, `PolycubeSeconds`, `UnflattenedVertexCount` (vertices farther than
 * 1e-9 of the diagonal from a chart plane, left there because flattening them would invert a tet
 * or fold a chart face; 0 means every chart is exactly flat), `ReleasedVertexCount` (vertices whose
 * planes were not imposed exactly at the end, though possibly reached within that tolerance) and
 * `MaxPlaneDeviation` (the largest distance of a chart vertex from its plane, input units),
 * `CreaseTurnBack` and `CreaseTurnBackBeforeFlattening` (how far the mesh path of a polycube
 * edge runs back along the edge's axis, the largest over the edges, input units; 0 when every
 * edge is monotone) and `TurnedBackCreaseCount` (edges turning back over 1e-3 of the diagonal),
 * `MinCreaseStretch` (the smallest ratio of an edge's length along its axis to its length in the
 * input, over edges at least 2 % of the diagonal long) and `SquashedCreaseCount` (edges below
 * 0.25: their charts are labelled across the edge's axis; the tets along it are crushed, and
 * often the hexes too).
 * Output port 1: the polycube boundary with cell arrays `PolycubeLabel`, `ChartId`, and the
 * point array `PolycubeDefect`, which shows where those counts are: bit flags, 1 off a chart
 * plane, 2 on an edge turning back, 4 on a squashed edge; 0 where the polycube is sound (the
 * hexes near a flagged vertex are the likeliest to be poor).
 */
#ifndef vtkPolycubeDeformFilter_h
#define vtkPolycubeDeformFilter_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class POLYCUBEHEXFILTERS_EXPORT vtkPolycubeDeformFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkPolycubeDeformFilter* New();
  vtkTypeMacro(vtkPolycubeDeformFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum GuidanceType
  {
    AUTOMATIC = 0,
    FRAME_FIELD = 1,
    UNIFORM = 2
  };

  ///@{
  /// What guides the polycube. Default AUTOMATIC (FrameField when the input has a frame field,
  /// else Uniform). See the class comment.
  vtkSetClampMacro(Guidance, int, AUTOMATIC, UNIFORM);
  vtkGetMacro(Guidance, int);
  ///@}

  ///@{
  /// Rotate the model first so that its normals best align with the axes. Default on.
  vtkSetMacro(AlignInitialRotation, bool);
  vtkGetMacro(AlignInitialRotation, bool);
  vtkBooleanMacro(AlignInitialRotation, bool);
  ///@}

  ///@{
  /// Alignment weight of the first continuation round. Default 0.2, in (0, 100].
  vtkSetClampMacro(AlignmentWeight, double, 1e-6, 100.0);
  vtkGetMacro(AlignmentWeight, double);
  ///@}

  ///@{
  /// Factor on the alignment weight per round. Default 2, in [1, 10].
  vtkSetClampMacro(AlignmentWeightGrowth, double, 1.0, 10.0);
  vtkGetMacro(AlignmentWeightGrowth, double);
  ///@}

  ///@{
  /// Smoothing of the l1 norm in the first round (sqrt(x^2 + eps)). Default 0.1, in (0, 1].
  vtkSetClampMacro(AlignmentEpsilon, double, 1e-8, 1.0);
  vtkGetMacro(AlignmentEpsilon, double);
  ///@}

  ///@{
  /// Smallest l1 smoothing reached by the continuation. Default 0.01, in (0, 1].
  vtkSetClampMacro(MinAlignmentEpsilon, double, 1e-8, 1.0);
  vtkGetMacro(MinAlignmentEpsilon, double);
  ///@}

  ///@{
  /// Most continuation rounds. Default 30, in [1, 1000].
  vtkSetClampMacro(MaxRounds, int, 1, 1000);
  vtkGetMacro(MaxRounds, int);
  ///@}

  ///@{
  /// Polycube residual (DESIGN.md section 4) that counts as converged. Default 1e-3.
  vtkSetClampMacro(ResidualTolerance, double, 1e-12, 1.0);
  vtkGetMacro(ResidualTolerance, double);
  ///@}

  ///@{
  /// Weight of the normal difference term, eq. (12). Default 1, at least 0. Other values give
  /// other labellings; where the filter warns of squashed polycube edges, 1.5 or 2 may avoid them
  /// (rockerarm, Uniform: 2 does), though on other models they do worse.
  vtkSetClampMacro(NormalDifferenceWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(NormalDifferenceWeight, double);
  ///@}

  ///@{
  /// On a cut mesh, let the normal difference (12) reach across each cut's loop, through the
  /// cut's transition (as the paper). Default off (see PolycubeParameters).
  vtkSetMacro(NormalDifferenceAcrossCuts, bool);
  vtkGetMacro(NormalDifferenceAcrossCuts, bool);
  vtkBooleanMacro(NormalDifferenceAcrossCuts, bool);
  ///@}

  ///@{
  /// Uniform guidance: rounds of crease repair after labelling (PolycubeCreases.h). A polycube
  /// edge whose mesh path runs back along its axis folds when flattened; its charts' faces
  /// around the part that runs back take one label and the shape is deformed again. Default 6,
  /// 0 turns it off.
  vtkSetClampMacro(MonotoneRepairRounds, int, 0, 100);
  vtkGetMacro(MonotoneRepairRounds, int);
  ///@}

  ///@{
  /// Charts smaller than this fraction of the boundary area are merged into a neighbour.
  /// Default 2e-4, in [0, 0.1].
  vtkSetClampMacro(MinChartAreaFraction, double, 0.0, 0.1);
  vtkGetMacro(MinChartAreaFraction, double);
  ///@}

  ///@{
  /// When the polycube has an edge squashed below this fraction of its input length along its
  /// axis (field MinCreaseStretch), the deformation runs once more with the other setting of
  /// when the inversion barrier widens, and the polycube with the less squashed edge is kept
  /// (field PolycubeRetried; PolycubeSeconds counts both runs). The continuation's outcome is
  /// chaotic in that setting: on rockerarm's closed form one squashes an edge to 0.016, the
  /// other to 0.038, with smoothed hexes of 0.35 and 0.59. Default 0.05, 0 turns it off, in
  /// [0, 1].
  vtkSetClampMacro(SquashedRetryStretch, double, 0.0, 1.0);
  vtkGetMacro(SquashedRetryStretch, double);
  ///@}

  ///@{
  /// Flatten every chart exactly onto its plane (off: stop after labelling). Default on.
  vtkSetMacro(Flatten, bool);
  vtkGetMacro(Flatten, bool);
  vtkBooleanMacro(Flatten, bool);
  ///@}

  ///@{
  /// Uniform guidance: homotopy steps after the penalised flattening that carry the charts the
  /// rest of the way onto their planes with the planes hard (fewer vertices left off their
  /// planes: fertility 162 -> 57). Default 0 (off): the hex minima it leads to were lower on
  /// the models measured (fertility 0.638 -> 0.507, rockerarm 0.208 -> 0.022). In [0, 200].
  vtkSetClampMacro(FlattenHomotopySteps, int, 0, 200);
  vtkGetMacro(FlattenHomotopySteps, int);
  ///@}

protected:
  vtkPolycubeDeformFilter();
  ~vtkPolycubeDeformFilter() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int Guidance = AUTOMATIC;
  bool AlignInitialRotation = true;
  double AlignmentWeight = 0.2;
  double AlignmentWeightGrowth = 2.0;
  double AlignmentEpsilon = 0.1;
  double MinAlignmentEpsilon = 0.01;
  int MaxRounds = 30;
  double ResidualTolerance = 1e-3;
  double NormalDifferenceWeight = 1.0;
  bool NormalDifferenceAcrossCuts = false;
  int MonotoneRepairRounds = 6;
  double MinChartAreaFraction = 2e-4;
  double SquashedRetryStretch = 0.05;
  bool Flatten = true;
  int FlattenHomotopySteps = 0;

private:
  vtkPolycubeDeformFilter(const vtkPolycubeDeformFilter&) = delete;
  void operator=(const vtkPolycubeDeformFilter&) = delete;
};

#endif
