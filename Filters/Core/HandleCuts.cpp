// SPDX-License-Identifier: BSD-3-Clause
#include "HandleCuts.h"

#include "CutMesh.h"
#include "CutMinimize.h"
#include "CutRepair.h"
#include "CutSubdivision.h"
#include "CutSurface.h"
#include "DisjointSets.h"
#include "TetGeometry.h"
#include "TopologyAdjacency.h"
#include "TopologyBoundary.h"
#include "TopologyHomology.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <set>
#include <sstream>

namespace polycubehex
{

namespace
{

/// The mesh cut by the cuts made so far, with its topology.
struct CutState
{
  Tets Cells;
  Points Vertices;
  std::vector<int> ToOriginal; // per vertex: the input vertex it copies
  TetAdjacency Adjacency;
  BoundaryTopology Boundary;
  CohomologyBasis Basis;
};

/// Builds the adjacency, the boundary topology and the cohomology of `state` and checks that
/// both beta_1 agree.
Status Analyze(CutState& state)
{
  Status status =
    BuildTetAdjacency(static_cast<int>(state.Vertices.rows()), state.Cells, state.Adjacency);
  if (!status)
  {
    return status;
  }
  status = ComputeBoundaryTopology(state.Cells, state.Adjacency, state.Boundary);
  if (!status)
  {
    return status;
  }
  status = ComputeCohomologyBasis(state.Cells, state.Adjacency, true, state.Basis);
  if (!status)
  {
    return status;
  }
  if (state.Basis.Beta1 != state.Boundary.Beta1)
  {
    std::ostringstream message;
    message << "beta_1 from the boundary genera (" << state.Boundary.Beta1
            << ") and from the dual complex (" << state.Basis.Beta1 << ") disagree";
    return Status::Failure(message.str());
  }
  return Status::Success();
}

struct Candidate
{
  std::vector<CutFaceEntry> Faces;
  CutSurfaceReport Report;
  bool Simple = true; // every face carries +-1 (no face of the surface counted twice)
  int Mismatched = 0; // CountMismatchedEdges of its loops
};

/// Splits the support of `cocycle` into components (connected through shared edges).
void ExtractComponents(const Tets& cells,
  const TetAdjacency& adjacency,
  const Points& points,
  const std::vector<int>& cocycle,
  std::vector<Candidate>& candidates)
{
  std::vector<int> support;
  for (size_t f = 0; f < cocycle.size(); ++f)
  {
    if (cocycle[f] != 0)
    {
      support.push_back(static_cast<int>(f));
    }
  }
  const int count = static_cast<int>(support.size());
  std::vector<int> parent(count);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> edgeFirst(adjacency.EdgeVertices.size(), -1);
  for (int i = 0; i < count; ++i)
  {
    for (int edge : InteriorFaceEdges(adjacency, support[i]))
    {
      if (edgeFirst[edge] < 0)
      {
        edgeFirst[edge] = i;
      }
      else
      {
        parent[FindRoot(parent, i)] = FindRoot(parent, edgeFirst[edge]);
      }
    }
  }
  std::vector<int> rootToCandidate(count, -1);
  const size_t firstNew = candidates.size();
  for (int i = 0; i < count; ++i)
  {
    const int root = FindRoot(parent, i);
    if (rootToCandidate[root] < 0)
    {
      rootToCandidate[root] = static_cast<int>(candidates.size());
      candidates.emplace_back();
    }
    Candidate& candidate = candidates[rootToCandidate[root]];
    const int value = cocycle[support[i]];
    candidate.Faces.push_back({ support[i], value > 0 ? 1 : -1 });
    candidate.Simple = candidate.Simple && std::abs(value) == 1;
  }
  for (size_t c = firstNew; c < candidates.size(); ++c)
  {
    AnalyzeCutSurface(cells, adjacency, points, candidates[c].Faces, candidates[c].Report);
    if (!candidates[c].Simple)
    {
      candidates[c].Report.Manifold = false;
      candidates[c].Report.Problem +=
        std::string(candidates[c].Report.Problem.empty() ? "" : "; ") +
        "a face is covered more than once";
    }
  }
}

/// A candidate kept between steps, by tets (ids and local faces never change).
struct PooledCut
{
  std::vector<std::array<int, 2>> Minus; // (minus-side tet, local face)
};

PooledCut ToPooled(const TetAdjacency& adjacency, const Candidate& candidate)
{
  PooledCut pooled;
  for (const CutFaceEntry& entry : candidate.Faces)
  {
    const int t = adjacency.InteriorFaces[entry.Face][0];
    const int k = adjacency.InteriorFaces[entry.Face][1];
    pooled.Minus.push_back(entry.Side > 0
        ? std::array<int, 2>{ t, k }
        : std::array<int, 2>{ adjacency.Neighbor(t, k), adjacency.NeighborFace(t, k) });
  }
  return pooled;
}

/// The pooled cut on the current mesh; false when one of its faces is no longer interior.
bool FromPooled(const TetAdjacency& adjacency, const PooledCut& pooled, Candidate& candidate)
{
  candidate = Candidate();
  for (const auto& minus : pooled.Minus)
  {
    const int face = adjacency.InteriorFaceId(minus[0], minus[1]);
    if (face < 0)
    {
      return false;
    }
    const auto& first = adjacency.InteriorFaces[face];
    candidate.Faces.push_back({ face, first[0] == minus[0] && first[1] == minus[1] ? 1 : -1 });
  }
  return true;
}

/// Tries the valid candidates, smallest first: the first that does not separate its solid and
/// whose cutting lowers beta_1 by exactly one (both counts) is returned in `accepted`, with the
/// cut mesh in `next`. `rejected` receives the first reason for refusing a candidate.
bool TryCandidates(const CutState& state,
  const std::vector<Candidate>& candidates,
  bool preferMatched,
  int& accepted,
  CutState& next,
  std::string& rejected,
  int& rejectedCount)
{
  const TetAdjacency& adjacency = state.Adjacency;
  const int faceCount = static_cast<int>(adjacency.InteriorFaces.size());
  const int beta1 = state.Boundary.Beta1;
  std::vector<int> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(),
    order.end(),
    [&](int a, int b)
    {
      const bool va = candidates[a].Report.Valid();
      const bool vb = candidates[b].Report.Valid();
      if (va != vb)
      {
        return va;
      }
      const bool ma = !preferMatched || candidates[a].Mismatched == 0;
      const bool mb = !preferMatched || candidates[b].Mismatched == 0;
      return ma != mb ? ma : candidates[a].Report.Area < candidates[b].Report.Area;
    });
  const int solids = CountSolidComponents(adjacency, {});
  for (int index : order)
  {
    const Candidate& candidate = candidates[index];
    if (!candidate.Report.Valid())
    {
      if (rejected.empty())
      {
        rejected = candidate.Report.Problem;
      }
      ++rejectedCount;
      continue;
    }
    std::vector<char> cut(faceCount, 0);
    for (const CutFaceEntry& entry : candidate.Faces)
    {
      cut[entry.Face] = 1;
    }
    if (CountSolidComponents(adjacency, cut) != solids)
    {
      if (rejected.empty())
      {
        rejected = "the surface separates the solid";
      }
      ++rejectedCount;
      continue;
    }
    std::vector<int> splitToOld;
    SplitAlongFaces(
      static_cast<int>(state.Vertices.rows()), state.Cells, adjacency, cut, next.Cells, splitToOld);
    next.Vertices.resize(static_cast<Eigen::Index>(splitToOld.size()), 3);
    next.ToOriginal.resize(splitToOld.size());
    for (size_t v = 0; v < splitToOld.size(); ++v)
    {
      next.Vertices.row(v) = state.Vertices.row(splitToOld[v]);
      next.ToOriginal[v] = state.ToOriginal[splitToOld[v]];
    }
    const Status analyzed = Analyze(next);
    if (!analyzed || next.Boundary.Beta1 != beta1 - 1)
    {
      if (rejected.empty())
      {
        rejected = analyzed ? "cutting leaves beta_1 = " + std::to_string(next.Boundary.Beta1)
                            : "after cutting: " + analyzed.Message();
      }
      ++rejectedCount;
      continue;
    }
    accepted = index;
    return true;
  }
  return false;
}

/// The cuts of `mesh` without subdivision. When a step finds no valid cut, `failedNear` receives
/// one flag per vertex of `mesh`: the vertices of that step's candidates.
Status ComputeCutsOnMesh(const TetMesh& mesh,
  const HandleCutParameters& params,
  HandleCutResult& result,
  const Progress& progress,
  std::vector<char>& failedNear)
{
  result = HandleCutResult();
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  CutState state;
  state.Cells = mesh.Cells;
  state.Vertices = mesh.Vertices;
  state.ToOriginal.resize(mesh.Vertices.rows());
  std::iota(state.ToOriginal.begin(), state.ToOriginal.end(), 0);
  // Later stages need positive tets; saying so here names the problem at the first stage.
  if (!mesh.Vertices.allFinite())
  {
    return Status::Failure("handle cuts: input: a vertex has a non-finite coordinate");
  }
  for (int t = 0; t < tetCount; ++t)
  {
    const double volume = TetSignedVolume(mesh.Vertices, mesh.Cells, t);
    if (!(volume > 0.0))
    {
      std::ostringstream message;
      message << "handle cuts: input: tet " << t << " has non-positive volume (" << volume
              << "); the tets must be positively oriented (VTK node order) and not flat";
      return Status::Failure(message.str());
    }
  }
  Status status = Analyze(state);
  if (!status)
  {
    return Status::Failure("handle cuts: input: " + status.Message());
  }
  result.Beta1 = state.Boundary.Beta1;
  result.BoundaryGenus = state.Boundary.ComponentGenus;
  result.CutFaces.setConstant(tetCount, 4, -1);
  result.CutSide.setConstant(tetCount, 4, 0);
  if (!ReportProgress(progress, 0.0))
  {
    return Status::Failure("handle cuts: aborted");
  }

  const TetAdjacency input = state.Adjacency;
  std::vector<PooledCut> pool;
  for (int step = 0; state.Boundary.Beta1 > 0; ++step)
  {
    const int beta1 = state.Boundary.Beta1;
    const TetAdjacency& adjacency = state.Adjacency;
    std::vector<Candidate> candidates;
    int accepted = -1;
    CutState next;
    std::string rejected;

    // Drops repeated surfaces (a surface of the input is often found again on the cut mesh)
    // and counts the mismatched edges of the new candidates from index `from` on.
    std::set<std::vector<int>> seen;
    auto measure = [&](size_t from)
    {
      size_t kept = from;
      for (size_t c = from; c < candidates.size(); ++c)
      {
        std::vector<int> key;
        for (const CutFaceEntry& entry : candidates[c].Faces)
        {
          key.push_back(entry.Face);
        }
        std::sort(key.begin(), key.end());
        if (!seen.insert(std::move(key)).second)
        {
          continue;
        }
        candidates[c].Mismatched =
          CountMismatchedCutEdges(input, candidates[c].Report.Loops, state.ToOriginal);
        if (kept != c)
        {
          candidates[kept] = std::move(candidates[c]);
        }
        ++kept;
      }
      candidates.resize(kept);
      result.CandidateCount += static_cast<int>(kept - from);
    };
    // 1. The least-area surfaces computed on the input (step 0), re-checked on the current cut
    //    mesh. Such a surface is proper in M, so where it meets an earlier cut it crosses it
    //    (its two faces at a shared edge lie on both copies): no mismatched edge (section 5.3).
    if (params.MatchedCuts && step > 0)
    {
      for (const PooledCut& pooled : pool)
      {
        Candidate candidate;
        if (FromPooled(adjacency, pooled, candidate))
        {
          AnalyzeCutSurface(
            state.Cells, adjacency, state.Vertices, candidate.Faces, candidate.Report);
          if (candidate.Report.Valid())
          {
            candidates.push_back(std::move(candidate));
          }
        }
      }
      measure(0);
      if (!params.RecomputeEachStep)
      {
        TryCandidates(state,
          candidates,
          params.MatchedCuts,
          accepted,
          next,
          rejected,
          result.RejectedCandidateCount);
      }
    }

    // 2. The least-area surface of every basis class of the current cut mesh, repaired, in
    //    components (at every step, or when no surface of step 1 passed).
    if (accepted < 0)
    {
      const size_t kept = candidates.size();
      const int faceCount = static_cast<int>(adjacency.InteriorFaces.size());
      std::vector<double> faceArea(faceCount);
      for (int f = 0; f < faceCount; ++f)
      {
        faceArea[f] = InteriorFaceArea(state.Cells, adjacency, state.Vertices, f);
      }
      // Least-area representative of every basis class.
      std::vector<std::vector<int>> classes = state.Basis.Cocycles;
      std::vector<double> classArea(classes.size());
      auto minimize = [&](std::vector<int>& cocycle)
      {
        int rounds = 0;
        const double area = MinimizeCocycleArea(
          adjacency, faceArea, cocycle, params.CoverCopies, params.MaxMinCutRounds, &rounds);
        result.MinCutCount += rounds;
        ++result.ClassCount;
        return area;
      };
      for (size_t c = 0; c < classes.size(); ++c)
      {
        classArea[c] = minimize(classes[c]);
        const double fraction = (step + (c + 1.0) / (classes.size() + 1.0)) / result.Beta1;
        if (!ReportProgress(progress, fraction))
        {
          return Status::Failure("handle cuts: aborted");
        }
      }
      // Basis reduction against the smallest class: a basis class whose surface meets the
      // smallest one may be a sum of classes (its least-area surface is then one connected
      // surface through both, and its summands never show up as candidates); try
      // class -+ smallest and keep the smaller. Surfaces apart from the smallest are left alone.
      if (params.ReduceBasis && classes.size() > 1)
      {
        const size_t smallest = static_cast<size_t>(
          std::min_element(classArea.begin(), classArea.end()) - classArea.begin());
        std::vector<char> onSmallest(state.Vertices.rows(), 0);
        for (int f = 0; f < faceCount; ++f)
        {
          if (classes[smallest][f] != 0)
          {
            for (int i = 0; i < 3; ++i)
            {
              const auto& first = adjacency.InteriorFaces[f];
              onSmallest[state.Cells(first[0], TetFaceTable[first[1]][i])] = 1;
            }
          }
        }
        for (size_t c = 0; c < classes.size(); ++c)
        {
          bool meets = false;
          for (int f = 0; f < faceCount && !meets && c != smallest; ++f)
          {
            if (classes[c][f] != 0)
            {
              const auto& first = adjacency.InteriorFaces[f];
              for (int i = 0; i < 3; ++i)
              {
                meets = meets || onSmallest[state.Cells(first[0], TetFaceTable[first[1]][i])];
              }
            }
          }
          if (!meets)
          {
            continue;
          }
          for (int sign : { -1, 1 })
          {
            std::vector<int> combined = classes[c];
            for (int f = 0; f < faceCount; ++f)
            {
              combined[f] += sign * classes[smallest][f];
            }
            const double area = minimize(combined);
            if (area < classArea[c] * (1.0 - 1e-9))
            {
              classes[c].swap(combined);
              classArea[c] = area;
            }
          }
        }
      }
      for (std::vector<int>& cocycle : classes)
      {
        int supportSize = 0;
        for (int value : cocycle)
        {
          supportSize += value != 0 ? 1 : 0;
        }
        int moves = 0;
        RepairCocycleSurface(state.Cells,
          adjacency,
          faceArea,
          cocycle,
          params.RepairMovesPerFace * supportSize + 100,
          &moves);
        result.RepairMoveCount += moves;
        ExtractComponents(state.Cells, adjacency, state.Vertices, cocycle, candidates);
      }
      measure(kept);
      TryCandidates(state,
        candidates,
        params.MatchedCuts,
        accepted,
        next,
        rejected,
        result.RejectedCandidateCount);
    }
    if (accepted < 0)
    {
      std::ostringstream message;
      message << "handle cuts: no valid cut found at step " << step + 1 << " of " << result.Beta1
              << " (beta_1 = " << beta1 << ", " << candidates.size() << " candidates)";
      if (!rejected.empty())
      {
        message << "; the smallest was rejected: " << rejected;
      }
      failedNear.assign(mesh.Vertices.rows(), 0);
      for (const Candidate& failed : candidates)
      {
        for (const CutFaceEntry& entry : failed.Faces)
        {
          const auto& first = adjacency.InteriorFaces[entry.Face];
          for (int i = 0; i < 3; ++i)
          {
            failedNear[state.ToOriginal[state.Cells(first[0], TetFaceTable[first[1]][i])]] = 1;
          }
        }
      }
      return Status::Failure(message.str());
    }

    // Record the cut on the input's tets (ids and local faces are unchanged by splitting).
    const Candidate& candidate = candidates[accepted];
    const int cutId = static_cast<int>(result.Cuts.size());
    HandleCut record;
    for (const CutFaceEntry& entry : candidate.Faces)
    {
      const int t = adjacency.InteriorFaces[entry.Face][0];
      const int k = adjacency.InteriorFaces[entry.Face][1];
      const int n = adjacency.Neighbor(t, k);
      const int nk = adjacency.NeighborFace(t, k);
      const int minusTet = entry.Side > 0 ? t : n;
      const int minusLocal = entry.Side > 0 ? k : nk;
      const int plusTet = entry.Side > 0 ? n : t;
      const int plusLocal = entry.Side > 0 ? nk : k;
      result.CutFaces(minusTet, minusLocal) = cutId;
      result.CutFaces(plusTet, plusLocal) = cutId;
      result.CutSide(minusTet, minusLocal) = -1;
      result.CutSide(plusTet, plusLocal) = 1;
      record.Faces.push_back({ minusTet, minusLocal });
    }
    std::sort(record.Faces.begin(), record.Faces.end());
    for (const std::vector<int>& loop : candidate.Report.Loops)
    {
      std::vector<int> original;
      for (int v : loop)
      {
        original.push_back(state.ToOriginal[v]);
      }
      record.Loops.push_back(std::move(original));
    }
    record.MismatchedEdgeCount = candidate.Mismatched;
    record.Area = candidate.Report.Area;
    record.EulerCharacteristic = candidate.Report.EulerCharacteristic;
    record.Beta1Before = beta1;
    record.Beta1After = next.Boundary.Beta1;
    result.Cuts.push_back(std::move(record));

    // Keep the surfaces of the input for the next steps (the accepted one drops out by itself:
    // its faces are no longer interior).
    if (step == 0)
    {
      for (const Candidate& kept : candidates)
      {
        if (kept.Report.Valid())
        {
          pool.push_back(ToPooled(adjacency, kept));
        }
      }
    }
    state = std::move(next);
    if (!ReportProgress(progress, static_cast<double>(step + 1) / result.Beta1))
    {
      return Status::Failure("handle cuts: aborted");
    }
  }

  result.CutMesh.Vertices = state.Vertices;
  result.CutMesh.Cells = state.Cells;
  result.CutMeshOriginalVertex = state.ToOriginal;
  result.Beta1After = state.Boundary.Beta1;
  return Status::Success();
}
} // namespace

