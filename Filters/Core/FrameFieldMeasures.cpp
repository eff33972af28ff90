// SPDX-License-Identifier: BSD-3-Clause
#include "FrameFieldMeasures.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polycubehex
{

namespace
{

// The local face of a tet opposite each local vertex (VTK's face table).
constexpr int FaceOpposite[4] = { 1, 2, 0, 3 };

// Squared distance from p to the triangle (a, b, c), by the region of its closest point.
double PointTriangleDistance2(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const Eigen::Vector3d ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return ap.squaredNorm(); // vertex a
  }
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return bp.squaredNorm(); // vertex b
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double v = d1 / (d1 - d3);
    return (ap - v * ab).squaredNorm(); // edge ab
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return cp.squaredNorm(); // vertex c
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double w = d2 / (d2 - d6);
    return (ap - w * ac).squaredNorm(); // edge ac
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return (bp - w * (c - b)).squaredNorm(); // edge bc
  }
  const double denominator = va + vb + vc;
  if (!(std::fabs(denominator) > 0.0))
  {
    return std::min({ ap.squaredNorm(), bp.squaredNorm(), cp.squaredNorm() });
  }
  const double v = vb / denominator;
  const double w = vc / denominator;
  return (ap - v * ab - w * ac).squaredNorm(); // inside
}

// Distances to the boundary surface: an exact point-triangle test, skipped for triangles whose
// bounding sphere is farther than the best distance so far.
class BoundaryDistance
{
public:
  BoundaryDistance(const TetMesh& mesh, const TetTopology& topology)
    : Mesh(mesh)
    , Faces(topology.BoundaryFaces)
  {
    const int faceCount = static_cast<int>(this->Faces.rows());
    this->Centres.resize(static_cast<size_t>(faceCount));
    this->Radii.resize(static_cast<size_t>(faceCount));
    for (int f = 0; f < faceCount; ++f)
    {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int c = 0; c < 3; ++c)
      {
        centre += this->Vertex(f, c) / 3.0;
      }
      double radius = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        radius = std::max(radius, (this->Vertex(f, c) - centre).norm());
      }
      this->Centres[f] = centre;
      this->Radii[f] = radius;
    }
  }

  double operator()(const Eigen::Vector3d& p) const
  {
    const int faceCount = static_cast<int>(this->Faces.rows());
    if (faceCount == 0)
    {
      return 0.0;
    }
    // Start from the triangle with the nearest centre, then prune by bounding spheres.
    int nearest = 0;
    double nearestCentre = std::numeric_limits<double>::infinity();
    for (int f = 0; f < faceCount; ++f)
    {
      const double d = (this->Centres[f] - p).squaredNorm();
      if (d < nearestCentre)
      {
        nearestCentre = d;
        nearest = f;
      }
    }
    double best2 = PointTriangleDistance2(
      p, this->Vertex(nearest, 0), this->Vertex(nearest, 1), this->Vertex(nearest, 2));
    double best = std::sqrt(best2);
    for (int f = 0; f < faceCount; ++f)
    {
      if ((this->Centres[f] - p).norm() - this->Radii[f] >= best)
      {
        continue;
      }
      const double d2 =
        PointTriangleDistance2(p, this->Vertex(f, 0), this->Vertex(f, 1), this->Vertex(f, 2));
      if (d2 < best2)
      {
        best2 = d2;
        best = std::sqrt(d2);
      }
    }
    return best;
  }

private:
  Eigen::Vector3d Vertex(int f, int c) const
  {
    return this->Mesh.Vertices.row(this->Faces(f, c)).transpose();
  }
  const TetMesh& Mesh;
  const Triangles& Faces;
  std::vector<Eigen::Vector3d> Centres;
  std::vector<double> Radii;
};

} // namespace

