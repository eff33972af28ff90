// SPDX-License-Identifier: BSD-3-Clause
#include "TopologyHomology.h"

#include "TetGeometry.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <numeric>

namespace polycubehex
{

namespace
{
/// Rings of all interior edges in CSR form: interior face ids and their signs (+1 when the
/// walk crosses the face from its first to its second tet).
struct EdgeRings
{
  std::vector<int> Offsets; // per edge; boundary edges get an empty ring
  std::vector<int> Face;
  std::vector<signed char> Sign;
};

void BuildEdgeRings(const Tets& cells, const TetAdjacency& adjacency, EdgeRings& rings)
{
  const int edgeCount = static_cast<int>(adjacency.EdgeVertices.size());
  rings.Offsets.assign(static_cast<size_t>(edgeCount) + 1, 0);
  rings.Face.clear();
  rings.Sign.clear();
  std::vector<EdgeRingStep> ring;
  bool closed = false;
  for (int e = 0; e < edgeCount; ++e)
  {
    if (!adjacency.EdgeOnBoundary[e])
    {
      WalkAroundEdge(cells, adjacency, e, ring, closed);
      for (const EdgeRingStep& step : ring)
      {
        rings.Face.push_back(adjacency.InteriorFaceId(step.Tet, step.Exit));
        rings.Sign.push_back(
          static_cast<signed char>(InteriorFaceSign(adjacency, step.Tet, step.Exit)));
      }
    }
    rings.Offsets[e + 1] = static_cast<int>(rings.Face.size());
  }
}

/// Union-find with the parity of each element relative to its root.
struct ParityUnionFind
{
  std::vector<int> Parent;
  std::vector<signed char> Sign; // value(i) = Sign[i] * value(Parent[i])

  explicit ParityUnionFind(int n)
    : Parent(n)
    , Sign(n, 1)
  {
    std::iota(Parent.begin(), Parent.end(), 0);
  }

  /// Root of i and the sign s with value(i) = s * value(root).
  std::pair<int, int> Find(int i)
  {
    int sign = 1;
    int root = i;
    while (Parent[root] != root)
    {
      sign *= Sign[root];
      root = Parent[root];
    }
    // Path compression, keeping signs relative to the root.
    int node = i;
    int nodeSign = sign;
    while (Parent[node] != root && node != root)
    {
      const int next = Parent[node];
      const int nextSign = nodeSign * Sign[node];
      Parent[node] = root;
      Sign[node] = static_cast<signed char>(nodeSign);
      node = next;
      nodeSign = nextSign;
    }
    return { root, sign };
  }

