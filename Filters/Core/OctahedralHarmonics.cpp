// SPDX-License-Identifier: BSD-3-Clause
#include "OctahedralHarmonics.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <array>
#include <cmath>

namespace polycubehex
{

namespace
{

constexpr double Pi = 3.14159265358979323846;

// A polynomial in x, y, z of degree <= 4 in each variable: coefficient of x^i y^j z^k at
// 25 i + 5 j + k. Only used once, to build the harmonics from their textbook factorised forms.
struct Poly
{
  std::array<double, 125> C{};

  static Poly Monomial(int i, int j, int k, double c = 1.0)
  {
    Poly p;
    p.C[25 * i + 5 * j + k] = c;
    return p;
  }
  Poly operator+(const Poly& o) const
  {
    Poly r;
    for (int n = 0; n < 125; ++n)
    {
      r.C[n] = this->C[n] + o.C[n];
    }
    return r;
  }
  Poly operator*(double s) const
  {
    Poly r;
    for (int n = 0; n < 125; ++n)
    {
      r.C[n] = this->C[n] * s;
    }
    return r;
  }
  Poly operator-(const Poly& o) const { return *this + o * -1.0; }
  Poly operator*(const Poly& o) const
  {
    Poly r;
    for (int a = 0; a < 125; ++a)
    {
      if (this->C[a] == 0.0)
      {
        continue;
      }
      for (int b = 0; b < 125; ++b)
      {
        if (o.C[b] == 0.0)
        {
          continue;
        }
        const int i = a / 25 + b / 25;
        const int j = (a / 5) % 5 + (b / 5) % 5;
        const int k = a % 5 + b % 5;
        r.C[25 * i + 5 * j + k] += this->C[a] * o.C[b]; // degree 4 never overflows an exponent
      }
    }
    return r;
  }
};

// The 15 monomials of degree 4 and their exponents.
struct QuarticBasis
{
  int Exp[15][3];
  QuarticBasis()
  {
    int n = 0;
    for (int i = 4; i >= 0; --i)
    {
      for (int j = 4 - i; j >= 0; --j)
      {
        this->Exp[n][0] = i;
        this->Exp[n][1] = j;
        this->Exp[n][2] = 4 - i - j;
        ++n;
      }
    }
  }
};

using Monomials = Eigen::Matrix<double, 15, 1>;
using HarmonicMatrix = Eigen::Matrix<double, 9, 15>;

struct Harmonics
{
  QuarticBasis Basis;
  HarmonicMatrix B; // Y(x) = B m(x), m the 15 monomials
  double Norm = 0.0;
  double K = 0.0; // q(R) . Y(x) = K (sum_a (r_a . x)^4 - 3/5 |x|^4)