std::vector<SingularEdge> FindSingularEdges(const TetMesh& mesh,
  const TetTopology& topology,
  const std::vector<Eigen::Matrix3d>& frames)
{
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  // Best-aligning rotation from tet t to its neighbour across local face k.
  Tets best(tetCount, 4);
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int s = topology.Neighbors(t, k);
      best(t, k) = s < 0 ? -1 : (s > t ? BestCubeRotation(frames[t], frames[s]) : -1);
    }
  }
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int s = topology.Neighbors(t, k);
      if (s >= 0 && s < t)
      {
        // The same face seen from s: its rotation is the inverse (||Pi^T R_s - R_t|| is
        // ||R_s - Pi R_t||), so both directions agree on ties.
        for (int l = 0; l < 4; ++l)
        {
          if (topology.Neighbors(s, l) == t)
          {
            best(t, k) = CubeRotationInverse(best(s, l));
          }
        }
      }
    }
  }

  // Tets around each edge.
  struct EdgeTet
  {
    int A, B, Tet;
  };
  std::vector<EdgeTet> incidence;
  incidence.reserve(6 * static_cast<size_t>(tetCount));
  constexpr int localEdges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  for (int t = 0; t < tetCount; ++t)
  {
    for (const auto& e : localEdges)
    {
      const int a = mesh.Cells(t, e[0]);
      const int b = mesh.Cells(t, e[1]);
      incidence.push_back({ std::min(a, b), std::max(a, b), t });
    }
  }
  std::sort(incidence.begin(),
    incidence.end(),
    [](const EdgeTet& x, const EdgeTet& y)
    { return x.A != y.A ? x.A < y.A : (x.B != y.B ? x.B < y.B : x.Tet < y.Tet); });

  std::vector<SingularEdge> singular;
  for (size_t i = 0; i < incidence.size();)
  {
    size_t j = i;
    while (
      j < incidence.size() && incidence[j].A == incidence[i].A && incidence[j].B == incidence[i].B)
    {
      ++j;
    }
    const int a = incidence[i].A;
    const int b = incidence[i].B;
    const int ringSize = static_cast<int>(j - i);
    const int start = incidence[i].Tet;
    i = j;

    // Walk the ring: in each tet, the two faces holding the edge are the faces opposite the
    // two other vertices; leave through the one that does not lead back.
    int holonomy = 0;
    int previous = -1;
    int current = start;
    int steps = 0;
    bool closed = false;
    while (steps <= ringSize)
    {
      int others[2];
      int n = 0;
      for (int l = 0; l < 4; ++l)
      {
        const int v = mesh.Cells(current, l);
        if (v != a && v != b && n < 2)
        {
          others[n++] = l;
        }
      }
      if (n != 2)
      {
        break;
      }
      int face = FaceOpposite[others[0]];
      int next = topology.Neighbors(current, face);
      if (next == previous && previous >= 0)
      {
        face = FaceOpposite[others[1]];
        next = topology.Neighbors(current, face);
      }
      if (next < 0)
      {
        break; // a boundary edge
      }
      holonomy = CubeRotationProduct(best(current, face), holonomy);
      previous = current;
      current = next;
      ++steps;
      if (current == start)
      {
        closed = true;
        break;
      }
    }
    if (!closed || steps != ringSize || holonomy == 0)
    {
      continue;
    }
    SingularEdge edge;
    edge.Vertices = { a, b };
    edge.Holonomy = holonomy;
    edge.Type = ClassifyCubeRotation(holonomy);
    edge.Interior = !topology.IsBoundaryVertex[a] && !topology.IsBoundaryVertex[b];
    singular.push_back(edge);
  }

  if (!singular.empty())
  {
    const Eigen::RowVector3d lo = mesh.Vertices.colwise().minCoeff();
    const Eigen::RowVector3d hi = mesh.Vertices.colwise().maxCoeff();
    const double diagonal = (hi - lo).norm();
    const BoundaryDistance distance(mesh, topology);
    for (SingularEdge& edge : singular)
    {
      const Eigen::Vector3d midpoint = 0.5 *
        (mesh.Vertices.row(edge.Vertices[0]) + mesh.Vertices.row(edge.Vertices[1])).transpose();
      edge.Depth = diagonal > 0.0 ? distance(midpoint) / diagonal : 0.0;
    }
  }
  return singular;
}

double ComputeBoundaryAlignmentError(const TetMesh& mesh,
  const TetTopology& topology,
  const std::vector<Eigen::Matrix3d>& frames)
{
  const double degrees = 180.0 / 3.14159265358979323846;
  double weighted = 0.0;
  double total = 0.0;
  for (int f = 0; f < topology.BoundaryFaces.rows(); ++f)
  {
    const Eigen::Vector3d p0 = mesh.Vertices.row(topology.BoundaryFaces(f, 0)).transpose();
    const Eigen::Vector3d p1 = mesh.Vertices.row(topology.BoundaryFaces(f, 1)).transpose();
    const Eigen::Vector3d p2 = mesh.Vertices.row(topology.BoundaryFaces(f, 2)).transpose();
    const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
    const double area = 0.5 * n.norm();
    if (!(area > 0.0))
    {
      continue;
    }
    const Eigen::Matrix3d& frame = frames[topology.BoundaryFaceTet[f]];
    double cosine = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double length = frame.row(a).norm();
      if (length > 0.0)
      {
        cosine =
          std::max(cosine, std::fabs(frame.row(a).dot(n.transpose())) / (length * 2.0 * area));
      }
    }
    weighted += area * std::acos(std::min(1.0, cosine)) * degrees;
    total += area;
  }
  return total > 0.0 ? weighted / total : 0.0;
}

} // namespace polycubehex
