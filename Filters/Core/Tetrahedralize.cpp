// SPDX-License-Identifier: BSD-3-Clause
// The only file of the project that includes tetgen.h (TetGen is AGPL-3+, see the README).
#include "Tetrahedralize.h"

#include "SurfaceCheck.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

#ifdef POLYCUBEHEX_HAS_TETGEN
#include <tetgen.h>
#endif

namespace polycubehex
{
namespace
{
/// Each tet should hold about this fraction of TetGen's volume bound: quality refinement leaves
/// most tets well below the bound, so the bound is set above the mean volume wanted.
constexpr double TargetVolumeFactor = 1.0;

Status CheckParameters(const TetrahedralizeParameters& params)
{
  std::ostringstream why;
  if (!(params.RadiusEdgeRatio >= 1.0 && params.RadiusEdgeRatio <= 10.0))
  {
    why << "RadiusEdgeRatio must be in [1, 10], not " << params.RadiusEdgeRatio;
  }
  else if (!(params.MaxTetVolume >= 0.0 && std::isfinite(params.MaxTetVolume)))
  {
    why << "MaxTetVolume must be 0 (no bound) or positive, not " << params.MaxTetVolume;
  }
  else if (params.TargetTetCount < 0)
  {
    why << "TargetTetCount must be 0 (no target) or positive, not " << params.TargetTetCount;
  }
  return why.str().empty() ? Status::Success() : Status::Failure(why.str());
}

#ifdef POLYCUBEHEX_HAS_TETGEN

/// Components of `report` whose winding number at `point` is about +-1.
int EnclosingCount(const SurfaceMesh& surface, const SurfaceCheckReport& report,
  const Eigen::Vector3d& point, int component, bool& insideComponent)
{
  int count = 0;
  insideComponent = false;
  for (int c = 0; c < static_cast<int>(report.Components.size()); ++c)
  {
    const SurfaceComponent& candidate = report.Components[c];
    bool inBounds = true;
    for (int k = 0; k < 3; ++k)
    {
      inBounds = inBounds && point[k] >= candidate.BoundsMin[k] &&
        point[k] <= candidate.BoundsMax[k];
    }
    if (inBounds && std::abs(ComponentWindingNumber(surface, report, c, point)) > 0.5)
    {
      ++count;
      insideComponent = insideComponent || c == component;
    }
  }
  return count;
}

/// A point strictly inside the void bounded by component `v`: just behind one of its faces, on
/// the side its enclosed region lies. Accepted only if the winding numbers agree that the point
/// is inside `v` and inside exactly the components enclosing `v`, i.e. not in a solid island.
bool FindVoidSeed(
  const SurfaceMesh& surface, const SurfaceCheckReport& report, int v, Eigen::Vector3d& seed)
{
  const SurfaceComponent& component = report.Components[v];
  // Largest faces first: their neighbourhood leaves the most room.
  std::vector<std::pair<double, int>> faces;
  for (int f : component.Faces)
  {
    const Eigen::Vector3d p0 = surface.Vertices.row(surface.Faces(f, 0)).transpose();
    const Eigen::Vector3d p1 = surface.Vertices.row(surface.Faces(f, 1)).transpose();
    const Eigen::Vector3d p2 = surface.Vertices.row(surface.Faces(f, 2)).transpose();
    faces.emplace_back(-(p1 - p0).cross(p2 - p0).norm(), f);
  }
  const std::size_t tries = std::min<std::size_t>(faces.size(), 16);
  std::partial_sort(faces.begin(), faces.begin() + tries, faces.end());

  // The enclosed side is against the normal when the component encloses positive volume.
  const double inward = component.SignedVolume > 0.0 ? -1.0 : 1.0;
  for (std::size_t i = 0; i < tries; ++i)
  {
    const int f = faces[i].second;
    const Eigen::Vector3d p0 = surface.Vertices.row(surface.Faces(f, 0)).transpose();
    const Eigen::Vector3d p1 = surface.Vertices.row(surface.Faces(f, 1)).transpose();
    const Eigen::Vector3d p2 = surface.Vertices.row(surface.Faces(f, 2)).transpose();
    const Eigen::Vector3d normal = (p1 - p0).cross(p2 - p0).normalized();
    const Eigen::Vector3d centroid = (p0 + p1 + p2) / 3.0;
    const double size = std::sqrt(-faces[i].first); // ~ the face's edge length
    for (double scale : { 0.3, 0.1, 0.03, 0.01 })
    {
      seed = centroid + inward * scale * size * normal;
      bool insideVoid = false;
      const int depth = EnclosingCount(surface, report, seed, v, insideVoid);
      if (insideVoid && depth == component.NestingDepth + 1)
      {
        return true;
      }
    }
  }
  return false;
}

/// Keeps only the vertices used by faces, in their order; `compact` gets the renumbered faces.
void DropUnusedVertices(const SurfaceMesh& surface, SurfaceMesh& compact)
{
  std::vector<int> newIndex(surface.Vertices.rows(), -1);
  for (Eigen::Index i = 0; i < surface.Faces.size(); ++i)
  {
    newIndex[surface.Faces.data()[i]] = 0;
  }
  int next = 0;
  for (int& index : newIndex)
  {
    index = index == 0 ? next++ : -1;
  }
  compact.Vertices.resize(next, 3);
  for (int v = 0; v < surface.Vertices.rows(); ++v)
  {
    if (newIndex[v] >= 0)
    {
      compact.Vertices.row(newIndex[v]) = surface.Vertices.row(v);
    }
  }
  compact.Faces.resize(surface.Faces.rows(), 3);
  for (Eigen::Index i = 0; i < surface.Faces.size(); ++i)
  {
    compact.Faces.data()[i] = newIndex[surface.Faces.data()[i]];
  }
}

std::string FormatSwitches(const TetrahedralizeParameters& params, double maxVolume)
{
  std::ostringstream switches;
  switches.precision(6);
  // p: the input is a piecewise linear complex; q: radius-edge bound; Q: quiet.
  switches << "pq" << params.RadiusEdgeRatio;
  if (maxVolume > 0.0)
  {
    switches << "a" << maxVolume;
  }
  if (params.PreserveBoundary)
  {
    switches << "Y";
  }
  switches << "Q";
  return switches.str();
}

double SignedVolume(const TetMesh& mesh, int t)
{
  const Eigen::Vector3d p0 = mesh.Vertices.row(mesh.Cells(t, 0)).transpose();
  const Eigen::Vector3d p1 = mesh.Vertices.row(mesh.Cells(t, 1)).transpose();
  const Eigen::Vector3d p2 = mesh.Vertices.row(mesh.Cells(t, 2)).transpose();
  const Eigen::Vector3d p3 = mesh.Vertices.row(mesh.Cells(t, 3)).transpose();
  return (p1 - p0).cross(p2 - p0).dot(p3 - p0) / 6.0;
}

/// TetGen's exit codes (its terminatetetgen()), as sentences.
std::string TetGenError(int code)
{
  switch (code)
  {
    case 1:
      return "out of memory";
    case 2:
      return "internal error";
    case 3:
      return "the surface intersects itself";
    case 4:
      return "a very small input feature was found (features far below the mesh size)";
    case 5:
      return "two input triangles are very close to each other";
    case 10:
      return "TetGen refused the input";
    default:
      return "unknown error code " + std::to_string(code);
  }
}

/// Runs TetGen; tetgenio frees its arrays with delete[], so they are allocated with new[].
Status RunTetGen(const SurfaceMesh& surface, const std::vector<Eigen::Vector3d>& holes,
  const std::string& switches, TetMesh& out)
{
  tetgenio in;
  tetgenio result;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.Vertices.rows());
  in.pointlist = new REAL[3 * in.numberofpoints];
  std::copy(surface.Vertices.data(), surface.Vertices.data() + 3 * in.numberofpoints,
    in.pointlist);
  in.numberoffacets = static_cast<int>(surface.Faces.rows());
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  for (int f = 0; f < in.numberoffacets; ++f)
  {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k)
    {
      facet.polygonlist[0].vertexlist[k] = surface.Faces(f, k);
    }
  }
  in.numberofholes = static_cast<int>(holes.size());
  in.holelist = holes.empty() ? nullptr : new REAL[3 * holes.size()];
  for (std::size_t h = 0; h < holes.size(); ++h)
  {
    std::copy(holes[h].data(), holes[h].data() + 3, in.holelist + 3 * h);
  }

