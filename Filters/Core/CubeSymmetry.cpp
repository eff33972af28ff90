// SPDX-License-Identifier: BSD-3-Clause
#include "CubeSymmetry.h"

#include <Eigen/LU>

#include <array>
#include <limits>

namespace polycubehex
{

namespace
{

// Row i of rotation g holds Sign[g][i] in column Perm[g][i]: then trace(Pi M) is three products,
// which matters because the matching and the singular-edge search try all 24 on every face.
struct CubeGroup
{
  std::array<Eigen::Matrix3i, CubeRotationCount> Matrices;
  int Perm[CubeRotationCount][3];
  int Sign[CubeRotationCount][3];
  int Product[CubeRotationCount][CubeRotationCount];
  int Inverse[CubeRotationCount];
  CubeRotationClass Class[CubeRotationCount];

  CubeGroup()
  {
    // Permutations in lexicographic order and signs from +++ so that the identity comes first.
    const int perms[6][3] = {
      { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
    };
    int count = 0;
    for (const auto& perm : perms)
    {
      for (int signs = 0; signs < 8; ++signs)
      {
        Eigen::Matrix3i m = Eigen::Matrix3i::Zero();
        int s[3];
        for (int i = 0; i < 3; ++i)
        {
          s[i] = (signs >> i) & 1 ? -1 : 1;
          m(i, perm[i]) = s[i];
        }
        if (m.cast<double>().determinant() < 0.0)
        {
          continue;
        }
        this->Matrices[count] = m;
        for (int i = 0; i < 3; ++i)
        {
          this->Perm[count][i] = perm[i];
          this->Sign[count][i] = s[i];
        }
        ++count;
      }
    }
    for (int a = 0; a < CubeRotationCount; ++a)
    {
      for (int b = 0; b < CubeRotationCount; ++b)
      {
        this->Product[a][b] = this->Find(this->Matrices[a] * this->Matrices[b]);
      }
      this->Inverse[a] = this->Find(this->Matrices[a].transpose());
      const Eigen::Matrix3i& m = this->Matrices[a];
      const int trace = m.trace();
      const bool diagonal = m(0, 0) != 0 && m(1, 1) != 0 && m(2, 2) != 0;
      // trace = 1 + 2 cos(angle): 3 identity, 1 quarter turn, 0 third turn, -1 half turn.
      this->Class[a] = trace == 3 ? CubeRotationClass::Identity
        : trace == 1              ? CubeRotationClass::QuarterTurn
        : trace == 0              ? CubeRotationClass::ThirdTurn
        : diagonal                ? CubeRotationClass::HalfTurnFace
                                  : CubeRotationClass::HalfTurnEdge;
    }
  }

  int Find(const Eigen::Matrix3i& m) const
  {
    for (int g = 0; g < CubeRotationCount; ++g)
    {
      if (this->Matrices[g] == m)
      {
        return g;
      }
    }
    return -1;
  }
};

const CubeGroup& Group()
{
  static const CubeGroup group;
  return group;
}

} // namespace

const Eigen::Matrix3i& CubeRotation(int index)
{
  return Group().Matrices[index];
}

Eigen::Matrix3d CubeRotationMatrix(int index)
{
  return Group().Matrices[index].cast<double>();
}

int CubeRotationIndex(const Eigen::Matrix3i& pi)
{
  return Group().Find(pi);
}

int CubeRotationProduct(int a, int b)
{
  return Group().Product[a][b];
}

int CubeRotationInverse(int a)
{
  return Group().Inverse[a];
}

CubeRotationClass ClassifyCubeRotation(int index)
{
  return Group().Class[index];
}

int BestCubeRotationOfProduct(const Eigen::Matrix3d& m, double* trace)
{
  const CubeGroup& group = Group();
  int best = 0;
  double bestTrace = -std::numeric_limits<double>::infinity();
  for (int g = 0; g < CubeRotationCount; ++g)
  {
    // trace(Pi M) = sum_i Pi(i, p(i)) M(p(i), i).
    const double value = group.Sign[g][0] * m(group.Perm[g][0], 0) +
      group.Sign[g][1] * m(group.Perm[g][1], 1) + group.Sign[g][2] * m(group.Perm[g][2], 2);
    // Strictly greater: ties go to the lowest index, so the choice is deterministic.
    if (value > bestTrace)
    {
      bestTrace = value;
      best = g;
    }
  }
  if (trace)
  {
    *trace = bestTrace;
  }
  return best;
}

int BestCubeRotation(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to, double* error)
{
  // ||Pi A - B||^2 = ||A||^2 + ||B||^2 - 2 trace(Pi A B^T).
  double trace = 0.0;
  const int best = BestCubeRotationOfProduct(from * to.transpose(), &trace);
  if (error)
  {
    *error = from.squaredNorm() + to.squaredNorm() - 2.0 * trace;
  }
  return best;
}

} // namespace polycubehex