  /// Imposes value(a) = relation * value(b); returns false on a parity conflict.
  bool Unite(int a, int b, int relation)
  {
    const auto ra = Find(a);
    const auto rb = Find(b);
    if (ra.first == rb.first)
    {
      return ra.second == relation * rb.second;
    }
    // value(ra) = ra.second * value(a) = ra.second * relation * rb.second * value(rb)
    Parent[ra.first] = rb.first;
    Sign[ra.first] = static_cast<signed char>(ra.second * relation * rb.second);
    return true;
  }
};

// GCC and Clang extension: exact products of two 64-bit integers.
__extension__ typedef __int128 Int128;

bool FitsInt64(Int128 value)
{
  return value <= static_cast<Int128>(INT64_MAX) && value >= -static_cast<Int128>(INT64_MAX);
}

long long Gcd(long long a, long long b)
{
  a = std::llabs(a);
  b = std::llabs(b);
  while (b != 0)
  {
    const long long r = a % b;
    a = b;
    b = r;
  }
  return a;
}

/// Divides a row by the gcd of its entries and makes its first nonzero entry positive.
void NormalizeRow(std::vector<long long>& row)
{
  long long g = 0;
  for (long long value : row)
  {
    g = Gcd(g, value);
  }
  if (g == 0)
  {
    return;
  }
  long long first = 0;
  for (long long value : row)
  {
    if (value != 0)
    {
      first = value;
      break;
    }
  }
  if (first < 0)
  {
    g = -g;
  }
  for (long long& value : row)
  {
    value /= g;
  }
}

/// Reduced row echelon form over Q with integer rows (fraction free, gcd-normalised).
/// Returns false on overflow. `pivotColumn` gets the pivot column of each nonzero row.
bool ReduceRows(std::vector<std::vector<long long>>& rows,
  int columns,
  std::vector<int>& pivotColumn)
{
  pivotColumn.clear();
  size_t rank = 0;
  for (int column = 0; column < columns && rank < rows.size(); ++column)
  {
    // Pivot: the row with the smallest nonzero |entry| in this column (keeps numbers small).
    size_t best = rows.size();
    for (size_t r = rank; r < rows.size(); ++r)
    {
      if (rows[r][column] != 0 &&
        (best == rows.size() || std::llabs(rows[r][column]) < std::llabs(rows[best][column])))
      {
        best = r;
      }
    }
    if (best == rows.size())
    {
      continue;
    }
    std::swap(rows[rank], rows[best]);
    const std::vector<long long>& pivot = rows[rank];
    const long long p = pivot[column];
    for (size_t r = 0; r < rows.size(); ++r)
    {
      if (r == rank || rows[r][column] == 0)
      {
        continue;
      }
      const long long q = rows[r][column];
      const long long g = Gcd(p, q);
      const long long a = p / g;
      const long long b = q / g;
      std::vector<long long>& row = rows[r];
      for (int c = 0; c < columns; ++c)
      {
        if (row[c] == 0 && pivot[c] == 0)
        {
          continue;
        }
        const Int128 value = static_cast<Int128>(row[c]) * a - static_cast<Int128>(pivot[c]) * b;
        if (!FitsInt64(value))
        {
          return false;
        }
        row[c] = static_cast<long long>(value);
      }
      NormalizeRow(row);
    }
    pivotColumn.push_back(column);
    ++rank;
  }
  rows.resize(rank);
  return true;
}
} // namespace

bool IsCocycle(const Tets& cells,
  const TetAdjacency& adjacency,
  const std::vector<int>& cochain,
  int* badEdge)
{
  std::vector<EdgeRingStep> ring;
  bool closed = false;
  for (size_t e = 0; e < adjacency.EdgeVertices.size(); ++e)
  {
    if (adjacency.EdgeOnBoundary[e])
    {
      continue;
    }
    WalkAroundEdge(cells, adjacency, static_cast<int>(e), ring, closed);
    long long sum = 0;
    for (const EdgeRingStep& step : ring)
    {
      sum += static_cast<long long>(InteriorFaceSign(adjacency, step.Tet, step.Exit)) *
        cochain[adjacency.InteriorFaceId(step.Tet, step.Exit)];
    }
    if (sum != 0 || !closed)
    {
      if (badEdge)
      {
        *badEdge = static_cast<int>(e);
      }
      return false;
    }
  }
  return true;
}

Status ComputeCohomologyBasis(const Tets& cells,
  const TetAdjacency& adjacency,
  bool computeCocycles,
  CohomologyBasis& basis)
{
  basis = CohomologyBasis();
  const int faceCount = static_cast<int>(adjacency.InteriorFaces.size());
  const int edgeCount = static_cast<int>(adjacency.EdgeVertices.size());

  // 1. Spanning forest of the dual graph (breadth first, deterministic).
  std::vector<char> inC(faceCount, 1);
  {
    std::vector<char> visited(adjacency.TetCount, 0);
    std::vector<int> queue;
    queue.reserve(adjacency.TetCount);
    for (int seed = 0; seed < adjacency.TetCount; ++seed)
    {
      if (visited[seed])
      {
        continue;
      }
      visited[seed] = 1;
      queue.clear();
      queue.push_back(seed);
      for (size_t head = 0; head < queue.size(); ++head)
      {
        const int t = queue[head];
        for (int k = 0; k < 4; ++k)
        {
          const int n = adjacency.Neighbor(t, k);
          if (n >= 0 && !visited[n])
          {
            visited[n] = 1;
            inC[adjacency.InteriorFaceId(t, k)] = 0;
            queue.push_back(n);
          }
        }
      }
    }
  }

  // 2. Collapse C through free interior edges.
  EdgeRings rings;
  BuildEdgeRings(cells, adjacency, rings);
  std::vector<int> countInC(edgeCount, 0);
  for (int e = 0; e < edgeCount; ++e)
  {
    for (int i = rings.Offsets[e]; i < rings.Offsets[e + 1]; ++i)
    {
      countInC[e] += inC[rings.Face[i]];
    }
  }
  std::vector<int> freeEdges;
  for (int e = 0; e < edgeCount; ++e)
  {
    if (!adjacency.EdgeOnBoundary[e] && countInC[e] == 1)
    {
      freeEdges.push_back(e);
    }
  }
  while (!freeEdges.empty())
  {
    const int e = freeEdges.back();
    freeEdges.pop_back();
    if (countInC[e] != 1)
    {
      continue;
    }
    int face = -1;
    for (int i = rings.Offsets[e]; i < rings.Offsets[e + 1]; ++i)
    {
      if (inC[rings.Face[i]])
      {
        face = rings.Face[i];
        break;
      }
    }
    inC[face] = 0;
    for (int edge : InteriorFaceEdges(adjacency, face))
    {
      if (adjacency.EdgeOnBoundary[edge])
      {
        continue;
      }
      if (--countInC[edge] == 1)
      {
        freeEdges.push_back(edge);
      }
    }
  }

  // 3. Sheets: faces of C joined across interior edges holding exactly two of them.
  ParityUnionFind sheets(faceCount);
  std::vector<int> conflicting;
  for (int e = 0; e < edgeCount; ++e)
  {
    if (countInC[e] != 2)
    {
      continue;
    }
    int found[2];
    int sign[2];
    int n = 0;
    for (int i = rings.Offsets[e]; i < rings.Offsets[e + 1] && n < 2; ++i)
    {
      if (inC[rings.Face[i]])
      {
        found[n] = rings.Face[i];
        sign[n] = rings.Sign[i];
        ++n;
      }
    }
    // sign0 * x0 + sign1 * x1 = 0  =>  x0 = -sign0 * sign1 * x1
    if (!sheets.Unite(found[0], found[1], -sign[0] * sign[1]))
    {
      conflicting.push_back(found[0]);
    }
  }
  std::vector<int> sheetOfRoot(faceCount, -1);
  std::vector<int> faceSheet(faceCount, -1);
  std::vector<signed char> faceSign(faceCount, 0);
  int sheetCount = 0;
  for (int f = 0; f < faceCount; ++f)
  {
    if (!inC[f])
    {
      continue;
    }
    ++basis.RemainingFaceCount;
    const auto rootSign = sheets.Find(f);
    if (sheetOfRoot[rootSign.first] < 0)
    {
      sheetOfRoot[rootSign.first] = sheetCount++;
    }
    faceSheet[f] = sheetOfRoot[rootSign.first];
    faceSign[f] = static_cast<signed char>(rootSign.second);
  }
  basis.SheetCount = sheetCount;

  // 4. Relations on the sheet unknowns: seams, and sheets forced to 0 by a parity conflict.
  std::vector<std::vector<long long>> rows;
  {
    std::map<std::vector<std::pair<int, long long>>, int> unique; // sparse row -> seen
    std::map<int, long long> accumulate;
    for (int e = 0; e < edgeCount; ++e)
    {
      if (countInC[e] < 3)
      {
        continue;
      }
      accumulate.clear();
      for (int i = rings.Offsets[e]; i < rings.Offsets[e + 1]; ++i)
      {
        const int f = rings.Face[i];
        if (inC[f])
        {
          accumulate[faceSheet[f]] += static_cast<long long>(rings.Sign[i]) * faceSign[f];
        }
      }
      std::vector<std::pair<int, long long>> sparse;
      for (const auto& entry : accumulate)
      {
        if (entry.second != 0)
        {
          sparse.push_back(entry);
        }
      }
      if (sparse.empty())
      {
        continue;
      }
      if (sparse.front().second < 0)
      {
        for (auto& entry : sparse)
        {
          entry.second = -entry.second;
        }
      }
      unique.emplace(std::move(sparse), 0);
    }
    for (int f : conflicting)
    {
      unique.emplace(std::vector<std::pair<int, long long>>{ { faceSheet[f], 1 } }, 0);
    }
    for (const auto& entry : unique)
    {
      std::vector<long long> row(sheetCount, 0);
      for (const auto& value : entry.first)
      {
        row[value.first] = value.second;
      }
      rows.push_back(std::move(row));
    }
  }
  basis.RelationCount = static_cast<int>(rows.size());

  // 5. Kernel of the relations, exactly.
  std::vector<int> pivotColumn;
  if (!ReduceRows(rows, sheetCount, pivotColumn))
  {
    return Status::Failure("cohomology: integer overflow in the sheet relations (" +
      std::to_string(sheetCount) + " sheets, " + std::to_string(basis.RelationCount) +
      " relations)");
  }
  basis.Beta1 = sheetCount - static_cast<int>(pivotColumn.size());
  if (!computeCocycles)
  {
    return Status::Success();
  }
  std::vector<char> isPivot(sheetCount, 0);
  for (int column : pivotColumn)
  {
    isPivot[column] = 1;
  }
  for (int freeColumn = 0; freeColumn < sheetCount; ++freeColumn)
  {
    if (isPivot[freeColumn])
    {
      continue;
    }
    // x_free = D, x_pivot(r) = -row_r[free] * D / row_r[pivot(r)], D = lcm of those pivots.
    Int128 D = 1;
    for (size_t r = 0; r < rows.size(); ++r)
    {
      if (rows[r][freeColumn] != 0)
      {
        const long long p = std::llabs(rows[r][pivotColumn[r]]);
        D = D / Gcd(static_cast<long long>(D), p) * p;
        if (!FitsInt64(D))
        {
          return Status::Failure("cohomology: integer overflow in a kernel vector");
        }
      }
    }
    std::vector<long long> x(sheetCount, 0);
    x[freeColumn] = static_cast<long long>(D);
    for (size_t r = 0; r < rows.size(); ++r)
    {
      if (rows[r][freeColumn] != 0)
      {
        const Int128 value =
          -static_cast<Int128>(rows[r][freeColumn]) * D / rows[r][pivotColumn[r]];
        x[pivotColumn[r]] = static_cast<long long>(value);
      }
    }
    NormalizeRow(x);
    std::vector<int> cocycle(faceCount, 0);
    for (int f = 0; f < faceCount; ++f)
    {
      if (inC[f])
      {
        const long long value = faceSign[f] * x[faceSheet[f]];
        if (std::llabs(value) > 1000000)
        {
          return Status::Failure("cohomology: a basis cocycle has a value above 10^6");
        }
        cocycle[f] = static_cast<int>(value);
      }
    }
    // Self-check: closed around every interior edge.
    for (int e = 0; e < edgeCount; ++e)
    {
      long long sum = 0;
      for (int i = rings.Offsets[e]; i < rings.Offsets[e + 1]; ++i)
      {
        sum += rings.Sign[i] * static_cast<long long>(cocycle[rings.Face[i]]);
      }
      if (sum != 0)
      {
        return Status::Failure(
          "cohomology: internal error, a basis cochain is not closed at edge " + std::to_string(e));
      }
    }
    basis.Cocycles.push_back(std::move(cocycle));
  }
  return Status::Success();
}

} // namespace polycubehex