  std::vector<char> commandLine(switches.begin(), switches.end());
  commandLine.push_back('\0');
  try
  {
    tetrahedralize(commandLine.data(), &in, &result);
  }
  catch (int code)
  {
    return Status::Failure("TetGen failed (-" + switches + "): " + TetGenError(code));
  }
  catch (const std::exception& error)
  {
    return Status::Failure("TetGen failed (-" + switches + "): " + error.what());
  }
  if (result.numberoftetrahedra <= 0 || result.numberofcorners != 4)
  {
    return Status::Failure("TetGen (-" + switches + ") produced no tetrahedra");
  }

  out.Vertices.resize(result.numberofpoints, 3);
  std::copy(result.pointlist, result.pointlist + 3 * result.numberofpoints, out.Vertices.data());
  out.Cells.resize(result.numberoftetrahedra, 4);
  for (int t = 0; t < result.numberoftetrahedra; ++t)
  {
    const int* tet = result.tetrahedronlist + 4 * t;
    // TetGen's tets are negatively oriented in VTK's sense (its orient3d, Shewchuk's sign
    // convention, is positive for them): swapping two nodes makes every volume positive.
    out.Cells(t, 0) = tet[0];
    out.Cells(t, 1) = tet[2];
    out.Cells(t, 2) = tet[1];
    out.Cells(t, 3) = tet[3];
  }
  return Status::Success();
}

