// SPDX-License-Identifier: BSD-3-Clause
#include "TriangleGrid.h"

#include <algorithm>

namespace polycubehex
{

Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p,
  const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const double d1 = ab.dot(p - a);
  const double d2 = ac.dot(p - a);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return a;
  }
  const double d3 = ab.dot(p - b);
  const double d4 = ac.dot(p - b);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return a + (d1 / (d1 - d3)) * ab;
  }
  const double d5 = ab.dot(p - c);
  const double d6 = ac.dot(p - c);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denominator = va + vb + vc;
  return a + ab * (vb / denominator) + ac * (vc / denominator);
}

TriangleGrid::TriangleGrid(const Points& vertices, const Triangles& faces, double cellSize)
  : Vertices(vertices)
  , Faces(faces)
{
  if (vertices.rows() == 0 || faces.rows() == 0)
  {
    this->Start.assign(2, 0);
    return;
  }
  const Eigen::Vector3d low = vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d high = vertices.colwise().maxCoeff().transpose();
  const Eigen::Vector3d extent = (high - low).cwiseMax(1e-12);
  // At most about 2^21 cells.
  this->Cell = std::max(cellSize, std::cbrt(extent.prod() / 2097152.0));
  this->Origin = low;
  for (int a = 0; a < 3; ++a)
  {
    this->Dims[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / this->Cell)));
  }
  std::vector<std::vector<int>> bins(
    static_cast<size_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2]);
  this->FaceBox.reserve(static_cast<size_t>(faces.rows()));
  for (int f = 0; f < faces.rows(); ++f)
  {
    Eigen::AlignedBox3d box;
    for (int c = 0; c < 3; ++c)
    {
      box.extend(vertices.row(faces(f, c)).transpose());
    }
    this->FaceBox.push_back(box);
    const std::array<int, 3> from = this->CellOf(box.min());
    const std::array<int, 3> to = this->CellOf(box.max());
    for (int i = from[0]; i <= to[0]; ++i)
    {
      for (int j = from[1]; j <= to[1]; ++j)
      {
        for (int k = from[2]; k <= to[2]; ++k)
        {
          bins[this->Index(i, j, k)].push_back(f);
        }
      }
    }
  }
  this->Start.assign(bins.size() + 1, 0);
  for (size_t b = 0; b < bins.size(); ++b)
  {
    this->Start[b + 1] = this->Start[b] + static_cast<int>(bins[b].size());
  }
  this->Items.reserve(static_cast<size_t>(this->Start.back()));
  for (const auto& bin : bins)
  {
    this->Items.insert(this->Items.end(), bin.begin(), bin.end());
  }
}

int TriangleGrid::MaxRing() const
{
  return std::max({ this->Dims[0], this->Dims[1], this->Dims[2] });
}

double TriangleGrid::WallDistance(const Eigen::Vector3d& p) const
{
  double wall = std::numeric_limits<double>::max();
  for (int a = 0; a < 3; ++a)
  {
    const double x = (p[a] - this->Origin[a]) / this->Cell;
    if (!(x >= 0.0 && x < this->Dims[a]))
    {
      return 0.0;
    }
    const double fraction = x - std::floor(x);
    wall = std::min(wall, std::min(fraction, 1.0 - fraction));
  }
  return std::max(0.0, wall - 1e-9) * this->Cell;
}

std::array<int, 3> TriangleGrid::CellOf(const Eigen::Vector3d& p) const
{
  std::array<int, 3> cell;
  for (int a = 0; a < 3; ++a)
  {
    const double x = std::floor((p[a] - this->Origin[a]) / this->Cell);
    cell[a] = static_cast<int>(std::clamp(x, 0.0, static_cast<double>(this->Dims[a] - 1)));
  }
  return cell;
}

} // namespace polycubehex
