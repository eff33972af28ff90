// SPDX-License-Identifier: BSD-3-Clause
#include "SparseCholesky.h"

#include <Eigen/CholmodSupport>

#include <dlfcn.h>

namespace polycubehex
{

struct SparseCholesky::Implementation
{
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> Solver;
};

SparseCholesky::SparseCholesky()
  : Data(new Implementation)
{
  cholmod_common& common = this->Data->Solver.cholmod();
  // METIS only: on tet meshes it gives about 25% less fill than AMD (CHOLMOD's default tries
  // AMD first and keeps it when its fill looks acceptable).
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_METIS;
  common.print = 0; // a matrix that is not positive definite is reported through Factorize
}

SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::AnalyzePattern(const Eigen::SparseMatrix<double>& a)
{
  this->Data->Solver.analyzePattern(a);
}

bool SparseCholesky::Factorize(const Eigen::SparseMatrix<double>& a, double shift)
{
  this->Data->Solver.setShift(shift);
  this->Data->Solver.factorize(a);
  return this->Data->Solver.info() == Eigen::Success;
}

Eigen::VectorXd SparseCholesky::Solve(const Eigen::VectorXd& b) const
{
  return this->Data->Solver.solve(b);
}

namespace
{
// The OpenMP runtime's own entry points, looked up in the process (CHOLMOD loads the runtime),
// so that the core needs no OpenMP flags of its own: compiled with them, Eigen would start
// parallelising its products too.
using GetLevels = int (*)();
using SetLevels = void (*)(int);
GetLevels OpenMPGetMaxActiveLevels()
{
  return reinterpret_cast<GetLevels>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
}
SetLevels OpenMPSetMaxActiveLevels()
{
  return reinterpret_cast<SetLevels>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
}
} // namespace

SerialOpenMPScope::SerialOpenMPScope()
{
  const GetLevels get = OpenMPGetMaxActiveLevels();
  const SetLevels set = OpenMPSetMaxActiveLevels();
  if (get && set)
  {
    this->Saved = get();
    set(0); // no active parallel region: every region runs on the thread that meets it
  }
}

SerialOpenMPScope::~SerialOpenMPScope()
{
  if (this->Saved >= 0)
  {
    OpenMPSetMaxActiveLevels()(this->Saved);
  }
}

} // namespace polycubehex
