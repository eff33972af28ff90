// SPDX-License-Identifier: BSD-3-Clause
// Sparse Cholesky factorisation of a symmetric positive definite matrix: CHOLMOD's supernodal
// LL^T (dense BLAS kernels on the supernodes) with a METIS nested-dissection ordering. The only
// file that includes CHOLMOD (SuiteSparse, already a dependency of Ceres).
//
// Measured on one per-axis block of kitten's Newton matrix (14.3k rows): Eigen's SimplicialLLT
// with its AMD ordering has 2.37M non-zeros in L, factorises in 1.1 s and solves in 14 ms;
// this has 1.72M, factorises in 0.25 s and solves in 8.5 ms (2 shared cores).
#pragma once

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <memory>

namespace polycubehex
{

class SparseCholesky
{
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// The ordering and the symbolic factorisation for the pattern of `a` (square, compressed,
  /// full or lower storage: only the lower triangle is read).
  void AnalyzePattern(const Eigen::SparseMatrix<double>& a);

  /// Factorises a + shift I (a with the analysed pattern). False when it is not positive
  /// definite.
  bool Factorize(const Eigen::SparseMatrix<double>& a, double shift = 0.0);

  /// (a + shift I)^-1 b after a successful Factorize.
  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const;

private:
  struct Implementation;
  std::unique_ptr<Implementation> Data;
};

/// While alive, OpenMP parallel regions run on a single thread. CHOLMOD's supernodal
/// factorisation opens a region of up to four threads per supernode (to clear and assemble it),
/// too little work to pay for the threads, and the polycube solver already factorises its three
/// blocks on threads of its own: on 2 cores those regions cost more in thread wake-ups and
/// spinning than they save (kitten's l1
/// polycube: 37-39 s wall and 6.7 s system time with them, 30-33 s and 2.7 s without, the same
/// polycube). The setting (max-active-levels) is global to the process, so create the scope on
/// one thread around the factorisations only; it restores the previous value. Without an OpenMP
/// runtime in the process it does nothing.
class SerialOpenMPScope
{
public:
  SerialOpenMPScope();
  ~SerialOpenMPScope();
  SerialOpenMPScope(const SerialOpenMPScope&) = delete;
  SerialOpenMPScope& operator=(const SerialOpenMPScope&) = delete;

private:
  int Saved = -1;
};

} // namespace polycubehex
