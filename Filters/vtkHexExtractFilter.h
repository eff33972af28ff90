// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkHexExtractFilter
 * @brief Extracts an all-hex mesh from a polycube-deformed tet mesh (Fang et al. 2016, §4.3).
 *
 * Input: the output of vtkPolycubeDeformFilter: tets at their polycube positions with the point
 * array `OriginalPoints` and the cell array `PolycubeLabels`. The filter scales the polycube to
 * the requested resolution, rounds every chart plane to an integer (greedy rounding with
 * re-solve), enumerates the integer points per tet, maps them back to the input by barycentric
 * coordinates and connects the unit cubes into hexes. An optional padding layer and a
 * quality-guarded smoothing follow.
 *
 * A closed-form polycube (Guidance FrameField on a model with handles) is the cut mesh: its cut
 * faces carry no label and the fields `CutTransitions` and `CutTranslations` relate the two
 * sides, u_plus = Pi u_minus + t. The cut translations are then rounded to integers with the
 * planes, and the extraction, the padding and the smoothing walk across the cuts through the
 * transitions, so the hex mesh is seamless (one vertex per point of a cut). The field
 * `IntegerCutTranslations` gives each cut's translation in hex edges.
 *
 * Output port 0: the hexes with cell `ScaledJacobian` (vtkMeshQuality) and field data
 * `HexCount`, `ScaledJacobianMin`, `ScaledJacobianMean`, `InvertedHexCount`,
 * `IrregularBoundaryVertexCount`, `DistanceMean`, `DistanceHausdorff` (symmetric sampled
 * distance to the input's boundary, in units of 1e-3 of its bounding-box diagonal), plus the
 * input's field data. Output port 1: the boundary quads with cell `PolycubeLabel`.
 */
#ifndef vtkHexExtractFilter_h
#define vtkHexExtractFilter_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class POLYCUBEHEXFILTERS_EXPORT vtkHexExtractFilter : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkHexExtractFilter* New();
  vtkTypeMacro(vtkHexExtractFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Hexes wanted, padding layer included, used when TargetEdgeLength is 0.
  /// Default 5000, at least 1.
  vtkSetClampMacro(TargetHexCount, int, 1, VTK_INT_MAX);
  vtkGetMacro(TargetHexCount, int);
  ///@}

  ///@{
  /// Hex edge length wanted, in input units; 0 uses TargetHexCount. Default 0, at least 0.
  vtkSetClampMacro(TargetEdgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TargetEdgeLength, double);
  ///@}

  ///@{
  /// Insert one layer of hexes under the boundary (the paper's padding). Default on.
  vtkSetMacro(Padding, bool);
  vtkGetMacro(Padding, bool);
  vtkBooleanMacro(Padding, bool);
  ///@}

  ///@{
  /// With Padding and without Smoothing: place each inner copy of the padding layer between its
  /// position mapped from the polycube and its boundary vertex pushed along the surface normal,
  /// where its hexes are best; where they stay poor (scaled Jacobian below 0.1), the copy then
  /// walks off that segment to a better point; last, all copies move together to raise their
  /// hexes' scaled Jacobians (a copy whose hexes would lose their minimum stays). No other vertex
  /// moves. With Smoothing the untangling
  /// and the sweeps optimise the inner copies from their mapped positions instead (measured
  /// better). Default on.
  vtkSetMacro(PaddingPlacement, bool);
  vtkGetMacro(PaddingPlacement, bool);
  vtkBooleanMacro(PaddingPlacement, bool);
  ///@}

  ///@{
  /// Smooth and untangle after extraction, keeping boundary vertices on the input surface.
  /// Our addition (the paper has none). Default on.
  vtkSetMacro(Smoothing, bool);
  vtkGetMacro(Smoothing, bool);
  vtkBooleanMacro(Smoothing, bool);
  ///@}

  ///@{
  /// Smoothing sweeps. Default 20, in [0, 1000].
  vtkSetClampMacro(SmoothingIterations, int, 0, 1000);
  vtkGetMacro(SmoothingIterations, int);
  ///@}

  ///@{
  /// With Smoothing: untangle and optimise all vertex positions at once before the local
  /// sweeps (a regularised distortion energy minimised by L-BFGS; kept only where it makes the
  /// mesh no worse). Default on.
  vtkSetMacro(Untangling, bool);
  vtkGetMacro(Untangling, bool);
  vtkBooleanMacro(Untangling, bool);
  ///@}

  ///@{
  /// Smooth the rounded polycube map before the hexes are extracted: every coordinate the
  /// chart planes and cuts leave free minimises a foldover-free distortion energy of the map
  /// (the hexes are its image of unit cubes); kept only when it leaves no tet inverted. Not in
  /// the paper. Default off: it helps some models (bunny, fandisk) and not others, and costs
  /// seconds on large ones (see HexExtraction.h).
  vtkSetMacro(MapSmoothing, bool);
  vtkGetMacro(MapSmoothing, bool);
  vtkBooleanMacro(MapSmoothing, bool);
  ///@}

  ///@{
  /// With Smoothing: a boundary vertex on a polycube edge or corner may leave its feature curve
  /// and slide on the input surface across its charts where the input's normals about it vary
  /// by at most this many degrees (a smooth region the polycube cut with an edge). 0 keeps
  /// them on their curves and corners except where one forces a flat or inverted hex (the
  /// untangling releases those whatever the angle); larger values trade feature fidelity for
  /// hex quality. ReleasedBoundaryVertexCount reports how many left. Default 20, in [0, 90].
  vtkSetClampMacro(SoftFeatureAngle, double, 0.0, 90.0);
  vtkGetMacro(SoftFeatureAngle, double);
  ///@}

  ///@{
  /// With Smoothing: after the smoothing sweeps, polish the worst hexes. The sweeps move one
  /// vertex at a time and stall where two hexes around it are tied for its worst; the polish
  /// climbs a soft minimum of the corners' scaled Jacobians of the hexes near the minimum, one
  /// vertex at a time and then all of them together, boundary vertices kept on the surface.
  /// The minimum never decreases; ScaledJacobianMinBeforePolish reports it before. Default on.
  vtkSetMacro(Polish, bool);
  vtkGetMacro(Polish, bool);
  vtkBooleanMacro(Polish, bool);
  ///@}

  ///@{
  /// With Polish: the corners and curve vertices of the hexes nearest the minimum (within 0.01)
  /// may leave their place and slide on the surface where the input's normals about them vary
  /// by at most this many degrees, so that the polish can move them. It acts only where the
  /// mesh is worst, and at angles above SoftFeatureAngle rounds off polycube corners the input
  /// has only softly. The default, 40 degrees, keeps the sharp edges and corners of a box
  /// (their normals are 45 and 54.7 degrees from their mean); 0 keeps every one.
  /// PolishReleasedVertexCount reports how many left. Default 40, in [0, 90].
  vtkSetClampMacro(PolishReleaseAngle, double, 0.0, 90.0);
  vtkGetMacro(PolishReleaseAngle, double);
  ///@}

  ///@{
  /// With Polish: those corners and curve vertices are also released, whatever the spread of
  /// the normals about them, where no edge of the input within a hex edge is sharper than this
  /// many degrees (the normals of its two triangles further apart). A tight curve of a coarse
  /// surface turns as much as a box's corner within a hex edge without any sharp edge, and is
  /// no feature; a box's edge (90 degrees) stays. Default 60, in [0, 180]; 0 turns it off. It
  /// raised the smoothed minima of spot, elephant and kitten's closed form and kept fandisk's
  /// (README).
  vtkSetClampMacro(PolishSharpEdgeAngle, double, 0.0, 180.0);
  vtkGetMacro(PolishSharpEdgeAngle, double);
  ///@}

  ///@{
  /// With Smoothing: sweeps after the Laplacian ones (and in those between the polishes) in
  /// which every vertex, after its Laplacian step, also tries a short step (0.05 of its mean
  /// edge length) each way along each direction it may move in, kept when it raises the mean
  /// scaled Jacobian of its hexes without going below the mesh's minimum. The Laplacian aims at
  /// evenly spaced vertices rather than square hexes; three such sweeps raised the mean by about
  /// 0.01 on the benchmark models, for about 2 more seconds per 17k hexes. 0 turns the steps
  /// off. Default 3, in [0, 50].
  vtkSetClampMacro(MeanSearchSweeps, int, 0, 50);
  vtkGetMacro(MeanSearchSweeps, int);
  ///@}

  ///@{
  /// With Smoothing and Untangling: 2 (the default) also follows a second path, forked from
  /// the untangling where the count of inverted hexes stops falling for two rounds and ending
  /// its untangling there, smooths both (side by side on two threads) and keeps the better
  /// mesh (fewer inverted hexes, then the larger minimum where the two differ by more than
  /// 0.01, else the larger mean): its minimum never more than 0.01 below that of 1, which
  /// untangles and smooths once, for 10-25 % more time on the benchmark's
  /// models. The field UntanglingPath says which was kept. In [1, 2].
  vtkSetClampMacro(UntanglingPaths, int, 1, 2);
  vtkGetMacro(UntanglingPaths, int);
  ///@}

  ///@{
  /// With Smoothing: when the mesh's minimum scaled Jacobian is below ScaleRetryBelow, extract
  /// again at a lattice scale 1 % larger, then (2) 1 % smaller, until one reaches it, and keep
  /// the best mesh (fewer inverted hexes, then the larger minimum, within 0.01 the larger
  /// mean). Where the lattice falls on the polycube's folds decides whether the untangling can
  /// lift every hex (rockerarm l1: minimum 0.208 and Hausdorff 19.6 at 24,272 hexes, 0.461 and
  /// 10.2 at 24,676). Each retry costs one more extraction. Fields ScaleFactor (the kept
  /// lattice scale over the one the targets ask for) and ScaleRetryCount. Default 2, in
  /// [0, 2]; 0 turns the retries off.
  vtkSetClampMacro(ScaleRetries, int, 0, 2);
  vtkGetMacro(ScaleRetries, int);
  ///@}

  ///@{
  /// The minimum scaled Jacobian below which ScaleRetries extracts again. Default 0.3, in
  /// [0, 1].
  vtkSetClampMacro(ScaleRetryBelow, double, 0.0, 1.0);
  vtkGetMacro(ScaleRetryBelow, double);
  ///@}

  ///@{
  /// Integers tried per chart plane by the greedy rounding. Default 4, in [1, 64].
  vtkSetClampMacro(RoundingCandidates, int, 1, 64);
  vtkGetMacro(RoundingCandidates, int);
  ///@}

  ///@{
  /// Compute the symmetric sampled distance to the input boundary. Default on.
  vtkSetMacro(ComputeDistances, bool);
  vtkGetMacro(ComputeDistances, bool);
  vtkBooleanMacro(ComputeDistances, bool);
  ///@}

  ///@{
  /// Samples per surface for the distance. Default 100000, at least 1000.
  vtkSetClampMacro(NumberOfDistanceSamples, int, 1000, VTK_INT_MAX);
  vtkGetMacro(NumberOfDistanceSamples, int);
  ///@}

protected:
  vtkHexExtractFilter();
  ~vtkHexExtractFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int TargetHexCount = 5000;
  double TargetEdgeLength = 0.0;
  bool Padding = true;
  bool PaddingPlacement = true;
  bool Smoothing = true;
  int SmoothingIterations = 20;
  bool Untangling = true;
  bool MapSmoothing = false;
  int RoundingCandidates = 4;
  double SoftFeatureAngle = 20.0; // the core's DefaultSoftFeatureAngle (checked in the .cxx)
  bool Polish = true;
  double PolishReleaseAngle = 40.0;
  double PolishSharpEdgeAngle = 60.0;
  int MeanSearchSweeps = 3;
  int UntanglingPaths = 2;
  int ScaleRetries = 2;
  double ScaleRetryBelow = 0.3;
  bool ComputeDistances = true;
  int NumberOfDistanceSamples = 100000;

private:
  vtkHexExtractFilter(const vtkHexExtractFilter&) = delete;
  void operator=(const vtkHexExtractFilter&) = delete;
};

#endif
