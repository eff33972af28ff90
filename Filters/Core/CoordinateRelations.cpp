// SPDX-License-Identifier: BSD-3-Clause
#include "CoordinateRelations.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace polycubehex
{

void CoordinateRelations::Affine::Add(const Affine& other, double scale)
{
  for (const auto& term : other.Terms)
  {
    auto it = std::find_if(this->Terms.begin(),
      this->Terms.end(),
      [&term](const std::pair<int, double>& mine) { return mine.first == term.first; });
    if (it == this->Terms.end())
    {
      this->Terms.emplace_back(term.first, scale * term.second);
    }
    else
    {
      it->second += scale * term.second;
    }
  }
  this->Constant += scale * other.Constant;
}

CoordinateRelations::CoordinateRelations(int vertexCount, int extraCount, std::vector<int> extraAxis)
  : CoordinateCount(3 * vertexCount)
  , ExtraCount(extraCount)
  , ExtraAxis(std::move(extraAxis))
  , Nodes(static_cast<size_t>(3 * vertexCount))
  , RootFixed(static_cast<size_t>(3 * vertexCount), false)
  , RootValue(static_cast<size_t>(3 * vertexCount))
{
  for (int i = 0; i < this->CoordinateCount; ++i)
  {
    this->Nodes[static_cast<size_t>(i)].Parent = i;
  }
  this->ExtraAxis.resize(static_cast<size_t>(extraCount), 0);
}

int CoordinateRelations::Find(int i)
{
  std::vector<int> path;
  int root = i;
  while (this->Nodes[static_cast<size_t>(root)].Parent != root)
  {
    path.push_back(root);
    root = this->Nodes[static_cast<size_t>(root)].Parent;
  }
  // From the node nearest the root outwards, so that each parent already points at the root.
  for (auto it = path.rbegin(); it != path.rend(); ++it)
  {
    Node& node = this->Nodes[static_cast<size_t>(*it)];
    if (node.Parent != root)
    {
      const Node& parent = this->Nodes[static_cast<size_t>(node.Parent)];
      node.Offset.Add(parent.Offset, node.Sign); // x = s (s_p x_r + o_p) + o
      node.Sign *= parent.Sign;
      node.Parent = root;
    }
  }
  return root;
}

namespace
{
bool IsZero(double value)
{
  return std::abs(value) < 1e-9;
}
} // namespace

bool CoordinateRelations::Relate(int i,
  int j,
  double sign,
  const std::vector<std::pair<int, double>>& extras,
  double constant)
{
  if (i < 0 || j < 0 || i >= this->CoordinateCount || j >= this->CoordinateCount)
  {
    this->Error = "a relation names a coordinate out of range";
    return false;
  }
  for (const auto& term : extras)
  {
    if (term.first < 0 || term.first >= this->ExtraCount)
    {
      this->Error = "a relation names an extra unknown out of range";
      return false;
    }
  }
  Affine e;
  e.Terms = extras;
  e.Constant = constant;
  const int ri = this->Find(i);
  const int rj = this->Find(j);
  const Node ni = this->Nodes[static_cast<size_t>(i)];
  const Node nj = this->Nodes[static_cast<size_t>(j)];
  const double si = i == ri ? 1.0 : ni.Sign;
  const double sj = j == rj ? 1.0 : nj.Sign;
  // s_i x_ri + o_i = s (s_j x_rj + o_j) + e, so x_ri = s_i s s_j x_rj + s_i (s o_j + e - o_i).
  Affine rest = e;
  if (j != rj)
  {
    rest.Add(nj.Offset, sign);
  }
  if (i != ri)
  {
    rest.Add(ni.Offset, -1.0);
  }
  Affine offset;
  offset.Add(rest, si);
  const double composed = si * sign * sj;
  if (ri != rj)
  {
    Node& node = this->Nodes[static_cast<size_t>(ri)];
    node.Parent = rj;
    node.Sign = composed;
    node.Offset = offset;
    if (this->RootFixed[static_cast<size_t>(ri)])
    {
      // x_ri = f and x_ri = S x_rj + O give x_rj = S (f - O).
      Affine value = this->RootValue[static_cast<size_t>(ri)];
      value.Add(offset, -1.0);
      Affine scaled;
      scaled.Add(value, composed);
      this->RootFixed[static_cast<size_t>(ri)] = false;
      this->FixRoot(rj, scaled);
    }
    return true;
  }
  ++this->LoopCount;
  if (composed == 1.0)
  {
    this->ExtraEquations.push_back(offset); // x_r = x_r + offset: offset = 0
  }
  else
  {
    Affine half; // x_r = -x_r + offset: x_r = offset / 2
    half.Add(offset, 0.5);
    this->FixRoot(ri, half);
  }
  return true;
}

bool CoordinateRelations::Fix(int i, double value)
{
  if (i < 0 || i >= this->CoordinateCount)
  {
    this->Error = "a fixed coordinate is out of range";
    return false;
  }
  const int root = this->Find(i);
  const Node node = this->Nodes[static_cast<size_t>(i)];
  // s x_r + o = value, so x_r = s (value - o).
  Affine target;
  target.Constant = value;
  if (i != root)
  {
    target.Add(node.Offset, -1.0);
  }
  Affine scaled;
  scaled.Add(target, i == root ? 1.0 : node.Sign);
  this->FixRoot(root, scaled);
  return true;
}

void CoordinateRelations::FixRoot(int root, const Affine& value)
{
  if (this->RootFixed[static_cast<size_t>(root)])
  {
    Affine equation = this->RootValue[static_cast<size_t>(root)];
    equation.Add(value, -1.0);
    this->ExtraEquations.push_back(equation); // two values for one class: an equation on t
  }
  else
  {
    this->RootFixed[static_cast<size_t>(root)] = true;
    this->RootValue[static_cast<size_t>(root)] = value;
  }
}

Status CoordinateRelations::Build(VariableReduction& reduction)
{
  if (!this->Error.empty())
  {
    return Status::Failure("coordinate relations: " + this->Error);
  }
  const int e = this->ExtraCount;

  // 1. The equations on the extras, A t = b, to reduced row echelon form.
  const int m = static_cast<int>(this->ExtraEquations.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, e);
  Eigen::VectorXd b(m);
  for (int r = 0; r < m; ++r)
  {
    for (const auto& term : this->ExtraEquations[static_cast<size_t>(r)].Terms)
    {
      a(r, term.first) += term.second;
    }
    b(r) = -this->ExtraEquations[static_cast<size_t>(r)].Constant;
  }
  std::vector<int> pivotColumn;
  int row = 0;
  for (int c = 0; c < e && row < m; ++c)
  {
    Eigen::Index best = 0;
    const double size = a.col(c).tail(m - row).cwiseAbs().maxCoeff(&best);
    if (IsZero(size))
    {
      continue;
    }
    a.row(row).swap(a.row(row + static_cast<int>(best)));
    std::swap(b(row), b(row + static_cast<int>(best)));
    const double pivot = a(row, c);
    a.row(row) /= pivot;
    b(row) /= pivot;
    for (int r = 0; r < m; ++r)
    {
      if (r != row && a(r, c) != 0.0)
      {
        const double factor = a(r, c);
        a.row(r) -= factor * a.row(row);
        b(r) -= factor * b(row);
      }
    }
    pivotColumn.push_back(c);
    ++row;
  }
  for (int r = row; r < m; ++r)
  {
    if (!IsZero(b(r)))
    {
      std::ostringstream message;
      message << "coordinate relations: the hard relations contradict each other (an equation "
                 "on the cut translations is off by "
              << b(r) << ")";
      return Status::Failure(message.str());
    }
  }

  // 2. Variables: free representatives, then free extras.
  std::vector<int> variableOfRoot(static_cast<size_t>(this->CoordinateCount), -1);
  reduction = VariableReduction();
  reduction.IsIdentity = false;
  for (int i = 0; i < this->CoordinateCount; ++i)
  {
    if (this->Find(i) == i && !this->RootFixed[static_cast<size_t>(i)])
    {
      variableOfRoot[static_cast<size_t>(i)] = static_cast<int>(reduction.VariableAxis.size());
      reduction.VariableAxis.push_back(i % 3);
    }
  }
  std::vector<bool> isPivot(static_cast<size_t>(e), false);
  for (int c : pivotColumn)
  {
    isPivot[static_cast<size_t>(c)] = true;
  }
  std::vector<int> variableOfExtra(static_cast<size_t>(e), -1);
  for (int k = 0; k < e; ++k)
  {
    if (!isPivot[static_cast<size_t>(k)])
    {
      variableOfExtra[static_cast<size_t>(k)] = static_cast<int>(reduction.VariableAxis.size());
      reduction.VariableAxis.push_back(this->ExtraAxis[static_cast<size_t>(k)]);
    }
  }
  const int variableCount = static_cast<int>(reduction.VariableAxis.size());
  // t = ExtraMap y_free + ExtraOffset over the free extras' variables: a free t is its
  // variable; a pivot t = b - sum a t_free.
  std::vector<int> freeSlot(static_cast<size_t>(e), -1);
  this->FreeExtraVariable.clear();
  for (int k = 0; k < e; ++k)
  {
    if (!isPivot[static_cast<size_t>(k)])
    {
      freeSlot[static_cast<size_t>(k)] = static_cast<int>(this->FreeExtraVariable.size());
      this->FreeExtraVariable.push_back(variableOfExtra[static_cast<size_t>(k)]);
    }
  }
  const int freeCount = static_cast<int>(this->FreeExtraVariable.size());
  this->ExtraMap = Eigen::MatrixXd::Zero(e, freeCount);
  this->ExtraOffset = Eigen::VectorXd::Zero(e);
  for (int k = 0; k < e; ++k)
  {
    if (!isPivot[static_cast<size_t>(k)])
    {
      this->ExtraMap(k, freeSlot[static_cast<size_t>(k)]) = 1.0;
    }
  }
  for (size_t r = 0; r < pivotColumn.size(); ++r)
  {
    const int k = pivotColumn[r];
    this->ExtraOffset(k) = b(static_cast<int>(r));
    for (int c = 0; c < e; ++c)
    {
      if (!isPivot[static_cast<size_t>(c)] && a(static_cast<int>(r), c) != 0.0)
      {
        this->ExtraMap(k, freeSlot[static_cast<size_t>(c)]) -= a(static_cast<int>(r), c);
      }
    }
  }

  // 3. Every coordinate: x_i = s_i x_r + o_i(t), x_r a variable or a function of t.
  std::vector<Eigen::Triplet<double>> triplets;
  reduction.Offset.setZero(this->CoordinateCount);
  auto addAffine = [&](int i, const Affine& f, double scale)
  {
    reduction.Offset(i) += scale * f.Constant;
    for (const auto& term : f.Terms)
    {
      reduction.Offset(i) += scale * term.second * this->ExtraOffset(term.first);
      for (int slot = 0; slot < freeCount; ++slot)
      {
        const double coefficient = this->ExtraMap(term.first, slot);
        if (coefficient != 0.0)
        {
          triplets.emplace_back(
            i, this->FreeExtraVariable[static_cast<size_t>(slot)], scale * term.second * coefficient);
        }
      }
    }
  };
  for (int i = 0; i < this->CoordinateCount; ++i)
  {
    const int root = this->Find(i);
    const Node& node = this->Nodes[static_cast<size_t>(i)];
    const double sign = i == root ? 1.0 : node.Sign;
    if (this->RootFixed[static_cast<size_t>(root)])
    {
      addAffine(i, this->RootValue[static_cast<size_t>(root)], sign);
    }
    else
    {
      triplets.emplace_back(i, variableOfRoot[static_cast<size_t>(root)], sign);
    }
    if (i != root)
    {
      addAffine(i, node.Offset, 1.0);
    }
  }
  reduction.B.resize(this->CoordinateCount, variableCount);
  reduction.B.setFromTriplets(triplets.begin(), triplets.end()); // duplicates are summed
  reduction.B.prune(0.0);
  return Status::Success();
}

Eigen::VectorXd CoordinateRelations::Extras(const Eigen::VectorXd& y) const
{
  Eigen::VectorXd free(static_cast<Eigen::Index>(this->FreeExtraVariable.size()));
  for (size_t slot = 0; slot < this->FreeExtraVariable.size(); ++slot)
  {
    free(static_cast<Eigen::Index>(slot)) = y(this->FreeExtraVariable[slot]);
  }
  return this->ExtraMap * free + this->ExtraOffset;
}

} // namespace polycubehex
