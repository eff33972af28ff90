// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceCheck.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <tuple>

namespace polycubehex
{
namespace
{
/// How many offenders a message names before it relies on the count alone.
constexpr int ExampleCount = 3;

/// A triangle is degenerate when its height is below this fraction of the bounding-box diagonal:
/// far below TetGen's own coplanarity tolerance (1e-8), so only truly flat triangles are refused.
constexpr double DegenerateHeight = 1e-10;

Eigen::Vector3d Position(const SurfaceMesh& surface, int vertex)
{
  return surface.Vertices.row(vertex).transpose();
}

std::string FormatPoint(const Eigen::Vector3d& p)
{
  std::ostringstream text;
  text << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return text.str();
}

std::string FormatEdge(const SurfaceMesh& surface, int a, int b)
{
  std::ostringstream text;
  text << "edge (" << a << ", " << b << ") at " << FormatPoint(Position(surface, a)) << "-"
       << FormatPoint(Position(surface, b));
  return text.str();
}

std::string FormatFace(const SurfaceMesh& surface, int face)
{
  std::ostringstream text;
  text << "face " << face << " (" << surface.Faces(face, 0) << ", " << surface.Faces(face, 1)
       << ", " << surface.Faces(face, 2) << ")";
  return text.str();
}

/// "<prefix><count> <noun> <rest>, e.g. <example>, <example>, <example>"
std::string Describe(const std::string& prefix,
  int count,
  const char* singular,
  const char* plural,
  const std::string& rest,
  const std::vector<std::string>& examples)
{
  std::ostringstream text;
  text << prefix << count << " " << (count == 1 ? singular : plural) << " " << rest;
  for (std::size_t i = 0; i < examples.size(); ++i)
  {
    text << (i == 0 ? ", e.g. " : ", ") << examples[i];
  }
  return text.str();
}

/// One side of an undirected edge a < b as seen from a face: `Forward` when the face runs a -> b.
struct HalfEdge
{
  int A;
  int B;
  int Face;
  bool Forward;
  bool operator<(const HalfEdge& other) const
  {
    return std::tie(this->A, this->B, this->Face) < std::tie(other.A, other.B, other.Face);
  }
};

/// Disjoint sets over faces, with path halving.
struct UnionFind
{
  std::vector<int> Parent;
  explicit UnionFind(int n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  int Find(int x)
  {
    while (this->Parent[x] != x)
    {
      this->Parent[x] = this->Parent[this->Parent[x]];
      x = this->Parent[x];
    }
    return x;
  }
  void Join(int a, int b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a != b)
    {
      this->Parent[std::max(a, b)] = std::min(a, b);
    }
  }
};

bool HasRepeatedVertex(const SurfaceMesh& surface, int f)
{
  const auto& F = surface.Faces;
  return F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 2) == F(f, 0);
}

/// Index ranges and finite coordinates: every later check relies on both.
void CheckIndicesAndCoordinates(const SurfaceMesh& surface,
  SurfaceCheckReport& report,
  std::vector<char>& used)
{
  const int vertexCount = static_cast<int>(surface.Vertices.rows());
  std::vector<std::string> examples;
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    bool inRange = true;
    for (int k = 0; k < 3; ++k)
    {
      const int v = surface.Faces(f, k);
      inRange = inRange && v >= 0 && v < vertexCount;
    }
    if (!inRange)
    {
      if (report.OutOfRangeIndexCount++ < ExampleCount)
      {
        examples.push_back(FormatFace(surface, f));
      }
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      used[surface.Faces(f, k)] = 1;
    }
  }
  if (report.OutOfRangeIndexCount > 0)
  {
    const std::string rest = "with a vertex index outside [0, " + std::to_string(vertexCount) + ")";
    report.Problems.push_back(
      Describe("", report.OutOfRangeIndexCount, "triangle", "triangles", rest, examples));
  }

  examples.clear();
  for (int v = 0; v < vertexCount; ++v)
  {
    if (!used[v])
    {
      ++report.UnusedVertexCount;
    }
    else if (!surface.Vertices.row(v).allFinite())
    {
      if (report.NonFiniteVertexCount++ < ExampleCount)
      {
        examples.push_back(
          "vertex " + std::to_string(v) + " at " + FormatPoint(Position(surface, v)));
      }
    }
  }
  if (report.NonFiniteVertexCount > 0)
  {
    report.Problems.push_back(Describe("non-finite coordinates: ",
      report.NonFiniteVertexCount,
      "vertex",
      "vertices",
      "with a NaN or infinite coordinate",
      examples));
  }
}

