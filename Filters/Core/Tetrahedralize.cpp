// SPDX-License-Identifier: BSD-3-Clause
// The only file of the project that includes tetgen.h (TetGen is AGPL-3+, see the README).
#include "Tetrahedralize.h"

#include "MemoryBudget.h"

#include "SurfaceCheck.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

#ifdef POLYCUBEHEX_HAS_TETGEN
#include <tetgen.h>

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#endif

namespace polycubehex
{
namespace
{
/// TetGen's tets average well below its volume bound (a third to a fifth of it), so the bound for
/// a target count is this factor times the mean volume wanted. Measured on a ball, torus.obj,
/// 3holes.obj and fertility.off for targets of 20k to 300k: counts within 0.7x to 1.7x of target.
constexpr double TargetVolumeFactor = 3.0;

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
int EnclosingCount(const SurfaceMesh& surface,
  const SurfaceCheckReport& report,
  const Eigen::Vector3d& point,
  int component,
  bool& insideComponent)
{
  int count = 0;
  insideComponent = false;
  for (int c = 0; c < static_cast<int>(report.Components.size()); ++c)
  {
    const SurfaceComponent& candidate = report.Components[c];
    bool inBounds = true;
    for (int k = 0; k < 3; ++k)
    {
      inBounds =
        inBounds && point[k] >= candidate.BoundsMin[k] && point[k] <= candidate.BoundsMax[k];
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
bool FindVoidSeed(const SurfaceMesh& surface,
  const SurfaceCheckReport& report,
  int v,
  Eigen::Vector3d& seed)
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

// TetGen 1.5.0 cannot fail safely inside a library: on any error (self-intersection, tiny
// feature, ...) its terminatetetgen() frees the mesh's memory pools and throws, and the mesh's
// destructor frees them again while the exception unwinds, which crashes the process. So TetGen
// runs in a forked child process that sends the result back through a pipe: a failure costs
// only the child, and the parent can poll for an abort while TetGen works.

/// What the child sends first: the tets, or the triangles TetGen's -d check found crossing.
enum class ChildResult : std::int32_t
{
  Tets = 0,
  Intersections = 1
};

void FillTetGenInput(const SurfaceMesh& surface,
  const std::vector<Eigen::Vector3d>& holes,
  tetgenio& in)
{
  // tetgenio frees its arrays with delete[], so they are allocated with new[].
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.Vertices.rows());
  in.pointlist = new REAL[3 * in.numberofpoints];
  std::copy(surface.Vertices.data(), surface.Vertices.data() + 3 * in.numberofpoints, in.pointlist);
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
}

bool WriteAll(int fd, const void* data, std::size_t bytes)
{
  const char* next = static_cast<const char*>(data);
  while (bytes > 0)
  {
    const ssize_t written = ::write(fd, next, bytes);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written <= 0)
    {
      return false;
    }
    next += written;
    bytes -= static_cast<std::size_t>(written);
  }
  return true;
}

template<typename T>
bool WriteArray(int fd, const T* values, std::int32_t count)
{
  return WriteAll(fd, &count, sizeof(count)) && WriteAll(fd, values, sizeof(T) * count);
}

/// The child: TetGen's self-intersection check (-d), then the mesh. Never returns.
[[noreturn]] void RunChild(const SurfaceMesh& surface,
  const std::vector<Eigen::Vector3d>& holes,
  const std::string& switches,
  int fd)
{
  bool sent = false;
  try
  {
    tetgenio in;
    FillTetGenInput(surface, holes, in);
    tetgenio check;
    char detect[] = "pdQ";
    tetrahedralize(detect, &in, &check);
    if (check.numberoftrifaces > 0)
    {
      const ChildResult kind = ChildResult::Intersections;
      sent = WriteAll(fd, &kind, sizeof(kind)) &&
        WriteArray(fd, check.trifacelist, 3 * check.numberoftrifaces);
    }
    else
    {
      tetgenio result;
      std::vector<char> commandLine(switches.begin(), switches.end());
      commandLine.push_back('\0');
      tetrahedralize(commandLine.data(), &in, &result);
      const ChildResult kind = ChildResult::Tets;
      const std::int32_t corners = result.numberoftetrahedra > 0 ? result.numberofcorners : 4;
      sent = WriteAll(fd, &kind, sizeof(kind)) &&
        WriteArray(fd, result.pointlist, 3 * result.numberofpoints) &&
        WriteArray(fd, result.tetrahedronlist, corners * result.numberoftetrahedra);
    }
  }
  catch (...)
  {
    sent = false; // the crash described above usually comes first
  }
  ::close(fd);
  ::_exit(sent ? 0 : 1); // no atexit handlers or stdio flushes of the parent's state
}

/// A cursor over the bytes the child sent.
struct Reader
{
  const std::string& Bytes;
  std::size_t Offset = 0;

  template<typename T>
  bool Read(T& value)
  {
    if (this->Offset + sizeof(T) > this->Bytes.size())
    {
      return false;
    }
    std::memcpy(&value, this->Bytes.data() + this->Offset, sizeof(T));
    this->Offset += sizeof(T);
    return true;
  }

  template<typename T>
  bool ReadArray(std::vector<T>& values)
  {
    std::int32_t count = 0;
    if (!this->Read(count) || count < 0 || this->Offset + sizeof(T) * count > this->Bytes.size())
    {
      return false;
    }
    values.resize(count);
    std::memcpy(values.data(), this->Bytes.data() + this->Offset, sizeof(T) * count);
    this->Offset += sizeof(T) * count;
    return true;
  }
};

std::string DescribeChildEnd(int waitStatus)
{
  std::ostringstream text;
  if (WIFSIGNALED(waitStatus))
  {
    text << "stopped by signal " << WTERMSIG(waitStatus) << " (" << strsignal(WTERMSIG(waitStatus))
         << ")";
  }
  else
  {
    text << "exited with code " << WEXITSTATUS(waitStatus);
  }
  return text.str();
}

/// Reads everything the child sends, polling `progress` for an abort while TetGen works.
/// Returns false if the caller aborted (the child is then killed).
bool Collect(int fd, pid_t child, const Progress& progress, std::string& bytes)
{
  std::vector<char> chunk(1 << 16);
  for (;;)
  {
    pollfd request = { fd, POLLIN, 0 };
    const int ready = ::poll(&request, 1, 100);
    if (ready == 0 || (ready < 0 && errno == EINTR))
    {
      if (!ReportProgress(progress, 0.1))
      {
        ::kill(child, SIGKILL);
        return false;
      }
      continue;
    }
    const ssize_t got = ::read(fd, chunk.data(), chunk.size());
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got <= 0)
    {
      return true; // end of data (or an error: the parse below notices missing bytes)
    }
    bytes.append(chunk.data(), static_cast<std::size_t>(got));
  }
}

/// Runs TetGen with `switches` in a child process. On success fills `out` (TetGen's node order)
/// or, if TetGen found self-intersections, `crossing` (#C vertex triples) and fails.
Status RunTetGen(const SurfaceMesh& surface,
  const std::vector<Eigen::Vector3d>& holes,
  const std::string& switches,
  const Progress& progress,
  TetMesh& out,
  std::vector<int>& crossing)
{
  int fds[2];
  if (::pipe(fds) != 0)
  {
    return Status::Failure(std::string("cannot start TetGen: pipe: ") + std::strerror(errno));
  }
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  if (child < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return Status::Failure(std::string("cannot start TetGen: fork: ") + std::strerror(errno));
  }
  if (child == 0)
  {
    // Die with the parent: a killed application must not leave TetGen running.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent)
    {
      ::_exit(1);
    }
    ::close(fds[0]);
    RunChild(surface, holes, switches, fds[1]);
  }
  ::close(fds[1]);
  std::string bytes;
  const bool finished = Collect(fds[0], child, progress, bytes);
  ::close(fds[0]);
  int waitStatus = 0;
  while (::waitpid(child, &waitStatus, 0) < 0 && errno == EINTR)
  {
  }
  if (!finished)
  {
    return Status::Failure("aborted while TetGen was running");
  }

  Reader reader{ bytes };
  ChildResult kind = ChildResult::Tets;
  std::vector<double> points;
  std::vector<int> tets;
  const bool complete = WIFEXITED(waitStatus) && WEXITSTATUS(waitStatus) == 0 &&
    reader.Read(kind) &&
    (kind == ChildResult::Intersections ? reader.ReadArray(crossing)
                                        : reader.ReadArray(points) && reader.ReadArray(tets));
  if (!complete)
  {
    return Status::Failure("TetGen (-" + switches + ") failed on this surface: it " +
      DescribeChildEnd(waitStatus) +
      ". TetGen stops this way on nearly touching triangles and on features far smaller than "
      "the mesh size");
  }
  if (kind == ChildResult::Intersections)
  {
    return Status::Failure("self-intersections");
  }
  if (tets.empty() || tets.size() % 4 != 0 || points.size() % 3 != 0)
  {
    return Status::Failure("TetGen (-" + switches + ") produced no tetrahedra");
  }
  out.Vertices = Eigen::Map<const Points>(points.data(), points.size() / 3, 3);
  // TetGen keeps orient3d(p0, p1, p2, p3) < 0 for its tets; Shewchuk's orient3d is minus six
  // times VTK's signed volume, so TetGen's node order is already VTK's positive order.
  out.Cells = Eigen::Map<const Tets>(tets.data(), tets.size() / 4, 4);
  return Status::Success();
}

/// "the surface intersects itself: N triangles cross others, e.g. triangle f (a, b, c), ..."
std::string DescribeIntersections(const SurfaceMesh& surface, const std::vector<int>& crossing)
{
  std::map<std::array<int, 3>, int> faceOf;
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    std::array<int, 3> key = { surface.Faces(f, 0), surface.Faces(f, 1), surface.Faces(f, 2) };
    std::sort(key.begin(), key.end());
    faceOf[key] = f;
  }
  const std::size_t count = crossing.size() / 3;
  std::ostringstream text;
  text << "the surface intersects itself: " << count
       << " triangles cross other triangles (TetGen -d)";
  for (std::size_t i = 0; i < std::min<std::size_t>(count, 3); ++i)
  {
    std::array<int, 3> key = { crossing[3 * i], crossing[3 * i + 1], crossing[3 * i + 2] };
    std::sort(key.begin(), key.end());
    const auto found = faceOf.find(key);
    // TetGen may renumber vertices it merges, so a triangle may match no input face.
    text << (i == 0 ? ", e.g. " : ", ") << "triangle "
         << (found != faceOf.end() ? std::to_string(found->second) + " " : std::string()) << "("
         << crossing[3 * i] << ", " << crossing[3 * i + 1] << ", " << crossing[3 * i + 2] << ")";
  }
  return text.str();
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

Status Tetrahedralize(const SurfaceMesh& surface,
  const TetrahedralizeParameters& params,
  TetMesh& out,
  std::string& switchesUsed,
  const Progress& progress)
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
  if (maxVolume > 0.0)
  {
    // TetGen's tets average a third to a fifth of the bound; about 1 kB per tet at its peak.
    const double tets = 5.0 * report.EnclosedVolume / maxVolume;
    const Status fits = CheckMemoryEstimate("tetrahedralizing into about " +
        std::to_string(static_cast<long long>(tets)) + " tets",
      1024.0 * tets,
      "raise MaxTetVolume or lower TargetTetCount");
    if (!fits)
    {
      return fits;
    }
  }
  const std::string switches = FormatSwitches(params, maxVolume);
  if (!ReportProgress(progress, 0.1))
  {
    return Status::Failure("aborted");
  }

  // 5. TetGen, then the output in VTK's orientation, verified.
  std::vector<int> crossing;
  const Status meshed = RunTetGen(*input, holes, switches, progress, out, crossing);
  if (!crossing.empty())
  {
    // Vertex ids of the compact surface: report them only when they are the input's.
    return Status::Failure("cannot tetrahedralize: " + DescribeIntersections(*input, crossing) +
      (input == &surface ? "" : " (vertex ids after dropping unused vertices)"));
  }
  if (!meshed)
  {
    out = TetMesh();
    return meshed;
  }
  if (!ReportProgress(progress, 0.9))
  {
    out = TetMesh();
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
