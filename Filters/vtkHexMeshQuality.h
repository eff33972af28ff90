// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkHexMeshQuality
 * @brief The measures of a hex mesh (shared/DESIGN.md section 4): scaled Jacobian, validity,
 * irregular boundary vertices and, against an optional reference, the surface distance.
 *
 * Input port 0: a vtkUnstructuredGrid of VTK_HEXAHEDRON cells only (anything else is refused).
 * Input port 1 (optional): the reference, any vtkDataSet; its boundary surface
 * (vtkDataSetSurfaceFilter) is compared with the hex mesh's boundary.
 *
 * The output is a shallow copy of the hex mesh with
 * - cell `ScaledJacobian`: vtkMeshQuality's (Verdict's) hex scaled Jacobian, in [-1, 1]; a hex
 *   with a zero-length edge, for which Verdict returns its sentinel 1e30, gets 0;
 * - field `HexCount`, `ScaledJacobianMin`, `ScaledJacobianMean`, `InvertedHexCount`
 *   (scaled Jacobian <= 0), `DegenerateHexCount` (a repeated vertex),
 *   `IrregularBoundaryVertexCount` (boundary quad valence other than 4);
 * - field `ScaledJacobianHistogram`: 11 tuples of one int, the number of hexes with a scaled
 *   Jacobian in (-inf, 0], then in (0, 0.1], (0.1, 0.2], ..., (0.9, 1]; values above 1
 *   (rounding) count in the last bin;
 * - field `ValidHexMesh` (1 or 0) and `ValidityReport` (a string naming the first offender of
 *   each defect). Valid means: every hex has 8 distinct vertices and a scaled Jacobian > 0,
 *   every interior quad is shared by exactly two hexes (from opposite sides), the boundary
 *   quads form a closed, oriented 2-manifold, and no two vertices are closer than 1e-9 of the
 *   bounding-box diagonal;
 * - with a reference, field `DistanceMean` and `DistanceHausdorff`: the symmetric sampled
 *   distance in units of 1e-3 of the reference's bounding-box diagonal, from
 *   NumberOfDistanceSamples points on each surface drawn from RandomSeed.
 */
#ifndef vtkHexMeshQuality_h
#define vtkHexMeshQuality_h

#include "PolycubeHexFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <string> // For ComputeQuality

class vtkAlgorithmOutput;
class vtkDataObject;
class vtkDataSet;

class POLYCUBEHEXFILTERS_EXPORT vtkHexMeshQuality : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkHexMeshQuality* New();
  vtkTypeMacro(vtkHexMeshQuality, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The optional reference (input port 1) for the distances; without it no distance is
  /// computed.
  void SetReferenceConnection(vtkAlgorithmOutput* output);
  void SetReferenceData(vtkDataObject* reference);
  ///@}

  ///@{
  /// Points sampled on each of the two surfaces for the distances. Default: 100000, the
  /// design's minimum for reported numbers; range [1000, VTK_INT_MAX].
  vtkSetClampMacro(NumberOfDistanceSamples, int, 1000, VTK_INT_MAX);
  vtkGetMacro(NumberOfDistanceSamples, int);
  ///@}

  ///@{
  /// Seed of the sampling's random generator: one seed, one result. Default: 0; range
  /// [0, VTK_INT_MAX].
  vtkSetClampMacro(RandomSeed, int, 0, VTK_INT_MAX);
  vtkGetMacro(RandomSeed, int);
  ///@}

  /**
   * The whole computation, for C++ callers such as the hex extraction filter: fills `output`
   * (which may be `hexes` itself) with the arrays listed in the class description. `reference`
   * may be null (no distances). Returns false with the reason in `why` when `hexes` is empty
   * or has a cell that is not a hexahedron, or the reference has no surface; an invalid hex
   * mesh is not an error (it gets ValidHexMesh = 0).
   */
  VTK_WRAPEXCLUDE static bool ComputeQuality(vtkUnstructuredGrid* hexes,
    vtkDataSet* reference,
    vtkUnstructuredGrid* output,
    std::string& why,
    int numberOfDistanceSamples = 100000,
    int randomSeed = 0);

protected:
  vtkHexMeshQuality();
  ~vtkHexMeshQuality() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int NumberOfDistanceSamples = 100000;
  int RandomSeed = 0;

private:
  vtkHexMeshQuality(const vtkHexMeshQuality&) = delete;
  void operator=(const vtkHexMeshQuality&) = delete;
};

#endif
