// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeRotation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace polycubehex
{

namespace
{

constexpr double Pi = 3.14159265358979323846;

std::vector<Eigen::Vector3d> AreaVectors(const Points& x, const Triangles& faces)
{
  std::vector<Eigen::Vector3d> u(static_cast<size_t>(faces.rows()));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    const Eigen::Vector3d p0 = x.row(faces(f, 0)).transpose();
    u[static_cast<size_t>(f)] =
      0.5 * (x.row(faces(f, 1)).transpose() - p0).cross(x.row(faces(f, 2)).transpose() - p0);
  }
  return u;
}

double L1Sum(const std::vector<Eigen::Vector3d>& u, const Eigen::Matrix3d& r)
{
  double sum = 0.0;
  for (const auto& v : u)
  {
    sum += (r * v).lpNorm<1>();
  }
  return sum;
}

Eigen::Matrix3d Euler(double a, double b, double c)
{
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) *
    Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(c, Eigen::Vector3d::UnitX()))
    .toRotationMatrix();
}

} // namespace

double AreaWeightedL1Norm(const Points& x, const Triangles& faces, const Eigen::Matrix3d& R)
{
  const std::vector<Eigen::Vector3d> u = AreaVectors(x, faces);
  double area = 0.0;
  for (const auto& v : u)
  {
    area += v.norm();
  }
  return area > 0.0 ? L1Sum(u, R) / area : 1.0;
}

Eigen::Matrix3d ComputeAxisAligningRotation(const Points& x, const Triangles& faces)
{
  const std::vector<Eigen::Vector3d> u = AreaVectors(x, faces);
  if (u.empty())
  {
    return Eigen::Matrix3d::Identity();
  }

  // Bin the area vectors by direction: the coarse search then costs little per rotation.
  constexpr int bins = 16;
  std::map<std::array<int, 3>, Eigen::Vector3d> binned;
  for (const auto& v : u)
  {
    const double norm = v.norm();
    if (!(norm > 0.0))
    {
      continue;
    }
    std::array<int, 3> key;
    for (int a = 0; a < 3; ++a)
    {
      key[static_cast<size_t>(a)] =
        std::min(bins - 1, static_cast<int>(std::floor((v(a) / norm + 1.0) * 0.5 * bins)));
    }
    auto it = binned.emplace(key, Eigen::Vector3d::Zero()).first;
    it->second += v;
  }
  std::vector<Eigen::Vector3d> coarse;
  coarse.reserve(binned.size());
  for (const auto& entry : binned)
  {
    coarse.push_back(entry.second);
  }

  // The energy is invariant under the cube symmetries acting on the left, so the first angle
  // only needs a quarter turn.
  const double step = 7.5 * Pi / 180.0;
  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  double bestValue = L1Sum(coarse, best);
  for (int i = 0; i < 12; ++i)
  {
    for (int j = -12; j <= 12; ++j)
    {
      for (int k = 0; k < 48; ++k)
      {
        const Eigen::Matrix3d r = Euler(i * step, j * step, k * step);
        const double value = L1Sum(coarse, r);
        if (value < bestValue - 1e-12 * std::abs(bestValue))
        {
          bestValue = value;
          best = r;
        }
      }
    }
  }

  // Pattern search on all faces with small rotations about the axes.
  bestValue = L1Sum(u, best);
  double angle = step;
  while (angle > 1e-6)
  {
    bool improved = false;
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int sign = -1; sign <= 1; sign += 2)
      {
        const Eigen::Matrix3d r =
          Eigen::AngleAxisd(sign * angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix() * best;
        const double value = L1Sum(u, r);
        if (value < bestValue - 1e-14 * std::abs(bestValue))
        {
          bestValue = value;
          best = r;
          improved = true;
        }
      }
    }
    if (!improved)
    {
      angle *= 0.5;
    }
  }
  // Of the 24 equivalent rotations S R (S a cube symmetry), return the one closest to the
  // identity, so that the model turns as little as possible.
  Eigen::Matrix3d closest = best;
  double bestTrace = -4.0;
  const int permutations[6][3] = {
    { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
  };
  for (const auto& p : permutations)
  {
    for (int signs = 0; signs < 8; ++signs)
    {
      Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 3; ++i)
      {
        s(i, p[i]) = (signs >> i) & 1 ? -1.0 : 1.0;
      }
      if (s.determinant() < 0.0)
      {
        continue;
      }
      const Eigen::Matrix3d candidate = s * best;
      if (candidate.trace() > bestTrace + 1e-12)
      {
        bestTrace = candidate.trace();
        closest = candidate;
      }
    }
  }
  // Re-orthonormalise against round-off from the products.
  const Eigen::Quaterniond q(closest);
  return q.normalized().toRotationMatrix();
}

} // namespace polycubehex
