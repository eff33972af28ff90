// SPDX-License-Identifier: BSD-3-Clause
// Hard linear relations between vertex coordinates, eliminated by identifying variables
// (Fang et al. 2016, eq. 8: "each cut vertex copy is Pi times the other plus the cut's
// translation"), never by a dense elimination.
//
// The unknowns are the 3#V coordinates x_i (i = 3v + a) and a few extra unknowns t_k (the cut
// translations, 3 per cut). Every relation has the form
//     x_i = s x_j + sum_k c_k t_k + d,   s = +-1   (a copy across a cut, or two coordinates on one
//                                                   chart plane: s = 1, no t)
//     x_i = d                                      (a coordinate held fixed)
// Coordinates joined by relations form classes, each with one representative coordinate r, so
// that every x_i = s_i x_r + (affine function of t). A relation inside one class either fixes its
// representative in terms of t (when the signs disagree, as across a half turn) or is a linear
// equation on t alone (as around a chart that crosses a cut); those equations are solved by
// Gaussian elimination on the few t. The result is x = B y + c with y = the free representatives
// and the free t: sparse, one non-zero per coordinate plus its t terms.
#pragma once

#include "PolycubeNewton.h"
#include "Status.h"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace polycubehex
{

class CoordinateRelations
{
public:
  /// @param vertexCount  #V (3#V coordinates)
  /// @param extraCount   number of extra unknowns t_k
  /// @param extraAxis    #extraCount: the coordinate axis each t_k mostly moves (for the
  ///                     solver's per-axis preconditioner), e.g. k % 3 for 3 per cut
  CoordinateRelations(int vertexCount, int extraCount, std::vector<int> extraAxis);

  /// x_i = sign x_j + sum (coefficient * t_k) + constant. Returns false (and records an
  /// inconsistency for Build) only for an index out of range.
  bool Relate(int i,
    int j,
    double sign,
    const std::vector<std::pair<int, double>>& extras = {},
    double constant = 0.0);

  /// x_i = value.
  bool Fix(int i, double value);

  /// The reduction x = B y + Offset. Fails when the relations contradict each other (e.g. two
  /// fixed values for one class, or t equations without a solution), naming the first.
  Status Build(VariableReduction& reduction);

  /// After Build: the extra unknowns for a variable vector y.
  Eigen::VectorXd Extras(const Eigen::VectorXd& y) const;

  /// After Build: the variables (indices into y) that are free extras, i.e. the unknown
  /// translations the relations left free.
  const std::vector<int>& FreeExtraVariables() const { return this->FreeExtraVariable; }

  /// After Build: the number of relations that fixed a representative or constrained t.
  int ClosedLoopCount() const { return this->LoopCount; }

private:
  /// An affine function of the extras: sum Terms + Constant.
  struct Affine
  {
    std::vector<std::pair<int, double>> Terms;
    double Constant = 0.0;
    void Add(const Affine& other, double scale);
  };
  struct Node
  {
    int Parent = 0;
    double Sign = 1.0; ///< x_i = Sign x_Parent + Offset
    Affine Offset;
  };

  int Find(int i); ///< compresses paths, composing signs and offsets
  void FixRoot(int root, const Affine& value); ///< x_root = value (an equation if already fixed)

  int CoordinateCount = 0;
  int ExtraCount = 0;
  std::vector<int> ExtraAxis;
  std::vector<Node> Nodes;
  std::vector<bool> RootFixed;
  std::vector<Affine> RootValue; ///< x_r as a function of t, where RootFixed
  std::vector<Affine> ExtraEquations; ///< each = 0
  std::string Error;
  int LoopCount = 0;

  // Built by Build: t = ExtraMap * (y at FreeExtraVariable) + ExtraOffset.
  std::vector<int> FreeExtraVariable;
  Eigen::MatrixXd ExtraMap;
  Eigen::VectorXd ExtraOffset;
};

} // namespace polycubehex
