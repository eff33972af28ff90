// SPDX-License-Identifier: BSD-3-Clause
// Checks that a triangle surface bounds a solid: closed, 2-manifold, consistently oriented and
// free of degenerate input, and describes its connected components (genus, volume, nesting).
#pragma once

#include "MeshTypes.h"
#include "Status.h"

#include <string>
#include <vector>

namespace polycubehex
{

/// One connected component (faces joined through shared edges) of a checked surface.
struct SurfaceComponent
{
  int FaceCount = 0;
  int VertexCount = 0;
  int EdgeCount = 0;
  int EulerCharacteristic = 0; ///< V - E + F
  int Genus = 0;               ///< (2 - EulerCharacteristic) / 2
  /// Volume enclosed by the component alone, positive when its faces are counter-clockwise seen
  /// from outside its enclosed region.
  double SignedVolume = 0.0;
  /// How many other components enclose this one: odd depth = the boundary of a void.
  int NestingDepth = 0;
  int Parent = -1;        ///< the innermost enclosing component, -1 at depth 0
  std::vector<int> Faces; ///< ids of the component's faces, ascending
  double BoundsMin[3] = { 0.0, 0.0, 0.0 };
  double BoundsMax[3] = { 0.0, 0.0, 0.0 };

  bool IsVoid() const { return this->NestingDepth % 2 == 1; }
  /// True when the faces point away from the solid (out of a body, into a void).
  bool OrientedOutward() const
  {
    return this->IsVoid() ? this->SignedVolume < 0.0 : this->SignedVolume > 0.0;
  }
};

/// What CheckClosedSurface found. Counts are of distinct problems (edges, vertices, faces);
/// `Problems` holds one readable sentence per kind of problem, naming the first few offenders.
struct SurfaceCheckReport
{
  int OutOfRangeIndexCount = 0;   ///< faces with a vertex index outside [0, #V)
  int NonFiniteVertexCount = 0;   ///< used vertices with a NaN or infinite coordinate
  int DegenerateFaceCount = 0;    ///< repeated vertex or height below 1e-10 of the diagonal
  int DuplicateFaceCount = 0;     ///< faces on the same three vertices as an earlier face
  int CoincidentVertexCount = 0;  ///< used vertices at exactly the position of another one
  int BoundaryEdgeCount = 0;      ///< edges in one triangle only
  int NonManifoldEdgeCount = 0;   ///< edges in three or more triangles
  int MisorientedEdgeCount = 0;   ///< edges used twice in the same direction
  int NonManifoldVertexCount = 0; ///< vertices whose triangles form several fans
  int UnusedVertexCount = 0;      ///< vertices in no face (not an error; they are ignored)

  double BoundingBoxDiagonal = 0.0; ///< of the used vertices
  /// Volume of the solid: bodies count positive and voids negative, whatever the orientation.
  double EnclosedVolume = 0.0;

  std::vector<SurfaceComponent> Components; ///< filled when the surface is valid
  std::vector<int> FaceComponent;           ///< #F component of each face (when valid)
  std::vector<std::string> Problems;

  bool IsValid() const { return this->Problems.empty(); }
  int VoidCount() const;
  /// A multi-line human-readable summary: the problems, or the components with genus and volume.
  std::string Summary() const;
};

/// Checks that `surface` is a closed, 2-manifold, consistently oriented triangle surface with
/// finite coordinates, in-range indices, no degenerate or duplicate triangles and no two vertices
/// at the same position. On success fills the components with their Euler characteristic, genus,
/// signed volume and nesting depth (found with the generalized winding number, which assumes the
/// components do not intersect each other; self-intersections are not detected here).
/// @param surface  #V by 3 vertices, #F by 3 triangles
/// @param report   every problem found and, if the surface is valid, its components
/// @return Failure whose message names each problem and its first offending edges or vertices.
Status CheckClosedSurface(const SurfaceMesh& surface, SurfaceCheckReport& report);

/// The triangles with a small angle (needles and caps) of a surface: not an error, but TetGen
/// refines the boundary around them down to their size (synthetic surfaces with a few hundred
/// such triangles among 3000 gave 140k-390k tets instead of a few thousand), and a polycube
/// cannot flatten them well when they are kept as boundary faces.
struct SurfaceAngleReport
{
  int SmallAngleFaceCount = 0;         ///< faces with an angle below the threshold
  double SmallestAngleDegrees = 180.0; ///< over all faces (180 when there are none)
  int SmallestAngleFace = -1;
};

/// Counts the faces of `surface` with an interior angle below `thresholdDegrees` (degenerate
/// faces, with no angle, count as 0 degrees).
SurfaceAngleReport MeasureSurfaceAngles(const SurfaceMesh& surface, double thresholdDegrees);

/// Generalized winding number (Jacobson et al. 2013) of the faces of one component of a checked
/// surface at `point`: about +-1 inside the component's enclosed region and 0 outside, with the
/// sign of the component's orientation. Exact in the sense of the solid-angle sum; no tolerance.
double ComponentWindingNumber(const SurfaceMesh& surface,
  const SurfaceCheckReport& report,
  int component,
  const Eigen::Vector3d& point);

} // namespace polycubehex
