// SPDX-License-Identifier: BSD-3-Clause
// SparseCholesky solves a shifted grid Laplacian to round-off, refuses a matrix that is not
// positive definite, and refactorises with new values on the analysed pattern; SerialOpenMPScope
// switches OpenMP's parallel regions off while it lives and restores the previous setting.
#include "SparseCholesky.h"

#include "TestAssert.h"

#include <dlfcn.h>

#include <iostream>
#include <vector>

using namespace polycubehex;

namespace
{
/// The 5-point Laplacian of an n x n grid, full storage.
Eigen::SparseMatrix<double> GridLaplacian(int n)
{
  std::vector<Eigen::Triplet<double>> entries;
  auto id = [n](int i, int j) { return i + n * j; };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      entries.emplace_back(id(i, j), id(i, j), 4.0);
      if (i + 1 < n)
      {
        entries.emplace_back(id(i, j), id(i + 1, j), -1.0);
        entries.emplace_back(id(i + 1, j), id(i, j), -1.0);
      }
      if (j + 1 < n)
      {
        entries.emplace_back(id(i, j), id(i, j + 1), -1.0);
        entries.emplace_back(id(i, j + 1), id(i, j), -1.0);
      }
    }
  }
  Eigen::SparseMatrix<double> a(n * n, n * n);
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  return a;
}
} // namespace

int main()
{
  const Eigen::SparseMatrix<double> a = GridLaplacian(40);
  const Eigen::VectorXd expected = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);

  SparseCholesky solver;
  solver.AnalyzePattern(a);
  PCH_CHECK(solver.Factorize(a, 0.5));
  Eigen::SparseMatrix<double> shifted = a;
  shifted.diagonal().array() += 0.5;
  Eigen::VectorXd x = solver.Solve(shifted * expected);
  PCH_CHECK_NEAR((x - expected).lpNorm<Eigen::Infinity>(), 0.0, 1e-10);

  // New values on the same pattern: the Laplacian scaled by 3, no shift.
  const Eigen::SparseMatrix<double> scaled = 3.0 * a;
  PCH_CHECK(solver.Factorize(scaled));
  x = solver.Solve(scaled * expected);
  PCH_CHECK_NEAR((x - expected).lpNorm<Eigen::Infinity>(), 0.0, 1e-10);

  // Indefinite: the Laplacian shifted below its smallest eigenvalue (about 0.012 for n = 40).
  PCH_CHECK(!solver.Factorize(a, -1.0));

  // The scope, through the OpenMP runtime that CHOLMOD brings into the process (none: nothing
  // to check).
  using GetLevels = int (*)();
  const auto get = reinterpret_cast<GetLevels>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  if (get)
  {
    const int before = get();
    {
      const SerialOpenMPScope serial;
      PCH_CHECK(get() == 0);
      // A factorisation inside the scope gives the same answer.
      PCH_CHECK(solver.Factorize(a, 0.5));
      x = solver.Solve(shifted * expected);
      PCH_CHECK_NEAR((x - expected).lpNorm<Eigen::Infinity>(), 0.0, 1e-10);
    }
    PCH_CHECK(get() == before);
    std::cout << "OpenMP max-active-levels " << before << ", 0 inside the scope\n";
    PCH_CHECK(before > 0);
  }
  return polycubehex_test::FailureCount();
}
