// SPDX-License-Identifier: BSD-3-Clause
#include "TetGeometry.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace polycubehex
{

double TetSignedVolume(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c,
  const Eigen::Vector3d& d)
{
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

double TetSignedVolume(const Points& x, const Tets& cells, int t)
{
  return TetSignedVolume(x.row(cells(t, 0)).transpose(),
    x.row(cells(t, 1)).transpose(),
    x.row(cells(t, 2)).transpose(),
    x.row(cells(t, 3)).transpose());
}

namespace
{
struct FaceKey
{
  std::array<int, 3> Sorted;
  int Tet;
  int Local;
};
} // namespace

void ComputeTetTopology(int vertexCount, const Tets& cells, TetTopology& topology)
{
  const int tetCount = static_cast<int>(cells.rows());
  std::vector<FaceKey> keys;
  keys.reserve(4 * static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      FaceKey key;
      for (int c = 0; c < 3; ++c)
      {
        key.Sorted[c] = cells(t, TetFaceTable[k][c]);
      }
      std::sort(key.Sorted.begin(), key.Sorted.end());
      key.Tet = t;
      key.Local = k;
      keys.push_back(key);
    }
  }
  std::sort(keys.begin(),
    keys.end(),
    [](const FaceKey& a, const FaceKey& b)
    {
      return a.Sorted != b.Sorted ? a.Sorted < b.Sorted
                                  : (a.Tet != b.Tet ? a.Tet < b.Tet : a.Local < b.Local);
    });

  topology.Neighbors.setConstant(tetCount, 4, -1);
  topology.TetFaceToBoundaryFace.setConstant(tetCount, 4, -1);
  topology.NonManifoldFaceCount = 0;
  std::vector<std::array<int, 3>> boundary;
  topology.BoundaryFaceTet.clear();
  topology.BoundaryFaceLocal.clear();
  for (size_t i = 0; i < keys.size();)
  {
    size_t j = i + 1;
    while (j < keys.size() && keys[j].Sorted == keys[i].Sorted)
    {
      ++j;
    }
    if (j - i == 1)
    {
      const FaceKey& key = keys[i];
      std::array<int, 3> face;
      for (int c = 0; c < 3; ++c)
      {
        face[c] = cells(key.Tet, TetFaceTable[key.Local][c]);
      }
      topology.TetFaceToBoundaryFace(key.Tet, key.Local) = static_cast<int>(boundary.size());
      boundary.push_back(face);
      topology.BoundaryFaceTet.push_back(key.Tet);
      topology.BoundaryFaceLocal.push_back(key.Local);
    }
    else if (j - i == 2)
    {
      topology.Neighbors(keys[i].Tet, keys[i].Local) = keys[i + 1].Tet;
      topology.Neighbors(keys[i + 1].Tet, keys[i + 1].Local) = keys[i].Tet;
    }
    else
    {
      ++topology.NonManifoldFaceCount;
    }
    i = j;
  }
  topology.BoundaryFaces.resize(static_cast<Eigen::Index>(boundary.size()), 3);
  for (size_t f = 0; f < boundary.size(); ++f)
  {
    for (int c = 0; c < 3; ++c)
    {
      topology.BoundaryFaces(static_cast<Eigen::Index>(f), c) = boundary[f][c];
    }
  }

  topology.IsBoundaryVertex.assign(static_cast<size_t>(vertexCount), false);
  for (const auto& face : boundary)
  {
    for (int v : face)
    {
      topology.IsBoundaryVertex[static_cast<size_t>(v)] = true;
    }
  }

  constexpr int tetEdges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  topology.Edges.clear();
  topology.Edges.reserve(6 * static_cast<size_t>(tetCount));
  for (int t = 0; t < tetCount; ++t)
  {
    for (const auto& e : tetEdges)
    {
      const int a = cells(t, e[0]);
      const int b = cells(t, e[1]);
      topology.Edges.push_back({ std::min(a, b), std::max(a, b) });
    }
  }
  std::sort(topology.Edges.begin(), topology.Edges.end());
  topology.Edges.erase(
    std::unique(topology.Edges.begin(), topology.Edges.end()), topology.Edges.end());
}

Triangles ComputeFaceAdjacency(int vertexCount, const Triangles& faces)
{
  (void)vertexCount;
  const int faceCount = static_cast<int>(faces.rows());
  struct HalfEdge
  {
    int A, B, Face, Local;
  };
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * static_cast<size_t>(faceCount));
  for (int f = 0; f < faceCount; ++f)
  {
    for (int e = 0; e < 3; ++e)
    {
      const int a = faces(f, e);
      const int b = faces(f, (e + 1) % 3);
      halfEdges.push_back({ std::min(a, b), std::max(a, b), f, e });
    }
  }
  std::sort(halfEdges.begin(),
    halfEdges.end(),
    [](const HalfEdge& x, const HalfEdge& y)
    { return x.A != y.A ? x.A < y.A : (x.B != y.B ? x.B < y.B : x.Face < y.Face); });
  Triangles adjacency;
  adjacency.setConstant(faceCount, 3, -1);
  for (size_t i = 0; i < halfEdges.size();)
  {
    size_t j = i + 1;
    while (
      j < halfEdges.size() && halfEdges[j].A == halfEdges[i].A && halfEdges[j].B == halfEdges[i].B)
    {
      ++j;
    }
    if (j - i == 2)
    {
      adjacency(halfEdges[i].Face, halfEdges[i].Local) = halfEdges[i + 1].Face;
      adjacency(halfEdges[i + 1].Face, halfEdges[i + 1].Local) = halfEdges[i].Face;
    }
    i = j;
  }
  return adjacency;
}