  Harmonics()
  {
    const Poly x = Poly::Monomial(1, 0, 0);
    const Poly y = Poly::Monomial(0, 1, 0);
    const Poly z = Poly::Monomial(0, 0, 1);
    const Poly r2 = x * x + y * y + z * z;
    const Poly z2 = z * z;
    // Real solid harmonics of degree 4, m = -4..4, before normalisation.
    const Poly unnormalised[9] = {
      x * y * (x * x - y * y),
      (x * x * 3.0 - y * y) * y * z,
      x * y * (z2 * 7.0 - r2),
      y * z * (z2 * 7.0 - r2 * 3.0),
      z2 * z2 * 35.0 - z2 * r2 * 30.0 + r2 * r2 * 3.0,
      x * z * (z2 * 7.0 - r2 * 3.0),
      (x * x - y * y) * (z2 * 7.0 - r2),
      (x * x - y * y * 3.0) * x * z,
      x * x * x * x - x * x * y * y * 6.0 + y * y * y * y,
    };
    for (int m = 0; m < 9; ++m)
    {
      for (int n = 0; n < 15; ++n)
      {
        const int* e = this->Basis.Exp[n];
        this->B(m, n) = unnormalised[m].C[25 * e[0] + 5 * e[1] + e[2]];
      }
    }
    // Normalise on the sphere with a quadrature exact for degree 8: Gauss-Legendre with 5 nodes
    // in z times 10 uniform angles (only the axially symmetric part of a product survives the
    // angular sum, and it is a polynomial of degree 8 in z).
    const double nodes[5] = {
      -0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640
    };
    const double weights[5] = { 0.2369268850561891,
      0.4786286704993665,
      0.5688888888888889,
      0.4786286704993665,
      0.2369268850561891 };
    Eigen::Matrix<double, 9, 1> squares = Eigen::Matrix<double, 9, 1>::Zero();
    for (int a = 0; a < 5; ++a)
    {
      for (int b = 0; b < 10; ++b)
      {
        const double phi = 2.0 * Pi * b / 10.0;
        const double s = std::sqrt(1.0 - nodes[a] * nodes[a]);
        const Eigen::Matrix<double, 9, 1> yv = this->B *
          this->EvalMonomials(Eigen::Vector3d(s * std::cos(phi), s * std::sin(phi), nodes[a]));
        squares += (weights[a] * 2.0 * Pi / 10.0) * yv.cwiseProduct(yv);
      }
    }
    for (int m = 0; m < 9; ++m)
    {
      this->B.row(m) /= std::sqrt(squares(m));
    }
    const OctahedralVector q0 = this->FrameVector(Eigen::Matrix3d::Identity());
    this->Norm = q0.norm();
    this->K = 2.5 * q0.dot(this->B * this->EvalMonomials(Eigen::Vector3d::UnitZ()));
  }

  Monomials EvalMonomials(const Eigen::Vector3d& p) const
  {
    double pw[3][5];
    for (int c = 0; c < 3; ++c)
    {
      pw[c][0] = 1.0;
      for (int e = 1; e < 5; ++e)
      {
        pw[c][e] = pw[c][e - 1] * p(c);
      }
    }
    Monomials m;
    for (int n = 0; n < 15; ++n)
    {
      const int* e = this->Basis.Exp[n];
      m(n) = pw[0][e[0]] * pw[1][e[1]] * pw[2][e[2]];
    }
    return m;
  }

  OctahedralVector FrameVector(const Eigen::Matrix3d& frame) const
  {
    const Monomials sum = this->EvalMonomials(frame.row(0).transpose()) +
      this->EvalMonomials(frame.row(1).transpose()) + this->EvalMonomials(frame.row(2).transpose());
    return this->B * sum;
  }