Status ComputeHandleCuts(const TetMesh& mesh,
  const HandleCutParameters& params,
  HandleCutResult& result,
  const Progress& progress)
{
  // Round 0 runs on the input itself, so a mesh that needs no subdivision gives the same cuts
  // as without this loop. Each later round restarts on the refined mesh: the cuts found before
  // the failing step may not be the best ones once the mesh is finer.
  TetMesh refined;
  std::vector<int> originalCell(mesh.Cells.rows());
  std::iota(originalCell.begin(), originalCell.end(), 0);
  std::vector<std::array<int, 2>> midpointParents;
  int splitEdges = 0;
  for (int round = 0;; ++round)
  {
    const TetMesh& current = round == 0 ? mesh : refined;
    std::vector<char> failedNear;
    Status status = ComputeCutsOnMesh(current, params, result, progress, failedNear);
    std::vector<std::array<int, 2>> edges;
    if (!status && !failedNear.empty() && round < params.MaxSubdivisionRounds)
    {
      TetAdjacency adjacency;
      if (BuildTetAdjacency(static_cast<int>(current.Vertices.rows()), current.Cells, adjacency))
      {
        edges = BoundaryChordEdges(adjacency, failedNear);
        if (edges.empty())
        {
          edges = BoundaryChordEdges(adjacency, {});
        }
      }
    }
    if (edges.empty())
    {
      if (!status && !failedNear.empty())
      {
        std::ostringstream message;
        message << status.Message();
        if (params.MaxSubdivisionRounds == 0)
        {
          message << ". Refining the tet mesh near the handle may help (MaxSubdivisionRounds = 0:"
                     " tets are not subdivided).";
        }
        else
        {
          message << ", after " << round << " subdivision round(s) that split " << splitEdges
                  << " edges"
                  << (round < params.MaxSubdivisionRounds
                         ? "; no interior edge joins two boundary vertices any more."
                         : "; more rounds (MaxSubdivisionRounds) may help.");
        }
        return Status::Failure(message.str());
      }
      if (status)
      {
        result.Mesh = current;
        result.OriginalCellId = originalCell;
        result.MidpointParents = midpointParents;
        result.SubdivisionRounds = round;
        result.SplitEdgeCount = splitEdges;
        std::vector<int> children(mesh.Cells.rows(), 0);
        for (int parent : originalCell)
        {
          ++children[parent];
        }
        result.SubdividedTetCount = static_cast<int>(
          std::count_if(children.begin(), children.end(), [](int c) { return c > 1; }));
      }
      return status;
    }
    if (round == 0)
    {
      refined = mesh;
    }
    splitEdges += static_cast<int>(edges.size());
    SubdivideEdges(refined, edges, originalCell, midpointParents);
  }
}

} // namespace polycubehex