double BoundingBoxDiagonal(const SurfaceMesh& surface, const std::vector<char>& used)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (int v = 0; v < surface.Vertices.rows(); ++v)
  {
    if (used[v])
    {
      lo = lo.cwiseMin(Position(surface, v));
      hi = hi.cwiseMax(Position(surface, v));
    }
  }
  return (lo.array() <= hi.array()).all() ? (hi - lo).norm() : 0.0;
}

/// Degenerate and duplicate triangles, and distinct vertices at one position.
void CheckElements(const SurfaceMesh& surface,
  const std::vector<char>& used,
  SurfaceCheckReport& report)
{
  const double minHeight = DegenerateHeight * report.BoundingBoxDiagonal;
  std::vector<std::string> examples;
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    const Eigen::Vector3d p0 = Position(surface, surface.Faces(f, 0));
    const Eigen::Vector3d p1 = Position(surface, surface.Faces(f, 1));
    const Eigen::Vector3d p2 = Position(surface, surface.Faces(f, 2));
    const double longest = std::max({ (p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm() });
    const double height = longest > 0.0 ? (p1 - p0).cross(p2 - p0).norm() / longest : 0.0;
    if (HasRepeatedVertex(surface, f) || !(height > minHeight))
    {
      if (report.DegenerateFaceCount++ < ExampleCount)
      {
        examples.push_back(FormatFace(surface, f) + " at " + FormatPoint(p0) + ", " +
          FormatPoint(p1) + ", " + FormatPoint(p2));
      }
    }
  }
  if (report.DegenerateFaceCount > 0)
  {
    report.Problems.push_back(Describe("",
      report.DegenerateFaceCount,
      "degenerate triangle",
      "degenerate triangles",
      "(a repeated vertex or no area)",
      examples));
  }

  // Duplicates: the same vertex set, whatever the order or orientation.
  std::vector<std::pair<std::array<int, 3>, int>> keys(surface.Faces.rows());
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    std::array<int, 3> key = { surface.Faces(f, 0), surface.Faces(f, 1), surface.Faces(f, 2) };
    std::sort(key.begin(), key.end());
    keys[f] = { key, f };
  }
  std::sort(keys.begin(), keys.end());
  examples.clear();
  for (std::size_t i = 1; i < keys.size(); ++i)
  {
    if (keys[i].first == keys[i - 1].first)
    {
      if (report.DuplicateFaceCount++ < ExampleCount)
      {
        examples.push_back(FormatFace(surface, keys[i].second) + " repeats face " +
          std::to_string(keys[i - 1].second));
      }
    }
  }
  if (report.DuplicateFaceCount > 0)
  {
    report.Problems.push_back(Describe("",
      report.DuplicateFaceCount,
      "duplicate triangle",
      "duplicate triangles",
      "(the same three vertices as another triangle)",
      examples));
  }

  // Coincident vertices: the surface touches itself there, which TetGen cannot mesh.
  std::vector<int> order;
  for (int v = 0; v < surface.Vertices.rows(); ++v)
  {
    if (used[v])
    {
      order.push_back(v);
    }
  }
  const auto& X = surface.Vertices;
  auto lexicographic = [&X](int a, int b)
  {
    return std::make_tuple(X(a, 0), X(a, 1), X(a, 2), a) <
      std::make_tuple(X(b, 0), X(b, 1), X(b, 2), b);
  };
  std::sort(order.begin(), order.end(), lexicographic);
  examples.clear();
  for (std::size_t i = 1; i < order.size(); ++i)
  {
    if (X.row(order[i]) == X.row(order[i - 1]))
    {
      if (report.CoincidentVertexCount++ < ExampleCount)
      {
        examples.push_back("vertices " + std::to_string(order[i - 1]) + " and " +
          std::to_string(order[i]) + " at " + FormatPoint(Position(surface, order[i])));
      }
    }
  }
  if (report.CoincidentVertexCount > 0)
  {
    report.Problems.push_back(Describe("",
      report.CoincidentVertexCount,
      "vertex",
      "vertices",
      "at exactly the position of another vertex (merge them first)",
      examples));
  }
}