  // p(x) = sum_n c_n x^e_n with its gradient and Hessian.
  void Evaluate(const Monomials& c,
    const Eigen::Vector3d& p,
    double& value,
    Eigen::Vector3d& gradient,
    Eigen::Matrix3d& hessian) const
  {
    double pw[3][5];
    for (int d = 0; d < 3; ++d)
    {
      pw[d][0] = 1.0;
      for (int e = 1; e < 5; ++e)
      {
        pw[d][e] = pw[d][e - 1] * p(d);
      }
    }
    auto power = [&pw](int d, int e) { return e < 0 ? 0.0 : pw[d][e]; };
    value = 0.0;
    gradient.setZero();
    hessian.setZero();
    for (int n = 0; n < 15; ++n)
    {
      if (c(n) == 0.0)
      {
        continue;
      }
      const int* e = this->Basis.Exp[n];
      value += c(n) * pw[0][e[0]] * pw[1][e[1]] * pw[2][e[2]];
      for (int a = 0; a < 3; ++a)
      {
        int ea[3] = { e[0], e[1], e[2] };
        const double fa = ea[a];
        if (fa == 0.0)
        {
          continue;
        }
        --ea[a];
        gradient(a) += c(n) * fa * power(0, ea[0]) * power(1, ea[1]) * power(2, ea[2]);
        for (int b = a; b < 3; ++b)
        {
          int eb[3] = { ea[0], ea[1], ea[2] };
          const double fb = eb[b];
          if (fb == 0.0)
          {
            continue;
          }
          --eb[b];
          const double h = c(n) * fa * fb * power(0, eb[0]) * power(1, eb[1]) * power(2, eb[2]);
          hessian(a, b) += h;
          if (b != a)
          {
            hessian(b, a) += h;
          }
        }
      }
    }
  }
};

const Harmonics& GetHarmonics()
{
  static const Harmonics harmonics;
  return harmonics;
}

Eigen::Matrix3d Cross(const Eigen::Vector3d& r)
{
  Eigen::Matrix3d m;
  m << 0.0, -r(2), r(1), r(2), 0.0, -r(0), -r(1), r(0), 0.0;
  return m;
}

// F(R) = q(R) . q = sum_a p(r_a), with its gradient and Hessian for R <- exp([w]) R acting on
// the rows: F(w) ~ F + g . w + w^T H w / 2.
double Objective(const Harmonics& h,
  const Monomials& c,
  const Eigen::Matrix3d& frame,
  Eigen::Vector3d* gradient,
  Eigen::Matrix3d* hessian)
{
  if (!gradient)
  {
    return c.dot(h.EvalMonomials(frame.row(0).transpose()) +
      h.EvalMonomials(frame.row(1).transpose()) + h.EvalMonomials(frame.row(2).transpose()));
  }
  double total = 0.0;
  gradient->setZero();
  hessian->setZero();
  for (int a = 0; a < 3; ++a)
  {
    const Eigen::Vector3d r = frame.row(a).transpose();
    double value;
    Eigen::Vector3d g;
    Eigen::Matrix3d hp;
    h.Evaluate(c, r, value, g, hp);
    total += value;
    *gradient += r.cross(g);
    const Eigen::Matrix3d rx = Cross(r);
    *hessian += 0.5 * (g * r.transpose() + r * g.transpose()) -
      g.dot(r) * Eigen::Matrix3d::Identity() + rx.transpose() * hp * rx;
  }
  return total;
}

} // namespace

OctahedralVector EvaluateDegree4Harmonics(const Eigen::Vector3d& x)
{
  const Harmonics& h = GetHarmonics();
  return h.B * h.EvalMonomials(x);
}

OctahedralVector FrameToOctahedral(const Eigen::Matrix3d& frame)
{
  return GetHarmonics().FrameVector(frame);
}

double OctahedralNorm()
{
  return GetHarmonics().Norm;
}

Eigen::Matrix3d OctahedralToFrame(const OctahedralVector& q, double* fit)
{
  const Harmonics& h = GetHarmonics();
  const double qNorm = q.norm();
  if (!(qNorm > 1e-300) || !std::isfinite(qNorm))
  {
    if (fit)
    {
      *fit = 0.0;
    }
    return Eigen::Matrix3d::Identity();
  }
  const Monomials c = h.B.transpose() * q;
  const double scale = qNorm * h.Norm;

  // Initial guess: with s = ||q|| / ||q(R)||, p(x) / (s K) + 3/5 |x|^4 ~ sum_a (r_a . x)^4, whose
  // Hessian at a unit d is 12 sum_a (r_a . d)^2 r_a r_a^T: its eigenvectors are the axes as long
  // as the (r_a . d)^2 differ, so try a few generic d and keep the best frame.
  const double sK = qNorm / h.Norm * h.K;
  const Eigen::Vector3d directions[3] = { Eigen::Vector3d(0.267, 0.535, 0.802).normalized(),
    Eigen::Vector3d(0.802, -0.267, 0.535).normalized(),
    Eigen::Vector3d(-0.535, 0.802, 0.267).normalized() };
  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  double bestValue = Objective(h, c, best, nullptr, nullptr);
  for (const Eigen::Vector3d& d : directions)
  {
    double value;
    Eigen::Vector3d g;
    Eigen::Matrix3d hp;
    h.Evaluate(c, d, value, g, hp);
    const Eigen::Matrix3d tensor =
      hp / sK + 0.6 * (4.0 * Eigen::Matrix3d::Identity() + 8.0 * d * d.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(tensor);
    Eigen::Matrix3d frame = eigen.eigenvectors().transpose();
    if (frame.determinant() < 0.0)
    {
      frame.row(2) *= -1.0;
    }
    const double candidate = Objective(h, c, frame, nullptr, nullptr);
    if (candidate > bestValue)
    {
      bestValue = candidate;
      best = frame;
    }
  }

  // Newton ascent on SO(3) with a shift that keeps the model concave and a step limit.
  Eigen::Matrix3d frame = best;
  double value = bestValue;
  for (int iteration = 0; iteration < 50; ++iteration)
  {
    Eigen::Vector3d g;
    Eigen::Matrix3d hs;
    value = Objective(h, c, frame, &g, &hs);
    if (g.norm() <= 1e-14 * scale)
    {
      break;
    }
    // Plain Newton where the model is concave (the usual case near the optimum), else shifted.
    const Eigen::Matrix3d symmetric = 0.5 * (hs + hs.transpose());
    Eigen::LLT<Eigen::Matrix3d> concave(-symmetric);
    Eigen::Vector3d w;
    if (concave.info() == Eigen::Success)
    {
      w = concave.solve(g);
    }
    else
    {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(symmetric);
      const double shift = eigen.eigenvalues()(2) + 1e-3 * scale;
      w = -(symmetric - shift * Eigen::Matrix3d::Identity()).ldlt().solve(g);
    }
    if (!w.allFinite())
    {
      w = g / scale;
    }
    const bool newton = concave.info() == Eigen::Success;
    bool fullStep = true;
    const double maxStep = 0.3;
    if (w.norm() > maxStep)
    {
      w *= maxStep / w.norm();
      fullStep = false;
    }
    bool accepted = false;
    for (int halving = 0; halving < 30 && !accepted; ++halving)
    {
      const double angle = w.norm();
      const Eigen::Matrix3d rotation = angle > 0.0
        ? Eigen::AngleAxisd(angle, w / angle).toRotationMatrix()
        : Eigen::Matrix3d::Identity();
      // Rows rotate: r_a <- Q r_a, so R <- R Q^T.
      const Eigen::Matrix3d trial = frame * rotation.transpose();
      const double trialValue = Objective(h, c, trial, nullptr, nullptr);
      // Near the optimum the gain is below the rounding of F: accept such steps.
      if (trialValue >= value - 1e-14 * scale)
      {
        frame = trial;
        value = trialValue;
        accepted = true;
      }
      else
      {
        w *= 0.5;
        fullStep = false;
      }
    }
    // Newton converges quadratically: after a full step of 1e-8 the error is at rounding level.
    if (!accepted || w.norm() <= 1e-15 || (newton && fullStep && w.norm() <= 1e-8))
    {
      break;
    }
  }
  // Re-orthonormalise away the rounding of many small rotations.
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(frame, Eigen::ComputeFullU | Eigen::ComputeFullV);
  frame = svd.matrixU() * svd.matrixV().transpose();
  if (fit)
  {
    *fit = Objective(h, c, frame, nullptr, nullptr) / scale;
  }
  return frame;
}

NormalAlignedCircle ComputeNormalAlignedCircle(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d axis = n.normalized();
  // Any unit vector orthogonal to the normal.
  Eigen::Vector3d b1 = std::fabs(axis(0)) < 0.6 ? Eigen::Vector3d::UnitX().cross(axis)
                                                : Eigen::Vector3d::UnitY().cross(axis);
  b1.normalize();
  const Eigen::Vector3d b2 = axis.cross(b1);
  auto twisted = [&](double t)
  {
    Eigen::Matrix3d frame;
    frame.row(0) = (std::cos(t) * b1 + std::sin(t) * b2).transpose();
    frame.row(1) = (-std::sin(t) * b1 + std::cos(t) * b2).transpose();
    frame.row(2) = axis.transpose();
    return FrameToOctahedral(frame);
  };
  // q(t) = C + cos(4t) U + sin(4t) V at t = 0, pi/8, pi/4.
  const OctahedralVector q0 = twisted(0.0);
  const OctahedralVector q1 = twisted(Pi / 8.0);
  const OctahedralVector q2 = twisted(Pi / 4.0);
  NormalAlignedCircle circle;
  circle.Center = 0.5 * (q0 + q2);
  circle.U = 0.5 * (q0 - q2);
  circle.V = q1 - circle.Center;
  return circle;
}

} // namespace polycubehex