/// Drops vertices in no tet (TetGen keeps none normally), keeping the order of the others so
/// that the input vertices keep their indices.
void DropUnreferencedPoints(TetMesh& mesh)
{
  std::vector<int> newIndex(mesh.Vertices.rows(), -1);
  for (Eigen::Index i = 0; i < mesh.Cells.size(); ++i)
  {
    newIndex[mesh.Cells.data()[i]] = 0;
  }
  if (std::find(newIndex.begin(), newIndex.end(), -1) == newIndex.end())
  {
    return;
  }
  int next = 0;
  for (int& index : newIndex)
  {
    index = index == 0 ? next++ : -1;
  }
  Points kept(next, 3);
  for (int v = 0; v < mesh.Vertices.rows(); ++v)
  {
    if (newIndex[v] >= 0)
    {
      kept.row(newIndex[v]) = mesh.Vertices.row(v);
    }
  }
  mesh.Vertices.swap(kept);
  for (Eigen::Index i = 0; i < mesh.Cells.size(); ++i)
  {
    mesh.Cells.data()[i] = newIndex[mesh.Cells.data()[i]];
  }
}
#endif
} // namespace

Status Tetrahedralize(const SurfaceMesh& surface, const TetrahedralizeParameters& params,
  TetMesh& out, std::string& switchesUsed, const Progress& progress)
{
  out = TetMesh();
  switchesUsed.clear();
  const Status valid = CheckParameters(params);
  if (!valid)
  {
    return valid;
  }
#ifndef POLYCUBEHEX_HAS_TETGEN
  (void)surface;
  (void)progress;
  return Status::Failure("PolycubeHex was built without TetGen (CMake option "
                         "POLYCUBEHEX_USE_TETGEN=OFF), so it cannot tetrahedralize");
#else
  // 1. Only a closed, manifold, oriented surface bounds a solid that TetGen can mesh.
  SurfaceCheckReport report;
  const Status closed = CheckClosedSurface(surface, report);
  if (!closed)
  {
    return Status::Failure("cannot tetrahedralize: " + closed.Message());
  }
  if (!ReportProgress(progress, 0.05))
  {
    return Status::Failure("aborted");
  }

  // 2. Unused vertices would become isolated TetGen points: drop them. The faces keep their
  // ids, so the report's components still describe the compact surface.
  SurfaceMesh compactSurface;
  const SurfaceMesh* input = &surface;
  if (report.UnusedVertexCount > 0)
  {
    DropUnusedVertices(surface, compactSurface);
    input = &compactSurface;
  }

  // 3. A hole point in each void, else TetGen fills the void with tets.
  std::vector<Eigen::Vector3d> holes;
  for (int c = 0; c < static_cast<int>(report.Components.size()); ++c)
  {
    if (report.Components[c].IsVoid())
    {
      Eigen::Vector3d seed;
      if (!FindVoidSeed(*input, report, c, seed))
      {
        std::ostringstream why;
        why << "cannot tetrahedralize: found no point inside the void bounded by component " << c
            << " (" << report.Components[c].FaceCount
            << " triangles); does it intersect another component?";
        return Status::Failure(why.str());
      }
      holes.push_back(seed);
    }
  }

  // 4. The volume bound: the stricter of the explicit one and the one from the target count.
  double maxVolume = params.MaxTetVolume;
  if (params.TargetTetCount > 0)
  {
    const double fromTarget = TargetVolumeFactor * report.EnclosedVolume / params.TargetTetCount;
    maxVolume = maxVolume > 0.0 ? std::min(maxVolume, fromTarget) : fromTarget;
  }
  const std::string switches = FormatSwitches(params, maxVolume);
  if (!ReportProgress(progress, 0.1))
  {
    return Status::Failure("aborted");
  }

  // 5. TetGen, then the output in VTK's orientation, verified.
  const Status meshed = RunTetGen(*input, holes, switches, out);
  if (!meshed)
  {
    return meshed;
  }
  if (!ReportProgress(progress, 0.9))
  {
    return Status::Failure("aborted");
  }
  DropUnreferencedPoints(out);
  int inverted = 0;
  for (int t = 0; t < out.Cells.rows(); ++t)
  {
    inverted += SignedVolume(out, t) <= 0.0 ? 1 : 0;
  }
  if (inverted > 0)
  {
    std::ostringstream why;
    why << "TetGen (-" << switches << ") produced " << inverted << " of " << out.Cells.rows()
        << " tets with non-positive volume";
    out = TetMesh();
    return Status::Failure(why.str());
  }
  switchesUsed = switches;
  ReportProgress(progress, 1.0);
  return Status::Success();
#endif
}

} // namespace polycubehex