/// Closed, edge-manifold, consistently oriented. Returns the sorted half-edges for later use.
std::vector<HalfEdge> CheckEdges(const SurfaceMesh& surface, SurfaceCheckReport& report)
{
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * surface.Faces.rows());
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    if (HasRepeatedVertex(surface, f))
    {
      continue; // already reported as degenerate; it has no proper edges
    }
    for (int k = 0; k < 3; ++k)
    {
      const int a = surface.Faces(f, k);
      const int b = surface.Faces(f, (k + 1) % 3);
      halfEdges.push_back({ std::min(a, b), std::max(a, b), f, a < b });
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());

  std::vector<std::string> boundary, nonManifold, misoriented;
  for (std::size_t i = 0; i < halfEdges.size();)
  {
    std::size_t j = i;
    while (
      j < halfEdges.size() && halfEdges[j].A == halfEdges[i].A && halfEdges[j].B == halfEdges[i].B)
    {
      ++j;
    }
    const int uses = static_cast<int>(j - i);
    const int a = halfEdges[i].A;
    const int b = halfEdges[i].B;
    if (uses == 1)
    {
      if (report.BoundaryEdgeCount++ < ExampleCount)
      {
        boundary.push_back(FormatEdge(surface, a, b));
      }
    }
    else if (uses > 2)
    {
      if (report.NonManifoldEdgeCount++ < ExampleCount)
      {
        nonManifold.push_back(
          FormatEdge(surface, a, b) + " in " + std::to_string(uses) + " triangles");
      }
    }
    else if (halfEdges[i].Forward == halfEdges[i + 1].Forward)
    {
      if (report.MisorientedEdgeCount++ < ExampleCount)
      {
        misoriented.push_back(FormatEdge(surface, a, b) + " (triangles " +
          std::to_string(halfEdges[i].Face) + " and " + std::to_string(halfEdges[i + 1].Face) +
          ")");
      }
    }
    i = j;
  }
  if (report.BoundaryEdgeCount > 0)
  {
    report.Problems.push_back(Describe("the surface is not closed: ",
      report.BoundaryEdgeCount,
      "boundary edge",
      "boundary edges",
      "(in one triangle only)",
      boundary));
  }
  if (report.NonManifoldEdgeCount > 0)
  {
    report.Problems.push_back(Describe("the surface is not 2-manifold: ",
      report.NonManifoldEdgeCount,
      "edge",
      "edges",
      "in more than two triangles",
      nonManifold));
  }
  if (report.MisorientedEdgeCount > 0)
  {
    report.Problems.push_back(Describe("the surface is not consistently oriented: ",
      report.MisorientedEdgeCount,
      "edge",
      "edges",
      "used twice in the same direction",
      misoriented));
  }
  return halfEdges;
}

/// With manifold, oriented edges, the triangles (v, a, b) around v map a -> b, a permutation of
/// the neighbours of v; v is a manifold vertex when that permutation is a single cycle (one fan).
void CheckVertexFans(const SurfaceMesh& surface, SurfaceCheckReport& report)
{
  std::vector<std::array<int, 3>> corners; // (v, a, b)
  corners.reserve(3 * surface.Faces.rows());
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      corners.push_back(
        { surface.Faces(f, k), surface.Faces(f, (k + 1) % 3), surface.Faces(f, (k + 2) % 3) });
    }
  }
  std::sort(corners.begin(), corners.end());

  std::vector<std::string> examples;
  std::vector<char> visited;
  for (std::size_t i = 0; i < corners.size();)
  {
    std::size_t j = i;
    while (j < corners.size() && corners[j][0] == corners[i][0])
    {
      ++j;
    }
    // Count the cycles of a -> b among corners [i, j), which are sorted by a.
    visited.assign(j - i, 0);
    int fans = 0;
    for (std::size_t start = i; start < j; ++start)
    {
      if (visited[start - i])
      {
        continue;
      }
      ++fans;
      std::size_t c = start;
      while (!visited[c - i])
      {
        visited[c - i] = 1;
        const std::array<int, 3> key = { corners[i][0], corners[c][2], -1 };
        const auto next = std::lower_bound(corners.begin() + i, corners.begin() + j, key);
        if (next == corners.begin() + j || (*next)[1] != corners[c][2])
        {
          break; // cannot happen with manifold oriented edges; counted as a separate fan
        }
        c = static_cast<std::size_t>(next - corners.begin());
      }
    }
    if (fans > 1 && report.NonManifoldVertexCount++ < ExampleCount)
    {
      const int v = corners[i][0];
      examples.push_back("vertex " + std::to_string(v) + " at " +
        FormatPoint(Position(surface, v)) + " (" + std::to_string(fans) + " fans)");
    }
    i = j;
  }
  if (report.NonManifoldVertexCount > 0)
  {
    report.Problems.push_back(Describe("the surface is not 2-manifold: ",
      report.NonManifoldVertexCount,
      "vertex",
      "vertices",
      "whose triangles form several separate fans",
      examples));
  }
}