void PolarRotation(const Eigen::Matrix3d& J, Eigen::Matrix3d& R, Eigen::Vector3d& sigma)
{
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  const Eigen::Matrix3d V = svd.matrixV();
  sigma = svd.singularValues();
  if (U.determinant() * V.determinant() < 0.0)
  {
    // Flip the smallest singular direction so that R is a proper rotation.
    U.col(2) = -U.col(2);
    sigma(2) = -sigma(2);
  }
  R = U * V.transpose();
}

UnitDiagonalFrame ComputeUnitDiagonalFrame(const Points& x)
{
  UnitDiagonalFrame frame;
  if (x.rows() == 0)
  {
    return frame;
  }
  const Eigen::RowVector3d lo = x.colwise().minCoeff();
  const Eigen::RowVector3d hi = x.colwise().maxCoeff();
  frame.Center = 0.5 * (lo + hi);
  const double diagonal = (hi - lo).norm();
  frame.Scale = diagonal > 0.0 && std::isfinite(diagonal) ? diagonal : 1.0;
  return frame;
}

Points ToUnitDiagonal(const UnitDiagonalFrame& frame, const Points& x)
{
  Points y = (x.rowwise() - frame.Center) / frame.Scale;
  return y;
}

Points FromUnitDiagonal(const UnitDiagonalFrame& frame, const Points& x)
{
  Points y = (x * frame.Scale).rowwise() + frame.Center;
  return y;
}

double ComputeFaceAreasAndNormals(const Points& x,
  const Triangles& faces,
  const Eigen::Vector3d& zeroAreaNormal,
  std::vector<double>& area,
  std::vector<Eigen::Vector3d>& normal)
{
  const int faceCount = static_cast<int>(faces.rows());
  area.assign(static_cast<size_t>(faceCount), 0.0);
  normal.assign(static_cast<size_t>(faceCount), zeroAreaNormal);
  double totalArea = 0.0;
  for (int f = 0; f < faceCount; ++f)
  {
    const Eigen::Vector3d a = x.row(faces(f, 0)).transpose();
    const Eigen::Vector3d b = x.row(faces(f, 1)).transpose();
    const Eigen::Vector3d c = x.row(faces(f, 2)).transpose();
    const Eigen::Vector3d n = (b - a).cross(c - a);
    area[f] = 0.5 * n.norm();
    if (area[f] > 0.0)
    {
      normal[f] = n.normalized();
    }
    totalArea += area[f];
  }
  return totalArea;
}

} // namespace polycubehex
