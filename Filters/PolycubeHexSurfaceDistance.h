// SPDX-License-Identifier: BSD-3-Clause
// The symmetric sampled surface distance of shared/DESIGN.md section 4. Private to the module.
//
// Both boundaries are triangulated (quads split in two) and sampled uniformly by area with the
// same number of points each; every sample's distance to the other surface comes from the
// core's TriangleGrid (exact point-to-triangle distance, not a vertex distance: boundary hex
// vertices lie on the input surface by construction, so vertex distances would be ~0). VTK's
// vtkStaticCellLocator gives the same distances but took a quarter of the hex stage's time.
//
// Units: results are in units of 1e-3 of the bounding-box diagonal of the REFERENCE surface
// (the input the hex mesh approximates), the units of the paper's tables. Using the reference,
// not the hex mesh, keeps the unit fixed while a hex mesh is being compared or improved.
#ifndef PolycubeHexSurfaceDistance_h
#define PolycubeHexSurfaceDistance_h

#include "Status.h"

#include <vtkType.h>

#include <string>

class vtkDataSet;

namespace polycubehex
{

/// Distances between a mesh's boundary and a reference's boundary, in units of 1e-3 of the
/// reference's bounding-box diagonal (see the file comment).
struct SurfaceDistance
{
  double Mean = 0.0;               ///< mean over the samples of both directions
  double Hausdorff = 0.0;          ///< maximum over the samples of both directions
  double MeanToReference = 0.0;    ///< mean over samples on the mesh, to the reference
  double MaxToReference = 0.0;     ///< maximum over samples on the mesh, to the reference
  double MeanFromReference = 0.0;  ///< mean over samples on the reference, to the mesh
  double MaxFromReference = 0.0;   ///< maximum over samples on the reference, to the mesh
  double ReferenceDiagonal = 0.0;  ///< bounding-box diagonal of the reference surface
  vtkIdType SamplesPerSurface = 0; ///< number of samples taken on each surface
};

/// Computes the symmetric sampled distance between the boundaries of `mesh` and `reference`.
/// @param mesh       any data set; its boundary (vtkDataSetSurfaceFilter) is used: the boundary
///                   quads of a hex mesh, the boundary triangles of a tet mesh, or the polygons
///                   of a surface. Lines and vertices are ignored.
/// @param reference  the same for the reference; it also defines the unit of the result
/// @param samplesPerSurface  points sampled on each surface (the design asks for >= 100000)
/// @param seed       seeds the std::mt19937 used for sampling: same seed, same result
/// @param progress   called with the fraction done; returning false aborts (result unset)
/// @return false with a reason in `why` when a surface is empty or degenerate, or on abort.
bool ComputeSurfaceDistance(vtkDataSet* mesh,
  vtkDataSet* reference,
  vtkIdType samplesPerSurface,
  unsigned int seed,
  SurfaceDistance& result,
  std::string& why,
  const Progress& progress = {});

} // namespace polycubehex

#endif