/// Components through shared edges, with their topology, volume and bounds.
void FindComponents(const SurfaceMesh& surface,
  const std::vector<HalfEdge>& halfEdges,
  SurfaceCheckReport& report)
{
  const int faceCount = static_cast<int>(surface.Faces.rows());
  UnionFind sets(faceCount);
  for (std::size_t i = 0; i + 1 < halfEdges.size(); i += 2)
  {
    sets.Join(halfEdges[i].Face, halfEdges[i + 1].Face); // every edge has exactly two sides
  }
  std::vector<int> idOfRoot(faceCount, -1);
  report.FaceComponent.assign(faceCount, -1);
  for (int f = 0; f < faceCount; ++f)
  {
    const int root = sets.Find(f);
    if (idOfRoot[root] < 0)
    {
      idOfRoot[root] = static_cast<int>(report.Components.size());
      report.Components.emplace_back();
    }
    report.FaceComponent[f] = idOfRoot[root];
    report.Components[idOfRoot[root]].Faces.push_back(f);
  }
  for (std::size_t i = 0; i < halfEdges.size(); i += 2)
  {
    ++report.Components[report.FaceComponent[halfEdges[i].Face]].EdgeCount;
  }

  std::vector<int> lastSeen(surface.Vertices.rows(), -1);
  for (std::size_t c = 0; c < report.Components.size(); ++c)
  {
    SurfaceComponent& component = report.Components[c];
    component.FaceCount = static_cast<int>(component.Faces.size());
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (int f : component.Faces)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int v = surface.Faces(f, k);
        if (lastSeen[v] != static_cast<int>(c))
        {
          lastSeen[v] = static_cast<int>(c);
          ++component.VertexCount;
          lo = lo.cwiseMin(Position(surface, v));
          hi = hi.cwiseMax(Position(surface, v));
        }
      }
    }
    // Volume relative to the component's centre keeps the sum well conditioned far from 0.
    const Eigen::Vector3d centre = 0.5 * (lo + hi);
    double sixVolume = 0.0;
    for (int f : component.Faces)
    {
      const Eigen::Vector3d p0 = Position(surface, surface.Faces(f, 0)) - centre;
      const Eigen::Vector3d p1 = Position(surface, surface.Faces(f, 1)) - centre;
      const Eigen::Vector3d p2 = Position(surface, surface.Faces(f, 2)) - centre;
      sixVolume += p0.dot(p1.cross(p2));
    }
    component.SignedVolume = sixVolume / 6.0;
    component.EulerCharacteristic =
      component.VertexCount - component.EdgeCount + component.FaceCount;
    component.Genus = (2 - component.EulerCharacteristic) / 2;
    for (int k = 0; k < 3; ++k)
    {
      component.BoundsMin[k] = lo[k];
      component.BoundsMax[k] = hi[k];
    }
  }
}

bool BoundsContain(const SurfaceComponent& outer, const SurfaceComponent& inner)
{
  for (int k = 0; k < 3; ++k)
  {
    if (inner.BoundsMin[k] < outer.BoundsMin[k] || inner.BoundsMax[k] > outer.BoundsMax[k])
    {
      return false;
    }
  }
  return true;
}

/// Depth = number of components enclosing a vertex of this one. The components do not cross,
/// so any vertex tells; the winding number is about +-1 inside and 0 outside, cut at 1/2.
void FindNesting(const SurfaceMesh& surface, SurfaceCheckReport& report)
{
  const int count = static_cast<int>(report.Components.size());
  std::vector<std::vector<int>> enclosing(count);
  for (int a = 0; a < count; ++a)
  {
    const SurfaceComponent& inner = report.Components[a];
    const Eigen::Vector3d probe = Position(surface, surface.Faces(inner.Faces.front(), 0));
    for (int b = 0; b < count; ++b)
    {
      if (b != a && BoundsContain(report.Components[b], inner) &&
        std::abs(ComponentWindingNumber(surface, report, b, probe)) > 0.5)
      {
        enclosing[a].push_back(b);
      }
    }
    report.Components[a].NestingDepth = static_cast<int>(enclosing[a].size());
  }
  report.EnclosedVolume = 0.0;
  for (int a = 0; a < count; ++a)
  {
    SurfaceComponent& component = report.Components[a];
    for (int b : enclosing[a])
    {
      if (component.Parent < 0 ||
        report.Components[b].NestingDepth > report.Components[component.Parent].NestingDepth)
      {
        component.Parent = b;
      }
    }
    const double volume = std::abs(component.SignedVolume);
    report.EnclosedVolume += component.IsVoid() ? -volume : volume;
  }
}
} // namespace

