// SPDX-License-Identifier: BSD-3-Clause
#include "HexScaledJacobian.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace polycubehex
{
namespace
{
/// Normalised triple product; 0 when a vector has (numerically) zero length.
double NormalisedDeterminant(const Eigen::Vector3d& a,
  const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  const double lengths = a.squaredNorm() * b.squaredNorm() * c.squaredNorm();
  if (!(lengths > std::numeric_limits<double>::min()))
  {
    return 0.0;
  }
  return a.dot(b.cross(c)) / std::sqrt(lengths);
}
} // namespace

double HexCornerScaledJacobian(const Eigen::Matrix<double, 8, 3>& x, int which)
{
  if (which < 8)
  {
    const Eigen::Vector3d origin = x.row(which).transpose();
    return NormalisedDeterminant(x.row(HexCornerNeighbours[which][0]).transpose() - origin,
      x.row(HexCornerNeighbours[which][1]).transpose() - origin,
      x.row(HexCornerNeighbours[which][2]).transpose() - origin);
  }
  // The Jacobian at the centre uses the three principal axes (differences of opposite faces).
  const Eigen::Vector3d e1 =
    (x.row(1) + x.row(2) + x.row(5) + x.row(6) - x.row(0) - x.row(3) - x.row(4) - x.row(7))
      .transpose();
  const Eigen::Vector3d e2 =
    (x.row(2) + x.row(3) + x.row(6) + x.row(7) - x.row(0) - x.row(1) - x.row(4) - x.row(5))
      .transpose();
  const Eigen::Vector3d e3 =
    (x.row(4) + x.row(5) + x.row(6) + x.row(7) - x.row(0) - x.row(1) - x.row(2) - x.row(3))
      .transpose();
  return NormalisedDeterminant(e1, e2, e3);
}

std::array<double, 9> HexCornerScaledJacobians(const Eigen::Matrix<double, 8, 3>& x)
{
  std::array<double, 9> result;
  for (int which = 0; which < 9; ++which)
  {
    result[static_cast<size_t>(which)] = HexCornerScaledJacobian(x, which);
  }
  return result;
}

double HexScaledJacobian(const Eigen::Matrix<double, 8, 3>& x)
{
  const std::array<double, 9> values = HexCornerScaledJacobians(x);
  return *std::min_element(values.begin(), values.end());
}

double HexScaledJacobian(const HexMesh& mesh, int h)
{
  Eigen::Matrix<double, 8, 3> corners;
  for (int k = 0; k < 8; ++k)
  {
    corners.row(k) = mesh.Vertices.row(mesh.Cells(h, k));
  }
  return HexScaledJacobian(corners);
}

Eigen::VectorXd ComputeHexScaledJacobians(const HexMesh& mesh)
{
  Eigen::VectorXd result(mesh.Cells.rows());
  for (Eigen::Index h = 0; h < mesh.Cells.rows(); ++h)
  {
    result[h] = HexScaledJacobian(mesh, static_cast<int>(h));
  }
  return result;
}

HexQualitySummary SummarizeHexQuality(const Eigen::VectorXd& quality)
{
  HexQualitySummary summary;
  if (quality.size() > 0)
  {
    summary.Min = quality.minCoeff();
    summary.Mean = quality.mean();
    summary.Inverted = static_cast<int>((quality.array() <= 0.0).count());
  }
  return summary;
}

bool BetterHexQuality(const HexQualitySummary& quality,
  const HexQualitySummary& other,
  double minimumMargin)
{
  if (quality.Inverted != other.Inverted)
  {
    return quality.Inverted < other.Inverted;
  }
  if (std::abs(quality.Min - other.Min) > minimumMargin)
  {
    return quality.Min > other.Min;
  }
  if (quality.Mean != other.Mean)
  {
    return quality.Mean > other.Mean;
  }
  return quality.Min > other.Min;
}

double MeanHexEdgeLength(const HexMesh& mesh)
{
  const Eigen::Index hexCount = mesh.Cells.rows();
  double mean = 0.0;
  for (Eigen::Index h = 0; h < hexCount; ++h)
  {
    mean += (mesh.Vertices.row(mesh.Cells(h, 0)) - mesh.Vertices.row(mesh.Cells(h, 6))).norm() /
      (std::sqrt(3.0) * static_cast<double>(hexCount));
  }
  return mean;
}

} // namespace polycubehex