int SurfaceCheckReport::VoidCount() const
{
  return static_cast<int>(std::count_if(this->Components.begin(),
    this->Components.end(),
    [](const SurfaceComponent& c) { return c.IsVoid(); }));
}

std::string SurfaceCheckReport::Summary() const
{
  std::ostringstream text;
  if (!this->IsValid())
  {
    for (const std::string& problem : this->Problems)
    {
      text << problem << "\n";
    }
    return text.str();
  }
  text << this->Components.size() << " component(s), enclosed volume " << this->EnclosedVolume
       << "\n";
  for (std::size_t c = 0; c < this->Components.size(); ++c)
  {
    const SurfaceComponent& component = this->Components[c];
    text << "  component " << c << ": " << component.FaceCount << " triangles, genus "
         << component.Genus << ", signed volume " << component.SignedVolume << ", depth "
         << component.NestingDepth << (component.IsVoid() ? " (void)" : " (body)")
         << (component.OrientedOutward() ? "" : ", oriented inwards") << "\n";
  }
  if (this->UnusedVertexCount > 0)
  {
    text << "  " << this->UnusedVertexCount << " vertices in no triangle (ignored)\n";
  }
  return text.str();
}

double ComponentWindingNumber(const SurfaceMesh& surface,
  const SurfaceCheckReport& report,
  int component,
  const Eigen::Vector3d& point)
{
  // Van Oosterom and Strackee's solid angle of each triangle seen from `point`, summed.
  double solidAngle = 0.0;
  for (int f : report.Components[component].Faces)
  {
    const Eigen::Vector3d a = Position(surface, surface.Faces(f, 0)) - point;
    const Eigen::Vector3d b = Position(surface, surface.Faces(f, 1)) - point;
    const Eigen::Vector3d c = Position(surface, surface.Faces(f, 2)) - point;
    const double la = a.norm();
    const double lb = b.norm();
    const double lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    solidAngle += 2.0 * std::atan2(numerator, denominator);
  }
  constexpr double pi = 3.14159265358979323846;
  return solidAngle / (4.0 * pi);
}

Status CheckClosedSurface(const SurfaceMesh& surface, SurfaceCheckReport& report)
{
  report = SurfaceCheckReport();
  if (surface.Faces.rows() == 0)
  {
    report.Problems.push_back("the surface has no triangles");
  }
  else
  {
    std::vector<char> used(surface.Vertices.rows(), 0);
    CheckIndicesAndCoordinates(surface, report, used);
    if (report.IsValid())
    {
      report.BoundingBoxDiagonal = BoundingBoxDiagonal(surface, used);
      CheckElements(surface, used, report);
      const std::vector<HalfEdge> halfEdges = CheckEdges(surface, report);
      const bool edgesOk = report.BoundaryEdgeCount == 0 && report.NonManifoldEdgeCount == 0 &&
        report.MisorientedEdgeCount == 0;
      if (edgesOk)
      {
        CheckVertexFans(surface, report); // needs manifold, oriented edges
      }
      if (report.IsValid())
      {
        FindComponents(surface, halfEdges, report);
        FindNesting(surface, report);
      }
    }
  }
  if (report.IsValid())
  {
    return Status::Success();
  }
  std::ostringstream message;
  message << "invalid surface (" << surface.Vertices.rows() << " vertices, " << surface.Faces.rows()
          << " triangles): ";
  for (std::size_t i = 0; i < report.Problems.size(); ++i)
  {
    message << (i == 0 ? "" : "; ") << report.Problems[i];
  }
  return Status::Failure(message.str());
}

SurfaceAngleReport MeasureSurfaceAngles(const SurfaceMesh& surface, double thresholdDegrees)
{
  constexpr double degrees = 180.0 / 3.14159265358979323846;
  SurfaceAngleReport report;
  for (int f = 0; f < surface.Faces.rows(); ++f)
  {
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d p = Position(surface, surface.Faces(f, k));
      const Eigen::Vector3d a = Position(surface, surface.Faces(f, (k + 1) % 3)) - p;
      const Eigen::Vector3d b = Position(surface, surface.Faces(f, (k + 2) % 3)) - p;
      // atan2 of |a x b| and a.b stays accurate for the tiny angles this looks for.
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b)) * degrees;
      smallest = std::min(smallest, std::isfinite(angle) ? angle : 0.0);
    }
    if (smallest < thresholdDegrees)
    {
      ++report.SmallAngleFaceCount;
    }
    if (smallest < report.SmallestAngleDegrees)
    {
      report.SmallestAngleDegrees = smallest;
      report.SmallestAngleFace = f;
    }
  }
  return report;
}

} // namespace polycubehex
