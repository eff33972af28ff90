// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeDeformation.h"

#include "DisjointSets.h"
#include "MemoryBudget.h"
#include "PolycubeCharts.h"
#include "PolycubeCreases.h"
#include "PolycubeCutMesh.h"
#include "PolycubeEnergy.h"
#include "PolycubeHomotopy.h"
#include "PolycubeNewton.h"
#include "PolycubeRotation.h"
#include "SparseCholesky.h"
#include "TetEdgeSplit.h"
#include "TetGeometry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>

namespace polycubehex
{

namespace
{

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The mesh being deformed, with everything that must follow a split.
struct WorkMesh
{
  Tets Cells;
  Points Rest;     ///< normalised input positions (ARAP rest shape)
  Points Original; ///< input positions, input units
  Points X;        ///< deformed positions, normalised
  std::vector<int> OriginalPointId;
  std::vector<int> ParentTet;
  /// For each vertex created by a split (id - first new id): its parents, 2 (edge midpoint) or 4
  /// (tet centroid) ids.
  std::vector<std::vector<int>> SplitParents;
  int InputVertexCount = 0;
  /// Closed form only (empty otherwise): the copy relations across the cuts, their transitions,
  /// and per vertex its identity (the same for all copies of one point of the input).
  std::vector<CopyRelation> Copies;
  std::vector<Eigen::Matrix3i> Transitions;
  std::vector<int> Identity;

  int VertexCount() const { return static_cast<int>(this->Rest.rows()); }
};

void SplitEdges(WorkMesh& mesh, const std::vector<std::array<int, 2>>& requested)
{
  const int n = mesh.VertexCount();
  // On a cut mesh, an edge split on one side of a cut is split on the other too.
  std::vector<std::array<int, 3>> partnerEdges;
  std::vector<std::array<int, 2>> edges =
    MirrorEdgesAcrossCuts(requested, mesh.Copies, n, partnerEdges);
  if (!mesh.Copies.empty())
  {
    SortCopiesAlike(edges, partnerEdges, mesh.Identity);
  }
  std::vector<int> parentLocal;
  std::vector<std::array<int, 2>> parents;
  SplitTetEdges(n, mesh.Cells, edges, parentLocal, parents);
  AddMidpointCopies(edges, partnerEdges, parents, n, mesh.Copies, mesh.Identity);
  std::vector<int> composed(parentLocal.size());
  for (size_t t = 0; t < parentLocal.size(); ++t)
  {
    composed[t] = mesh.ParentTet[static_cast<size_t>(parentLocal[t])];
  }
  mesh.ParentTet = composed;
  AppendSplitMidpoints(mesh.Rest, parents);
  AppendSplitMidpoints(mesh.Original, parents);
  AppendSplitMidpoints(mesh.X, parents);
  mesh.OriginalPointId.resize(static_cast<size_t>(mesh.VertexCount()), -1);
  for (const auto& p : parents)
  {
    mesh.SplitParents.push_back({ p[0], p[1] });
  }
}

void SplitTets(WorkMesh& mesh, const std::vector<int>& tets)
{
  std::vector<std::array<int, 4>> corners;
  SplitTetsAtCentroid(mesh.VertexCount(), mesh.Cells, tets, mesh.ParentTet, corners);
  AppendSplitCentroids(mesh.Rest, corners);
  AppendSplitCentroids(mesh.Original, corners);
  AppendSplitCentroids(mesh.X, corners);
  mesh.OriginalPointId.resize(static_cast<size_t>(mesh.VertexCount()), -1);
  for (int v = static_cast<int>(mesh.Identity.size()); v < mesh.VertexCount(); ++v)
  {
    mesh.Identity.push_back(v);
  }
  for (const auto& c : corners)
  {
    mesh.SplitParents.push_back({ c[0], c[1], c[2], c[3] });
  }
}

struct TripleHash
{
  size_t operator()(const std::array<int, 3>& k) const
  {
    size_t h = static_cast<size_t>(k[0]);
    h = h * 1000003u ^ static_cast<size_t>(k[1]);
    h = h * 1000003u ^ static_cast<size_t>(k[2]);
    return h;
  }
};

std::array<int, 3> SortedFace(const Triangles& faces, Eigen::Index f)
{
  std::array<int, 3> key = { faces(f, 0), faces(f, 1), faces(f, 2) };
  std::sort(key.begin(), key.end());
  return key;
}

/// Carries per-boundary-face values across splits: a new boundary face lies inside an old one,
/// found by replacing each split vertex by its parent that the face does not hold (the latest
/// split first). Faces that do not map get -1.
std::vector<int> TransferFaceValues(const Triangles& oldFaces,
  const std::vector<int>& oldValues,
  int oldVertexCount,
  const Triangles& newFaces,
  const WorkMesh& mesh)
{
  std::unordered_map<std::array<int, 3>, int, TripleHash> lookup;
  for (Eigen::Index f = 0; f < oldFaces.rows(); ++f)
  {
    lookup.emplace(SortedFace(oldFaces, f), oldValues[static_cast<size_t>(f)]);
  }
  const int firstSplit = mesh.VertexCount() - static_cast<int>(mesh.SplitParents.size());
  std::vector<int> values(static_cast<size_t>(newFaces.rows()), -1);
  for (Eigen::Index f = 0; f < newFaces.rows(); ++f)
  {
    std::array<int, 3> face = { newFaces(f, 0), newFaces(f, 1), newFaces(f, 2) };
    bool ok = true;
    while (ok)
    {
      const int m = *std::max_element(face.begin(), face.end());
      if (m < oldVertexCount)
      {
        break;
      }
      const std::vector<int>& parents = mesh.SplitParents[static_cast<size_t>(m - firstSplit)];
      ok = parents.size() == 2;
      if (!ok)
      {
        break;
      }
      const bool hasFirst = std::find(face.begin(), face.end(), parents[0]) != face.end();
      const bool hasSecond = std::find(face.begin(), face.end(), parents[1]) != face.end();
      ok = hasFirst != hasSecond;
      std::replace(face.begin(), face.end(), m, hasFirst ? parents[1] : parents[0]);
    }
    if (!ok)
    {
      continue;
    }
    std::sort(face.begin(), face.end());
    const auto it = lookup.find(face);
    if (it != lookup.end())
    {
      values[static_cast<size_t>(f)] = it->second;
    }
  }
  return values;
}

Eigen::VectorXd Flat(const Points& x)
{
  return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}

Points Unflat(const Eigen::VectorXd& x)
{
  return Eigen::Map<const Points>(x.data(), x.size() / 3, 3);
}

std::set<std::array<int, 2>> BoundaryEdgeSet(const Triangles& faces)
{
  std::set<std::array<int, 2>> edges;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    for (int e = 0; e < 3; ++e)
    {
      const int a = faces(f, e);
      const int b = faces(f, (e + 1) % 3);
      edges.insert({ std::min(a, b), std::max(a, b) });
    }
  }
  return edges;
}

/// Charts touching each vertex (sorted, unique).
std::vector<std::vector<int>> VertexCharts(int vertexCount,
  const Triangles& faces,
  const std::vector<int>& faceChart)
{
  std::vector<std::vector<int>> charts(static_cast<size_t>(vertexCount));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
  {
    for (int c = 0; c < 3; ++c)
    {
      charts[static_cast<size_t>(faces(f, c))].push_back(faceChart[static_cast<size_t>(f)]);
    }
  }
  for (auto& list : charts)
  {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return charts;
}

bool ShareOne(const std::vector<int>& a, const std::vector<int>& b)
{
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end())
  {
    if (*i == *j)
    {
      return true;
    }
    *i < *j ? ++i : ++j;
  }
  return false;
}

/// ComputeTetTopology, and on a cut mesh only the boundary of the input as boundary (the faces
/// of the cuts are not aligned, labelled or flattened).
void RefreshTopology(const WorkMesh& mesh, TetTopology& topology)
{
  ComputeTetTopology(mesh.VertexCount(), mesh.Cells, topology);
  if (!mesh.Copies.empty())
  {
    KeepInputBoundary(topology, mesh.Identity);
  }
}

/// Face adjacency of the boundary of the input: on a cut mesh, faces on the two sides of a cut's
/// boundary loop are neighbours, so that charts run across the cuts.
Triangles BoundaryAdjacency(const WorkMesh& mesh, const Triangles& faces)
{
  return mesh.Copies.empty()
    ? ComputeFaceAdjacency(mesh.VertexCount(), faces)
    : ComputeFaceAdjacency(mesh.VertexCount(), IdentityFaces(faces, mesh.Identity));
}

/// On a cut mesh, the boundary faces that are neighbours on M across a cut's loop, with the
/// cut's transition, so that the normal difference (12) reaches across the loop; empty without
/// cuts.
std::vector<FacePairAcrossCut> NormalPairsAcrossCuts(const WorkMesh& mesh,
  const TetTopology& topology,
  bool wanted)
{
  std::vector<FacePairAcrossCut> pairs;
  if (mesh.Copies.empty() || !wanted)
  {
    return pairs;
  }
  for (const auto& across : FacesAcrossCuts(
         topology.BoundaryFaces, BoundaryAdjacency(mesh, topology.BoundaryFaces), mesh.Copies))
  {
    FacePairAcrossCut pair;
    pair.MinusFace = across[0];
    pair.PlusFace = across[1];
    pair.Transition = mesh.Transitions[static_cast<size_t>(across[2])].cast<double>();
    pairs.push_back(pair);
  }
  return pairs;
}

/// Neighbouring boundary faces for walking polycube creases: on a cut mesh, neighbours on M_c
/// only. Across a cut the two sides are in different frames (a rotated transition gives one
/// chart of M two labels), so a crease stops at a cut's loop and each side is measured alone.
Triangles CreaseAdjacency(const WorkMesh& mesh, const Triangles& faces)
{
  return ComputeFaceAdjacency(mesh.VertexCount(), faces);
}

/// The charts whose faces share one plane: on a cut mesh, a chart of M that runs across a cut
/// is one piece on each side, and the pieces' planes differ by the cut's translation (a chart
/// around a handle may climb by t_c along its normal), so charts are taken on M_c itself.
/// `adjacency` is CreaseAdjacency(mesh, faces), passed in where the caller has it already.
PolycubeCharts PlaneCharts(const WorkMesh& mesh,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<int>& labels)
{
  return ComputePolycubeCharts(mesh.X, faces, adjacency, labels);
}

PolycubeCharts PlaneCharts(const WorkMesh& mesh,
  const Triangles& faces,
  const std::vector<int>& labels)
{
  return PlaneCharts(mesh, faces, CreaseAdjacency(mesh, faces), labels);
}

/// The variables of a cut mesh: copies related by their cut's transition with unknown
/// translations (eq. 8), and the coordinates of `equalities` made equal (chart planes).
Status CutReduction(const WorkMesh& mesh,
  const std::vector<std::array<int, 2>>& equalities,
  VariableReduction& reduction,
  CoordinateRelations* relationsOut = nullptr,
  const Eigen::VectorXd* fixedTranslations = nullptr)
{
  const int cutCount = static_cast<int>(mesh.Transitions.size());
  std::vector<int> extraAxis(static_cast<size_t>(3 * cutCount));
  for (int k = 0; k < 3 * cutCount; ++k)
  {
    extraAxis[static_cast<size_t>(k)] = k % 3;
  }
  CoordinateRelations relations(mesh.VertexCount(), 3 * cutCount, extraAxis);
  AddCopyRelations(mesh.Copies, mesh.Transitions, relations);
  for (const auto& pair : equalities)
  {
    relations.Relate(pair[0], pair[1], 1.0);
  }
  if (fixedTranslations != nullptr)
  {
    // t_k = value, written as the loop x_0 = x_0 + t_k - value.
    for (int k = 0; k < 3 * cutCount; ++k)
    {
      relations.Relate(0, 0, 1.0, { { k, 1.0 } }, -(*fixedTranslations)(k));
    }
  }
  const Status status = relations.Build(reduction);
  if (status && relationsOut != nullptr)
  {
    *relationsOut = relations;
  }
  return status;
}

/// Fang et al. eq. (7) with (8) hard, on the cut mesh: the map whose gradient best fits the
/// frames in least squares, copies across each cut related by its transition and an unknown
/// translation. The energy is quadratic, so one linear solve in the reduced variables gives it.
Status FramePoissonStart(WorkMesh& mesh,
  const TetTopology& topology,
  const std::vector<Eigen::Matrix3d>& tetFrames,
  PolycubeResult& out)
{
  std::vector<Eigen::Matrix3d> targets(static_cast<size_t>(mesh.Cells.rows()));
  for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
  {
    const Eigen::Matrix3d& frame =
      tetFrames[static_cast<size_t>(mesh.ParentTet[static_cast<size_t>(t)])];
    if (!frame.allFinite() || std::abs(frame.determinant() - 1.0) > 1e-3)
    {
      return Status::Failure("ComputePolycube: the frame of tet " +
        std::to_string(mesh.ParentTet[static_cast<size_t>(t)]) + " is not a rotation");
    }
    targets[static_cast<size_t>(t)] = frame;
  }
  VariableReduction reduction;
  Status status = CutReduction(mesh, {}, reduction);
  if (!status)
  {
    return Status::Failure("ComputePolycube: " + status.Message());
  }
  PolycubeEnergy energy(mesh.Rest, mesh.Cells, topology.BoundaryFaces);
  energy.SetTargetRotations(targets);
  energy.SetWeights(PolycubeEnergyWeights()); // Arap (here the Poisson fit) only
  const Eigen::VectorXd rest = Flat(mesh.Rest);
  Eigen::VectorXd gradient(rest.size());
  Eigen::SparseMatrix<double> hessian = energy.Pattern().ZeroMatrix();
  PolycubeEnergyTerms terms;
  if (!energy.EvaluateDerivatives(rest.data(), terms, gradient, &hessian))
  {
    return Status::Failure("ComputePolycube: the input has a non-positive tet");
  }
  // E(x) = E(rest) + g.(x - rest) + (x - rest)^T H (x - rest) / 2 with x = B y + c.
  const Eigen::SparseMatrix<double> bt = reduction.B.transpose();
  Eigen::SparseMatrix<double> normal = bt * hessian * reduction.B;
  const double mu = 1e-10 * normal.diagonal().mean(); // fixes the free translation
  for (int i = 0; i < normal.rows(); ++i)
  {
    normal.coeffRef(i, i) += mu;
  }
  SparseCholesky solver;
  bool factorized = false;
  {
    // CHOLMOD's per-supernode regions are too small to pay for their threads.
    const SerialOpenMPScope serial;
    solver.AnalyzePattern(normal);
    factorized = solver.Factorize(normal);
  }
  if (!factorized)
  {
    out.FrameFieldRefused = true;
    return Status::Failure("ComputePolycube: the frame-guided Poisson system is singular");
  }
  const Eigen::VectorXd y = solver.Solve(bt * (hessian * (rest - reduction.Offset) - gradient));
  const Eigen::VectorXd x = reduction.Expand(y);
  const double ratio = energy.MinVolumeRatio(x.data());
  out.InitialRotation.setIdentity();
  if (!(ratio > 0.0))
  {
    int inverted = 0;
    const Points positions = Unflat(x);
    for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
    {
      inverted += TetSignedVolume(positions, mesh.Cells, static_cast<int>(t)) > 0.0 ? 0 : 1;
    }
    out.FrameFieldRefused = true;
    return Status::Failure("ComputePolycube: the frame-guided map of the cut mesh (eq. 7 with the "
                           "cut transitions) inverts " +
      std::to_string(inverted) +
      " tets; the frame field does not describe a valid map. A field from other settings may "
      "(the frame filter's CutMeshBoundaryAlignmentWeight 0, or another "
      "BoundaryAlignmentWeight), or Uniform guidance needs none");
  }
  PolycubeEnergyTerms fit;
  energy.Evaluate(x.data(), fit);
  out.FrameFitResidual = fit.Arap;
  mesh.X = Unflat(x);
  return Status::Success();
}

/// Gives the faces that the penalised flattening squeezed below `ratio` of their rest area
/// (projected on their label's direction) the label of a neighbouring face of another label,
/// growing inwards from the chart boundaries. Returns the number of faces relabelled.
/// On a cut mesh a neighbour across a cut's loop lends its label through the cut's transition
/// (`across`: minus face, plus face, cut): copied as it is, a label across a 90-degree cut is
/// perpendicular or opposite to the face's normal. (Lending only labels that the face's normal
/// before flattening does not oppose was tried: bunny FrameField 18 -> 13 vertices off their
/// planes, but rockerarm's closed form went from SJ min 0.325, Hausdorff 8.4e-3 to 0.189, 19e-3.)
int RelabelCollapsedFaces(const PolycubeEnergy& energy,
  const Eigen::VectorXd& x,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<std::array<int, 3>>& across,
  const std::vector<Eigen::Matrix3i>& transitions,
  double ratio,
  std::vector<int>& labels)
{
  // (face, neighbour) -> the rotation that carries the neighbour's labels to the face's side.
  std::map<std::pair<int, int>, Eigen::Matrix3i> lend;
  for (const auto& pair : across)
  {
    const Eigen::Matrix3i& pi = transitions[static_cast<size_t>(pair[2])];
    lend[{ pair[1], pair[0] }] = pi;             // x_plus = Pi x_minus
    lend[{ pair[0], pair[1] }] = pi.transpose(); // and back
  }
  auto lentLabel = [&](int face, int neighbour)
  {
    const auto it = lend.find({ face, neighbour });
    const int label = labels[static_cast<size_t>(neighbour)];
    return it == lend.end() ? label : TransformLabel(it->second, label);
  };
  const int faceCount = static_cast<int>(faces.rows());
  std::vector<bool> collapsed(static_cast<size_t>(faceCount), false);
  for (int f = 0; f < faceCount; ++f)
  {
    collapsed[static_cast<size_t>(f)] =
      energy.FaceOrientation(x.data(), f, labels[static_cast<size_t>(f)]) < ratio;
  }
  const std::vector<int> original = labels;
  int relabelled = 0;
  for (bool changed = true; changed;)
  {
    changed = false;
    for (int f = 0; f < faceCount; ++f)
    {
      if (!collapsed[static_cast<size_t>(f)])
      {
        continue;
      }
      for (int e = 0; e < 3; ++e)
      {
        const int g = adjacency(f, e);
        if (g >= 0 && lentLabel(f, g) != labels[static_cast<size_t>(f)] &&
          (!collapsed[static_cast<size_t>(g)] ||
            labels[static_cast<size_t>(g)] != original[static_cast<size_t>(g)]))
        {
          labels[static_cast<size_t>(f)] = lentLabel(f, g);
          collapsed[static_cast<size_t>(f)] = false;
          ++relabelled;
          changed = true;
          break;
        }
      }
    }
  }
  return relabelled;
}

/// Creases that turn back (PolycubeCreases.h) fold when flattened. Each round shaves them
/// (ShaveTurnedBackCreases, then the chart clean-up `cleanUp`) and deforms the shape again for a
/// few Newton iterations with the continuation's last weights, every face's alignment pulling
/// it onto its own label's axis, and the faces that changed label turned to its side by the
/// unfolding penalty (the alignment alone would take either side). A shaved fold can reappear
/// next to it, so the best state seen is kept: fewest creases turning back, then the smallest
/// turn-back. On a cut mesh `reduction` keeps the transitions hard, `normalPairs` carries the
/// normal difference across the cuts, and `cleanUp` makes the labels agree across them again.
Status RepairTurnedBackCreases(WorkMesh& mesh,
  const Triangles& faces,
  const Triangles& adjacency,
  const std::vector<FacePairAcrossCut>& normalPairs,
  const VariableReduction& reduction,
  const PolycubeEnergyWeights& lastWeights,
  const PolycubeParameters& params,
  NewtonSettings::LinearSolverType solverType,
  const std::function<int()>& cleanUp,
  std::vector<int>& labels,
  PolycubeResult& out)
{
  struct State
  {
    int Count = 0;
    double Largest = 0.0;
    bool operator<(const State& other) const
    {
      return this->Count < other.Count ||
        (this->Count == other.Count && this->Largest < other.Largest);
    }
  };
  std::vector<PolycubeCrease> creases;
  auto measure = [&]()
  {
    creases =
      ComputePolycubeCreases(mesh.X, faces, adjacency, PlaneCharts(mesh, faces, adjacency, labels));
    State state;
    state.Largest = MaxCreaseTurnBack(creases, params.MonotoneRepairTolerance, &state.Count);
    return state;
  };
  State best = measure();
  if (best.Count == 0 || params.MonotoneRepairRounds <= 0)
  {
    return Status::Success();
  }
  const std::vector<int> entryLabels = labels;
  std::vector<int> bestLabels = labels;
  Points bestX = mesh.X;
  PolycubeEnergy energy(mesh.Rest, mesh.Cells, faces, normalPairs);
  PolycubeNewtonSolver solver(energy, reduction); // keeps references to both
  // Deforms under the current labels: each face's alignment pulls it onto its label's axis, and
  // the faces whose label differs from `reference` are turned to their side by the unfolding
  // penalty, with the continuation's last weights.
  auto deformUnderLabels = [&](const std::vector<int>& reference, int iterations)
  {
    std::vector<int> turned(labels.size(), -1);
    for (size_t f = 0; f < labels.size(); ++f)
    {
      turned[f] = labels[f] != reference[f] ? labels[f] : -1;
    }
    energy.SetAlignmentLabels(labels);
    energy.SetUnfoldFaces(turned);
    PolycubeEnergyWeights weights = lastWeights;
    weights.FaceUnfold = weights.Alignment;
    weights.FaceBarrierThreshold = params.BarrierThreshold;
    energy.SetWeights(weights);
    NewtonSettings settings;
    settings.LinearSolver = solverType;
    settings.MaxIterations = iterations;
    NewtonStats stats;
    Eigen::VectorXd x = Flat(mesh.X);
    const Status status = solver.Minimize(x, settings, stats);
    if (status)
    {
      out.Iterations += stats.Iterations;
      mesh.X = Unflat(x);
    }
    return status;
  };
  int roundsRun = 0;
  for (int round = 0; round < params.MonotoneRepairRounds; ++round)
  {
    const std::vector<int> before = labels;
    const int shaved = ShaveTurnedBackCreases(mesh.X,
      faces,
      PlaneCharts(mesh, faces, adjacency, labels),
      creases,
      params.MonotoneRepairTolerance,
      labels);
    if (shaved == 0)
    {
      break;
    }
    cleanUp();
    out.ShavedFaceCount += shaved;
    ++out.MonotoneRepairRounds;
    ++roundsRun;
    const Status status = deformUnderLabels(before, params.MonotoneRepairIterations);
    if (!status)
    {
      return status;
    }
    const State state = measure();
    if (state < best)
    {
      best = state;
      bestLabels = labels;
      bestX = mesh.X;
    }
    if (best.Count == 0)
    {
      break;
    }
  }
  if (roundsRun == 0)
  {
    return Status::Success(); // nothing could be shaved (closed-loop creases): the shape is
                              // untouched
  }
  labels = bestLabels;
  mesh.X = bestX;
  // The rounds take few iterations each (the shaving only needs the folds to move); the kept
  // state then settles under its labels as long as a continuation round.
  return deformUnderLabels(entryLabels, params.IterationsPerRound);
}

/// Fang et al. §4.1: the map whose gradient best fits the frame field (eq. 7, the Poisson
/// reconstruction), here minimised with the inversion barrier so that the start of the l1 stage
/// keeps every tet positive. It starts from the rest shape turned by the mean frame rotation.
Status FrameGuidedStart(WorkMesh& mesh,
  const TetTopology& topology,
  const std::vector<Eigen::Matrix3d>& tetFrames,
  const PolycubeParameters& params,
  PolycubeResult& out)
{
  std::vector<Eigen::Matrix3d> targets(static_cast<size_t>(mesh.Cells.rows()));
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
  {
    const Eigen::Matrix3d& frame =
      tetFrames[static_cast<size_t>(mesh.ParentTet[static_cast<size_t>(t)])];
    if (!frame.allFinite() || std::abs(frame.determinant() - 1.0) > 1e-3)
    {
      return Status::Failure("ComputePolycube: the frame of tet " +
        std::to_string(mesh.ParentTet[static_cast<size_t>(t)]) + " is not a rotation");
    }
    targets[static_cast<size_t>(t)] = frame;
    sum += TetSignedVolume(mesh.Rest, mesh.Cells, static_cast<int>(t)) * frame;
  }
  Eigen::Matrix3d mean;
  Eigen::Vector3d sigma;
  PolarRotation(sum, mean, sigma);
  out.InitialRotation = mean;
  Eigen::VectorXd x = Flat(mesh.Rest * mean.transpose());

  PolycubeEnergy energy(mesh.Rest, mesh.Cells, topology.BoundaryFaces);
  energy.SetTargetRotations(targets);
  PolycubeEnergyWeights weights;
  weights.Barrier = params.BarrierWeight;
  weights.BarrierThreshold = params.BarrierThreshold;
  energy.SetWeights(weights);
  const VariableReduction reduction = VariableReduction::Identity(mesh.VertexCount());
  PolycubeNewtonSolver solver(energy, reduction);
  NewtonSettings settings;
  settings.MaxIterations = params.FrameGuidedIterations;
  settings.RelativeDecrease = 1e-4;
  NewtonStats stats;
  const Status status = solver.Minimize(x, settings, stats);
  if (!status)
  {
    return Status::Failure("ComputePolycube: " + status.Message());
  }
  out.Iterations += stats.Iterations;
  out.FrameFitResidual = stats.Terms.Arap;
  mesh.X = Unflat(x);
  return Status::Success();
}

Status CheckInput(const TetMesh& input)
{
  const Eigen::Index n = input.Vertices.rows();
  const Eigen::Index t = input.Cells.rows();
  if (n == 0 || t == 0)
  {
    std::ostringstream message;
    message << "ComputePolycube: the input mesh is empty (" << n << " vertices, " << t << " tets)";
    return Status::Failure(message.str());
  }
  if (!input.Vertices.allFinite())
  {
    return Status::Failure("ComputePolycube: the input has a non-finite vertex coordinate");
  }
  for (Eigen::Index i = 0; i < t; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      if (input.Cells(i, c) < 0 || input.Cells(i, c) >= n)
      {
        std::ostringstream message;
        message << "ComputePolycube: tet " << i << " refers to vertex " << input.Cells(i, c)
                << ", outside [0, " << n << ")";
        return Status::Failure(message.str());
      }
    }
  }
  return Status::Success();
}

} // namespace

namespace
{
/// One deformation with the settings as given (ComputePolycube picks the starvation setting and
/// may call this twice).
Status ComputePolycubeOnce(const TetMesh& input,
  const PolycubeParameters& params,
  PolycubeResult& out,
  const Progress& progress,
  const std::vector<Eigen::Matrix3d>& tetFrames,
  const PolycubeCuts* cuts)
{
  const auto totalStart = Clock::now();
  out = PolycubeResult();
  out.StarvedHalvingsPerIteration = params.StarvedHalvingsPerIteration;
  Status status = CheckInput(input);
  if (!status)
  {
    return status;
  }
  if (!tetFrames.empty() && static_cast<Eigen::Index>(tetFrames.size()) != input.Cells.rows())
  {
    return Status::Failure("ComputePolycube: " + std::to_string(tetFrames.size()) + " frames for " +
      std::to_string(input.Cells.rows()) + " tets");
  }

  // About 4 kB per tet at the peak (the Hessian's 3x3 blocks and its factorisations).
  status = CheckMemoryEstimate("ComputePolycube: " + std::to_string(input.Cells.rows()) + " tets",
    4096.0 * static_cast<double>(input.Cells.rows()),
    "coarsen the tet mesh");
  if (!status)
  {
    return status;
  }

  // Normalised working copy (DESIGN.md "Scale").
  const UnitDiagonalFrame frame = ComputeUnitDiagonalFrame(input.Vertices);
  WorkMesh mesh;
  mesh.Cells = input.Cells;
  mesh.Rest = ToUnitDiagonal(frame, input.Vertices);
  mesh.Original = input.Vertices;
  mesh.InputVertexCount = static_cast<int>(input.Vertices.rows());
  mesh.OriginalPointId.resize(static_cast<size_t>(mesh.InputVertexCount));
  std::iota(mesh.OriginalPointId.begin(), mesh.OriginalPointId.end(), 0);
  mesh.ParentTet.resize(static_cast<size_t>(input.Cells.rows()));
  std::iota(mesh.ParentTet.begin(), mesh.ParentTet.end(), 0);
  for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
  {
    const double volume = TetSignedVolume(mesh.Rest, mesh.Cells, static_cast<int>(t));
    if (!(volume > 0.0))
    {
      std::ostringstream message;
      message << "ComputePolycube: tet " << t << " has non-positive volume ("
              << volume * frame.Scale * frame.Scale * frame.Scale
              << "); the input tets must be positively oriented (VTK node order)";
      return Status::Failure(message.str());
    }
  }
  // Closed form: work on the cut mesh, the copies across each cut related by its transition.
  const bool closedForm = cuts != nullptr && cuts->Count() > 0;
  mesh.Identity = mesh.OriginalPointId;
  if (closedForm)
  {
    if (tetFrames.empty())
    {
      return Status::Failure("ComputePolycube: cuts need the frame field (FrameField guidance)");
    }
    PolycubeCutMesh cutMesh;
    status = BuildPolycubeCutMesh(input, *cuts, cutMesh);
    if (!status)
    {
      return Status::Failure("ComputePolycube: " + status.Message());
    }
    const int copyCount = static_cast<int>(cutMesh.CopiedVertex.size());
    Points rest(copyCount, 3);
    Points original(copyCount, 3);
    for (int v = 0; v < copyCount; ++v)
    {
      rest.row(v) = mesh.Rest.row(cutMesh.CopiedVertex[static_cast<size_t>(v)]);
      original.row(v) = mesh.Original.row(cutMesh.CopiedVertex[static_cast<size_t>(v)]);
    }
    mesh.Cells = cutMesh.Cells;
    mesh.Rest = rest;
    mesh.Original = original;
    mesh.OriginalPointId = cutMesh.CopiedVertex;
    mesh.Identity = cutMesh.CopiedVertex;
    mesh.Copies = cutMesh.Copies;
    mesh.Transitions = cuts->Transitions;
  }
  TetTopology topology;
  RefreshTopology(mesh, topology);
  if (topology.NonManifoldFaceCount > 0)
  {
    std::ostringstream message;
    message << "ComputePolycube: " << topology.NonManifoldFaceCount
            << " faces are shared by more than two tets";
    return Status::Failure(message.str());
  }
  mesh.X = mesh.Rest;

  // Interior edges with both ends on the boundary would be forced flat.
  if (params.PresplitBoundaryEdges)
  {
    const auto boundaryEdges = BoundaryEdgeSet(topology.BoundaryFaces);
    std::vector<std::array<int, 2>> edges;
    for (const auto& e : topology.Edges)
    {
      if (topology.IsBoundaryVertex[static_cast<size_t>(e[0])] &&
        topology.IsBoundaryVertex[static_cast<size_t>(e[1])] && boundaryEdges.count(e) == 0)
      {
        edges.push_back(e);
      }
    }
    if (!edges.empty())
    {
      SplitEdges(mesh, edges);
      RefreshTopology(mesh, topology);
    }
    out.PresplitEdgeCount = static_cast<int>(edges.size());
  }

  // Initial rotation, or the frame-guided start.
  const auto rotationStart = Clock::now();
  const bool frameGuided = !tetFrames.empty();
  if (closedForm)
  {
    status = FramePoissonStart(mesh, topology, tetFrames, out);
    if (!status)
    {
      return status;
    }
  }
  else if (frameGuided)
  {
    status = FrameGuidedStart(mesh, topology, tetFrames, params, out);
    if (!status)
    {
      return status;
    }
  }
  else if (params.AlignInitialRotation)
  {
    out.InitialRotation = ComputeAxisAligningRotation(mesh.Rest, topology.BoundaryFaces);
    mesh.X = mesh.Rest * out.InitialRotation.transpose();
  }
  out.RotationSeconds = SecondsSince(rotationStart);
  if (!ReportProgress(progress, 0.02))
  {
    return Status::Failure("ComputePolycube: aborted");
  }

  // Continuation on the l1 alignment weight, eq. (9)-(13).
  const auto optimizationStart = Clock::now();
  const NewtonSettings::LinearSolverType solverType =
    params.LinearSolver == PolycubeParameters::LinearSolverType::Direct
    ? NewtonSettings::LinearSolverType::Direct
    : NewtonSettings::LinearSolverType::BlockPcg;
  double finalBarrier = params.BarrierWeight;
  PolycubeEnergyWeights lastWeights; // of the continuation's last round
  {
    PolycubeEnergy energy(mesh.Rest,
      mesh.Cells,
      topology.BoundaryFaces,
      NormalPairsAcrossCuts(mesh, topology, params.NormalDifferenceAcrossCuts));
    VariableReduction reduction = VariableReduction::Identity(mesh.VertexCount());
    if (closedForm)
    {
      status = CutReduction(mesh, {}, reduction);
      if (!status)
      {
        return Status::Failure("ComputePolycube: " + status.Message());
      }
    }
    PolycubeNewtonSolver solver(energy, reduction);
    Eigen::VectorXd x = Flat(mesh.X);
    double weight = params.AlignmentWeight;
    double eps = params.AlignmentEpsilon;
    const int rounds = std::max(1, params.MaxRounds);
    // An input that is already a polycube (within the tolerance) is left as it is.
    PolycubeEnergyTerms initial;
    energy.Evaluate(x.data(), initial);
    out.Residual = initial.Residual;
    out.Converged = initial.Residual < params.ResidualTolerance;
    double barrierThreshold = params.BarrierThreshold;
    for (int round = 0; round < rounds && !out.Converged; ++round)
    {
      PolycubeEnergyWeights weights;
      weights.Alignment = weight;
      weights.AlignmentEpsilon = eps;
      weights.NormalDifference = params.NormalDifferenceWeight;
      weights.Area = params.AreaWeight;
      weights.Barrier = params.BarrierWeight * std::max(1.0, weight);
      weights.BarrierThreshold = barrierThreshold;
      finalBarrier = weights.Barrier;
      lastWeights = weights;
      energy.SetWeights(weights);
      NewtonSettings settings;
      settings.LinearSolver = solverType;
      settings.MaxIterations = params.IterationsPerRound;
      NewtonStats stats;
      const auto roundStart = Clock::now();
      const double base = 0.02 + 0.78 * round / rounds;
      status = solver.Minimize(x,
        settings,
        stats,
        [&](double f) { return ReportProgress(progress, base + 0.78 * f / rounds); });
      if (!status)
      {
        return Status::Failure("ComputePolycube: " + status.Message());
      }
      out.Iterations += stats.Iterations;
      out.Rounds = round + 1;
      out.Residual = stats.Terms.Residual;
      PolycubeRound entry;
      entry.Weight = weight;
      entry.Epsilon = eps;
      entry.Residual = stats.Terms.Residual;
      entry.MinVolumeRatio = energy.MinVolumeRatio(x.data());
      entry.Arap = stats.Terms.Arap;
      entry.Iterations = stats.Iterations;
      entry.CgIterations = stats.CgIterations;
      entry.InfeasibleTrials = stats.InfeasibleTrials;
      entry.ArmijoTrials = stats.ArmijoTrials;
      entry.LastStep = stats.LastStep;
      entry.LineSearchFailed = stats.LineSearchFailed;
      entry.Seconds = SecondsSince(roundStart);
      entry.BarrierThreshold = barrierThreshold;
      out.RoundLog.push_back(entry);
      // A starved round: widen the barrier for the rest of the continuation.
      if (stats.InfeasibleTrials >
        params.StarvedHalvingsPerIteration * std::max(1, stats.Iterations))
      {
        barrierThreshold = std::max(barrierThreshold, params.AlignmentBarrierThreshold);
      }
      if (out.Residual < params.ResidualTolerance)
      {
        out.Converged = true;
        break;
      }
      weight *= params.AlignmentWeightGrowth;
      eps = std::max(params.MinAlignmentEpsilon, eps * params.AlignmentEpsilonDecay);
    }
    mesh.X = Unflat(x);
  }
  out.OptimizationSeconds = SecondsSince(optimizationStart);
  if (!out.Converged)
  {
    std::ostringstream message;
    message << "the polycube residual is " << out.Residual << " after " << out.Rounds
            << " rounds, above the tolerance " << params.ResidualTolerance;
    out.Warnings.push_back(message.str());
  }

  // Labels and charts, then the splits that flattening needs.
  const auto labelStart = Clock::now();
  Triangles adjacency = BoundaryAdjacency(mesh, topology.BoundaryFaces);
  std::vector<int> labels = PolycubeFaceLabels(mesh.X, topology.BoundaryFaces);
  PolycubeChartCleanup cleanup;
  cleanup.MinAreaFraction = params.MinChartAreaFraction;
  cleanup.MinFaceCount = params.MinChartFaceCount;
  if (closedForm)
  {
    // A chart may wrap around a handle through a cut (the four sides of a torus's bar): its
    // boundary loops then have no turn at all and are still flat. The rule would merge them.
    // (It also catches islands; exempting only the loops that cross a cut is left to do.)
    cleanup.MinBoundaryTurns = 0;
  }
  // Clean-up, and on a cut mesh labels that agree across the cuts where that folds no face (a
  // chart boundary may run along a cut's loop); returns the changes.
  auto cleanUpLabels = [&]()
  {
    return CleanUpCutMeshLabels(mesh.X,
      topology.BoundaryFaces,
      adjacency,
      closedForm ? mesh.Copies : std::vector<CopyRelation>(),
      mesh.Transitions,
      cleanup,
      labels);
  };
  out.RelabelledFaceCount = cleanUpLabels();
  // The repair also runs on a cut mesh (a CutReduction for `reduction`, NormalPairsAcrossCuts
  // for the pairs), but there it made every closed-form model worse when tried (vertices off
  // their planes: kitten 3 -> 16, rockerarm 10 -> 12, fertility 186 -> 236; each 8-26 s slower):
  // the collapse relabelling after it does better alone.
  if (!closedForm && out.Rounds > 0)
  {
    const VariableReduction everyCoordinate = VariableReduction::Identity(mesh.VertexCount());
    status = RepairTurnedBackCreases(mesh,
      topology.BoundaryFaces,
      CreaseAdjacency(mesh, topology.BoundaryFaces),
      {},
      everyCoordinate,
      lastWeights,
      params,
      solverType,
      cleanUpLabels,
      labels,
      out);
    if (!status)
    {
      return Status::Failure("ComputePolycube: " + status.Message());
    }
  }
  // Labels that cannot be flattened (a tongue of one chart squeezed between two sides of
  // another) show up as faces the penalised flattening collapses; they take the neighbouring
  // chart's label and the flattening starts again from the deformed positions.
  PolycubeCharts charts;
  std::vector<double> plane;
  int chartCount = 0;
  const int labelAttempts = 1 + std::max(0, params.CollapseRelabelAttempts);
  for (int labelAttempt = 0; labelAttempt < labelAttempts; ++labelAttempt)
  {
    charts = PlaneCharts(mesh, topology.BoundaryFaces, labels);
    for (int pass = 0; pass < 4; ++pass)
    {
      // An interior edge with both ends in one chart would lie in the chart's plane; a boundary
      // edge inside one chart whose ends also share a second chart would lie on the line where
      // the two planes meet, and its faces would be degenerate.
      const auto vertexCharts =
        VertexCharts(mesh.VertexCount(), topology.BoundaryFaces, charts.FaceChart);
      const auto boundaryEdges = BoundaryEdgeSet(topology.BoundaryFaces);
      std::vector<std::array<int, 2>> edges;
      for (const auto& e : topology.Edges)
      {
        if (boundaryEdges.count(e) == 0 &&
          ShareOne(
            vertexCharts[static_cast<size_t>(e[0])], vertexCharts[static_cast<size_t>(e[1])]))
        {
          edges.push_back(e);
        }
      }
      for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
      {
        for (int e = 0; e < 3; ++e)
        {
          const Eigen::Index g = adjacency(f, e);
          if (g <= f ||
            charts.FaceChart[static_cast<size_t>(f)] != charts.FaceChart[static_cast<size_t>(g)])
          {
            continue;
          }
          const int a = topology.BoundaryFaces(f, e);
          const int b = topology.BoundaryFaces(f, (e + 1) % 3);
          const auto& ca = vertexCharts[static_cast<size_t>(a)];
          const auto& cb = vertexCharts[static_cast<size_t>(b)];
          std::vector<int> common;
          std::set_intersection(
            ca.begin(), ca.end(), cb.begin(), cb.end(), std::back_inserter(common));
          if (common.size() >= 2)
          {
            edges.push_back({ std::min(a, b), std::max(a, b) });
          }
        }
      }
      if (edges.empty())
      {
        break;
      }
      const Triangles oldFaces = topology.BoundaryFaces;
      const int oldCount = mesh.VertexCount();
      SplitEdges(mesh, edges);
      RefreshTopology(mesh, topology);
      labels = TransferFaceValues(oldFaces, labels, oldCount, topology.BoundaryFaces, mesh);
      adjacency = BoundaryAdjacency(mesh, topology.BoundaryFaces);
      charts = PlaneCharts(mesh, topology.BoundaryFaces, labels);
      out.SplitEdgeCount += static_cast<int>(edges.size());
    }
    {
      // A tet whose four corners are in one chart (all its edges on the boundary, e.g. two
      // boundary faces in one chart across a boundary edge): split at its centroid.
      adjacency = BoundaryAdjacency(mesh, topology.BoundaryFaces);
      charts = PlaneCharts(mesh, topology.BoundaryFaces, labels);
      const auto vertexCharts =
        VertexCharts(mesh.VertexCount(), topology.BoundaryFaces, charts.FaceChart);
      std::vector<int> tets;
      for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
      {
        std::vector<int> common = vertexCharts[static_cast<size_t>(mesh.Cells(t, 0))];
        for (int c = 1; c < 4 && !common.empty(); ++c)
        {
          const auto& other = vertexCharts[static_cast<size_t>(mesh.Cells(t, c))];
          std::vector<int> next;
          std::set_intersection(
            common.begin(), common.end(), other.begin(), other.end(), std::back_inserter(next));
          common.swap(next);
        }
        if (!common.empty())
        {
          tets.push_back(static_cast<int>(t));
        }
      }
      if (!tets.empty())
      {
        const Triangles oldFaces = topology.BoundaryFaces;
        const int oldCount = mesh.VertexCount();
        SplitTets(mesh, tets);
        RefreshTopology(mesh, topology);
        labels = TransferFaceValues(oldFaces, labels, oldCount, topology.BoundaryFaces, mesh);
      }
      out.SplitTetCount = static_cast<int>(tets.size());
    }
    for (int& label : labels)
    {
      if (label < 0)
      {
        label = 0; // cannot happen for a manifold boundary; keep the output well formed
        out.Warnings.push_back("a boundary face lost its label in a split");
      }
    }
    adjacency = BoundaryAdjacency(mesh, topology.BoundaryFaces);
    charts = PlaneCharts(mesh, topology.BoundaryFaces, labels);
    out.CreaseTurnBackBeforeFlattening = frame.Scale *
      MaxCreaseTurnBack(
        ComputePolycubeCreases(
          mesh.X, topology.BoundaryFaces, CreaseAdjacency(mesh, topology.BoundaryFaces), charts),
        0.0);
    // The flattening of an earlier labelling attempt counts as flattening, not as labelling.
    out.LabelingSeconds = SecondsSince(labelStart) - out.FlatteningSeconds;
    if (!ReportProgress(progress, 0.82))
    {
      return Status::Failure("ComputePolycube: aborted");
    }

    // Chart planes: charts of one axis that share a vertex must share the plane.
    chartCount = charts.Count();
    std::vector<int> group(static_cast<size_t>(chartCount));
    std::iota(group.begin(), group.end(), 0);
    const auto vertexCharts =
      VertexCharts(mesh.VertexCount(), topology.BoundaryFaces, charts.FaceChart);
    for (const auto& list : vertexCharts)
    {
      for (size_t i = 0; i < list.size(); ++i)
      {
        for (size_t j = i + 1; j < list.size(); ++j)
        {
          const int a = list[i];
          const int b = list[j];
          if (charts.ChartLabel[static_cast<size_t>(a)] / 2 ==
            charts.ChartLabel[static_cast<size_t>(b)] / 2)
          {
            group[static_cast<size_t>(FindRoot(group, a))] = FindRoot(group, b);
          }
        }
      }
    }
    std::vector<double> planeSum(static_cast<size_t>(chartCount), 0.0);
    std::vector<double> planeWeight(static_cast<size_t>(chartCount), 0.0);
    for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
    {
      const int chart = charts.FaceChart[static_cast<size_t>(f)];
      const int axis = charts.ChartLabel[static_cast<size_t>(chart)] / 2;
      const int root = FindRoot(group, chart);
      const Eigen::Vector3d p0 = mesh.X.row(topology.BoundaryFaces(f, 0)).transpose();
      const Eigen::Vector3d p1 = mesh.X.row(topology.BoundaryFaces(f, 1)).transpose();
      const Eigen::Vector3d p2 = mesh.X.row(topology.BoundaryFaces(f, 2)).transpose();
      const double area = 0.5 * (p1 - p0).cross(p2 - p0).norm() + 1e-300;
      planeSum[static_cast<size_t>(root)] += area * (p0(axis) + p1(axis) + p2(axis)) / 3.0;
      planeWeight[static_cast<size_t>(root)] += area;
    }
    plane.assign(static_cast<size_t>(chartCount), 0.0);
    for (int c = 0; c < chartCount; ++c)
    {
      const int root = FindRoot(group, c);
      plane[static_cast<size_t>(c)] =
        planeSum[static_cast<size_t>(root)] / planeWeight[static_cast<size_t>(root)];
    }
    std::map<int, double> anchors;  // coordinate 3v+a -> plane
    std::map<int, int> anchorGroup; // coordinate 3v+a -> its plane's group of charts
    for (int v = 0; v < mesh.VertexCount(); ++v)
    {
      for (int chart : vertexCharts[static_cast<size_t>(v)])
      {
        const int axis = charts.ChartLabel[static_cast<size_t>(chart)] / 2;
        anchors[3 * v + axis] = plane[static_cast<size_t>(chart)];
        anchorGroup[3 * v + axis] = FindRoot(group, chart);
      }
    }
    std::vector<int> anchorIndex;
    std::vector<double> anchorTarget;
    for (const auto& entry : anchors)
    {
      anchorIndex.push_back(entry.first);
      anchorTarget.push_back(entry.second);
    }
    if (closedForm)
    {
      // Plane means of charts on the two sides of a cut need not agree with the cut's
      // transition; the targets are instead the nearest shape (least squares) with every chart
      // flat and every copy relation exact, so that the penalty can reach them.
      std::map<int, int> groupCoordinate;
      std::vector<std::array<int, 2>> equalities;
      for (int i : anchorIndex)
      {
        const auto first = groupCoordinate.emplace(anchorGroup[i], i);
        if (!first.second)
        {
          equalities.push_back({ i, first.first->second });
        }
      }
      VariableReduction flat;
      status = CutReduction(mesh, equalities, flat);
      if (!status)
      {
        return Status::Failure("ComputePolycube: " + status.Message());
      }
      const Eigen::VectorXd nearest = flat.Expand(flat.Restrict(Flat(mesh.X)));
      for (size_t i = 0; i < anchorIndex.size(); ++i)
      {
        anchorTarget[i] = nearest(anchorIndex[i]);
      }
    }

    // Flattening: pull the chart coordinates onto their planes with a growing penalty (the line
    // search keeps every tet positive), then make them exact and relax the rest by ARAP.
    const auto flattenStart = Clock::now();
    if (params.Flatten)
    {
      PolycubeEnergy energy(mesh.Rest, mesh.Cells, topology.BoundaryFaces);
      energy.SetAnchors(anchorIndex, anchorTarget);
      PolycubeEnergyWeights weights;
      weights.Barrier = finalBarrier;
      weights.BarrierThreshold = params.BarrierThreshold;
      Eigen::VectorXd x = Flat(mesh.X);
      // Faces that are not folded over their label's direction must not fold while flattening.
      std::vector<int> guarded(labels);
      energy.SetFaceLabels(guarded);
      int unguarded = 0;
      for (size_t f = 0; f < guarded.size(); ++f)
      {
        if (!(energy.FaceOrientation(x.data(), static_cast<int>(f)) > 0.0))
        {
          guarded[f] = -1;
          ++unguarded;
        }
      }
      energy.SetFaceLabels(guarded);
      weights.FaceBarrier = finalBarrier;
      weights.FaceBarrierThreshold = params.BarrierThreshold;
      // The folded ones are turned over by a penalty that grows with the anchors, and join the
      // barrier as soon as they face their label's direction.
      std::vector<int> folded(labels.size(), -1);
      for (size_t f = 0; f < labels.size(); ++f)
      {
        folded[f] = guarded[f] < 0 ? labels[f] : -1;
      }
      energy.SetUnfoldFaces(folded);
      out.InitiallyFoldedFaceCount = unguarded;
      {
        VariableReduction reduction = VariableReduction::Identity(mesh.VertexCount());
        if (closedForm)
        {
          status = CutReduction(mesh, {}, reduction);
          if (!status)
          {
            return Status::Failure("ComputePolycube: " + status.Message());
          }
        }
        PolycubeNewtonSolver solver(energy, reduction);
        out.FlattenHalvings = 0;
        double anchorWeight = 1e3 * std::max(1.0, finalBarrier);
        for (int round = 0; round < params.FlattenRounds; ++round, anchorWeight *= 10.0)
        {
          weights.Anchor = anchorWeight;
          weights.FaceUnfold = unguarded > 0 ? anchorWeight : 0.0;
          energy.SetWeights(weights);
          NewtonSettings settings;
          settings.LinearSolver = solverType;
          settings.MaxIterations = params.FlattenIterations;
          settings.StepTolerance = 1e-12;
          NewtonStats stats;
          status = solver.Minimize(x, settings, stats);
          if (!status)
          {
            return Status::Failure("ComputePolycube: " + status.Message());
          }
          out.Iterations += stats.Iterations;
          out.FlattenHalvings += stats.InfeasibleTrials;
          out.FlattenDeviation = stats.Terms.MaxAnchorDeviation;
          for (size_t f = 0; f < folded.size(); ++f)
          {
            if (folded[f] >= 0 &&
              energy.FaceOrientation(x.data(), static_cast<int>(f), folded[f]) > 0.0)
            {
              guarded[f] = folded[f];
              folded[f] = -1;
              --unguarded;
            }
          }
          energy.SetFaceLabels(guarded);
          energy.SetUnfoldFaces(folded);
          if (!ReportProgress(progress, 0.82 + 0.15 * (round + 1) / params.FlattenRounds))
          {
            return Status::Failure("ComputePolycube: aborted");
          }
          if (stats.Terms.MaxAnchorDeviation < 1e-10 && unguarded == 0)
          {
            break;
          }
        }
      }
      if (labelAttempt + 1 < labelAttempts)
      {
        const int collapsed = RelabelCollapsedFaces(energy,
          x,
          topology.BoundaryFaces,
          adjacency,
          closedForm ? FacesAcrossCuts(topology.BoundaryFaces, adjacency, mesh.Copies)
                     : std::vector<std::array<int, 3>>(),
          mesh.Transitions,
          params.CollapseAreaRatio,
          labels);
        if (collapsed > 0)
        {
          out.CollapseRelabelledFaceCount += collapsed;
          out.RelabelledFaceCount += cleanUpLabels();
          out.FlatteningSeconds += SecondsSince(flattenStart);
          continue; // mesh.X still holds the deformed, unflattened positions
        }
      }
      if (!closedForm && params.FlattenHomotopySteps > 0)
      {
        // The rest of the way with the planes hard (PolycubeHomotopy.h).
        energy.SetAnchors({}, {});
        HomotopySettings homotopy;
        homotopy.MaxSteps = params.FlattenHomotopySteps;
        homotopy.RelaxIterations = params.FlattenRelaxIterations;
        homotopy.FreezeBelow = params.FlattenFreezeBelow;
        homotopy.LinearSolver = solverType;
        HomotopyStats followed;
        status = FollowAnchors(energy, anchorIndex, anchorTarget, homotopy, x, followed);
        if (!status)
        {
          return Status::Failure("ComputePolycube: " + status.Message());
        }
        out.FlattenHomotopySteps = followed.Steps;
        out.FlattenHomotopyFraction = followed.SmallestFraction;
        out.FlattenFrozenAnchors = followed.FrozenAnchors;
        out.FlattenHalvings += followed.Halvings;
        out.FlattenDeviation = followed.Deviation;
      }
      // Make the planes exact. Where that would invert a tet or fold a chart face (a labelling the
      // connectivity cannot realise), the vertices of the offending elements keep their penalised
      // positions instead: every tet stays positive and the few released coordinates stay within
      // the penalty's tolerance of their planes.
      std::vector<std::vector<int>> vertexAnchors(static_cast<size_t>(mesh.VertexCount()));
      for (size_t i = 0; i < anchorIndex.size(); ++i)
      {
        vertexAnchors[static_cast<size_t>(anchorIndex[i] / 3)].push_back(static_cast<int>(i));
      }
      std::vector<bool> released(anchorIndex.size(), false);
      Eigen::VectorXd snapped = x;
      for (size_t i = 0; i < anchorIndex.size(); ++i)
      {
        snapped(anchorIndex[i]) = anchorTarget[i];
      }
      auto release = [&](int v)
      {
        for (int i : vertexAnchors[static_cast<size_t>(v)])
        {
          released[static_cast<size_t>(i)] = true;
          snapped(anchorIndex[static_cast<size_t>(i)]) = x(anchorIndex[static_cast<size_t>(i)]);
        }
      };
      // The vertices of the tets that `positions` inverts, and of the guarded faces it folds.
      auto markInvertedTets = [&](const Eigen::VectorXd& positions, std::vector<char>& marked)
      {
        const Points current = Unflat(positions);
        for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
        {
          if (!(TetSignedVolume(current, mesh.Cells, static_cast<int>(t)) > 0.0))
          {
            for (int k = 0; k < 4; ++k)
            {
              marked[static_cast<size_t>(mesh.Cells(t, k))] = 1;
            }
          }
        }
      };
      auto markFoldedFaces = [&](const Eigen::VectorXd& positions, std::vector<char>& marked)
      {
        for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
        {
          if (guarded[static_cast<size_t>(f)] >= 0 &&
            !(energy.FaceOrientation(positions.data(), static_cast<int>(f)) > 0.0))
          {
            for (int k = 0; k < 3; ++k)
            {
              marked[static_cast<size_t>(topology.BoundaryFaces(f, k))] = 1;
            }
          }
        }
      };
      auto releaseMarked = [&](const std::vector<char>& marked)
      {
        for (int v = 0; v < mesh.VertexCount(); ++v)
        {
          if (marked[static_cast<size_t>(v)])
          {
            release(v);
          }
        }
      };
      for (int attempt = 0; attempt < 50 && !energy.IsFeasible(snapped.data()); ++attempt)
      {
        // Tets first: the faces are checked on the positions their releases leave.
        std::vector<char> marked(static_cast<size_t>(mesh.VertexCount()), 0);
        markInvertedTets(snapped, marked);
        releaseMarked(marked);
        std::fill(marked.begin(), marked.end(), 0);
        markFoldedFaces(snapped, marked);
        releaseMarked(marked);
      }
      // The anchors with `loose` set (held by the penalty), the others (hard); returns the
      // number of vertices with a loose anchor.
      auto partitionAnchors = [&](const std::vector<bool>& loose,
                                std::vector<int>& looseIndex,
                                std::vector<double>& looseTarget,
                                std::vector<int>& hardIndex,
                                std::vector<double>& hardTarget)
      {
        std::vector<bool> looseVertex(static_cast<size_t>(mesh.VertexCount()), false);
        for (size_t i = 0; i < anchorIndex.size(); ++i)
        {
          if (loose[i])
          {
            looseIndex.push_back(anchorIndex[i]);
            looseTarget.push_back(anchorTarget[i]);
            looseVertex[static_cast<size_t>(anchorIndex[i] / 3)] = true;
          }
          else
          {
            hardIndex.push_back(anchorIndex[i]);
            hardTarget.push_back(anchorTarget[i]);
          }
        }
        return static_cast<int>(std::count(looseVertex.begin(), looseVertex.end(), true));
      };
      std::vector<int> fixedIndex, freeIndex;
      std::vector<double> fixedTarget, freeTarget;
      out.ReleasedVertexCount =
        partitionAnchors(released, freeIndex, freeTarget, fixedIndex, fixedTarget);
      if (!energy.IsFeasible(snapped.data()))
      {
        snapped = x; // cannot happen: releasing everything gives back the penalised positions
        out.Warnings.push_back("the charts could not be snapped onto their planes");
      }
      else
      {
        // ARAP relaxation with the exact planes hard (variables eliminated), the released
        // coordinates still held by the penalty.
        energy.SetAnchors(freeIndex, freeTarget);
        energy.SetWeights(weights);
        VariableReduction reduction;
        if (closedForm)
        {
          // On a cut mesh the planes stay unknowns (each chart's coordinates one variable), so
          // that the planes of charts linked through the transitions agree exactly. The start
          // is the penalised shape (it satisfies the transitions) projected onto the planes;
          // vertices of tets that projection inverts are released, as above.
          std::vector<bool> loose = released;
          // The translations stay as the penalised shape has them: moving them would move every
          // copy on the plus side of a cut, and thin tets there would invert.
          Eigen::VectorXd translations;
          {
            VariableReduction copiesOnly;
            CoordinateRelations relations(0, 0, {});
            status = CutReduction(mesh, {}, copiesOnly, &relations);
            if (!status)
            {
              return Status::Failure("ComputePolycube: " + status.Message());
            }
            translations = relations.Extras(copiesOnly.Restrict(x));
          }
          Eigen::VectorXd projected = x;
          bool feasible = false;
          for (int attempt = 0; attempt < 10 && !feasible; ++attempt)
          {
            std::map<int, int> groupCoordinate;
            std::vector<std::array<int, 2>> equalities;
            for (size_t i = 0; i < anchorIndex.size(); ++i)
            {
              if (loose[i])
              {
                continue;
              }
              const auto first =
                groupCoordinate.emplace(anchorGroup[anchorIndex[i]], anchorIndex[i]);
              if (!first.second)
              {
                equalities.push_back({ anchorIndex[i], first.first->second });
              }
            }
            // Charts linked through several cuts can tie the translations among themselves;
            // then they cannot also stay as they are, and are left free.
            status = CutReduction(mesh, equalities, reduction, nullptr, &translations);
            if (!status)
            {
              status = CutReduction(mesh, equalities, reduction);
            }
            if (!status)
            {
              break; // contradictory planes: keep the penalised shape below
            }
            projected = reduction.Expand(reduction.Restrict(x));
            feasible = energy.IsFeasible(projected.data());
            if (feasible)
            {
              break;
            }
            // Release the vertices of inverted tets and folded faces, and their neighbours (the
            // projection spreads a conflict over a few tets, so one ring at a time is slow).
            std::vector<char> bad(static_cast<size_t>(mesh.VertexCount()), 0);
            markInvertedTets(projected, bad);
            markFoldedFaces(projected, bad);
            std::vector<char> ring = bad;
            for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
            {
              const bool touches = bad[static_cast<size_t>(mesh.Cells(t, 0))] ||
                bad[static_cast<size_t>(mesh.Cells(t, 1))] ||
                bad[static_cast<size_t>(mesh.Cells(t, 2))] ||
                bad[static_cast<size_t>(mesh.Cells(t, 3))];
              for (int k = 0; k < 4 && touches; ++k)
              {
                ring[static_cast<size_t>(mesh.Cells(t, k))] = 1;
              }
            }
            // Copies move together (the transitions are hard): release every copy of a point.
            std::vector<char> releasedPoint(static_cast<size_t>(mesh.VertexCount()), 0);
            for (int v = 0; v < mesh.VertexCount(); ++v)
            {
              if (ring[static_cast<size_t>(v)])
              {
                releasedPoint[static_cast<size_t>(mesh.Identity[static_cast<size_t>(v)])] = 1;
              }
            }
            for (int v = 0; v < mesh.VertexCount(); ++v)
            {
              if (!releasedPoint[static_cast<size_t>(mesh.Identity[static_cast<size_t>(v)])])
              {
                continue;
              }
              for (int i : vertexAnchors[static_cast<size_t>(v)])
              {
                loose[static_cast<size_t>(i)] = true;
              }
            }
          }
          if (!feasible)
          {
            // Keep the penalised shape (every tet positive, the transitions exact), with its
            // charts flat only to the penalty's tolerance, and say so.
            projected = x;
            std::fill(loose.begin(), loose.end(), true);
            reduction = VariableReduction();
            status = CutReduction(mesh, {}, reduction);
            if (!status)
            {
              return Status::Failure("ComputePolycube: " + status.Message());
            }
            out.Warnings.push_back("the charts of the cut mesh could not all be made exactly flat "
                                   "with the cut transitions hard: they stay within the "
                                   "flattening penalty's tolerance of their planes");
          }
          std::vector<int> looseIndex, hardIndex;
          std::vector<double> looseTarget, hardTarget;
          out.ReleasedVertexCount =
            partitionAnchors(loose, looseIndex, looseTarget, hardIndex, hardTarget);
          energy.SetAnchors(looseIndex, looseTarget);
          snapped = projected;
        }
        else
        {
          reduction =
            VariableReduction::FixCoordinates(mesh.VertexCount(), fixedIndex, fixedTarget);
        }
        NewtonSettings settings;
        settings.LinearSolver = solverType;
        settings.MaxIterations = params.FlattenIterations;
        PolycubeNewtonSolver solver(energy, reduction);
        NewtonStats stats;
        status = solver.Minimize(snapped, settings, stats);
        out.Iterations += stats.Iterations;
        if (!status)
        {
          return Status::Failure("ComputePolycube: " + status.Message());
        }
      }
      mesh.X = Unflat(snapped);
    }
    out.FlatteningSeconds += SecondsSince(flattenStart);
    break;
  }

  // On a cut mesh the planes were unknowns of the last solve: read them back. The median, not
  // the mean: the vertices released at the snap sit off the plane, and a mean would move it off
  // the exact value that every other vertex of the chart shares.
  if (closedForm)
  {
    std::vector<std::vector<double>> values(plane.size());
    for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
    {
      const int chart = charts.FaceChart[static_cast<size_t>(f)];
      const int axis = charts.ChartLabel[static_cast<size_t>(chart)] / 2;
      for (int c = 0; c < 3; ++c)
      {
        values[static_cast<size_t>(chart)].push_back(mesh.X(topology.BoundaryFaces(f, c), axis));
      }
    }
    for (size_t c = 0; c < plane.size(); ++c)
    {
      auto& chartValues = values[c];
      if (!chartValues.empty())
      {
        auto middle = chartValues.begin() + static_cast<std::ptrdiff_t>(chartValues.size() / 2);
        std::nth_element(chartValues.begin(), middle, chartValues.end());
        plane[c] = *middle;
      }
    }
  }

  // Results in input units.
  out.Positions = FromUnitDiagonal(frame, mesh.X);
  // Cut translations from the copies: x_plus = Pi x_minus + t (in input units).
  out.CutTranslations = Points::Zero(closedForm ? cuts->Count() : 0, 3);
  {
    std::vector<int> copiesPerCut(static_cast<size_t>(out.CutTranslations.rows()), 0);
    for (const CopyRelation& r : mesh.Copies)
    {
      const Eigen::Matrix3d pi = mesh.Transitions[static_cast<size_t>(r.Cut)].cast<double>();
      out.CutTranslations.row(r.Cut) +=
        out.Positions.row(r.Plus) - (pi * out.Positions.row(r.Minus).transpose()).transpose();
      ++copiesPerCut[static_cast<size_t>(r.Cut)];
    }
    for (Eigen::Index c = 0; c < out.CutTranslations.rows(); ++c)
    {
      out.CutTranslations.row(c) /= std::max(1, copiesPerCut[static_cast<size_t>(c)]);
    }
  }
  out.CopyCount = static_cast<int>(mesh.Copies.size());
  out.Cells = mesh.Cells;
  out.OriginalPointId = mesh.OriginalPointId;
  out.OriginalPoints = mesh.Original;
  out.OriginalCellId = mesh.ParentTet;
  out.BoundaryFaces = topology.BoundaryFaces;
  out.BoundaryFaceTet = topology.BoundaryFaceTet;
  out.BoundaryFaceLabel = labels;
  out.ChartId = charts.FaceChart;
  out.ChartCount = chartCount;
  out.ChartPlane.resize(static_cast<size_t>(chartCount));
  for (int c = 0; c < chartCount; ++c)
  {
    const int axis = charts.ChartLabel[static_cast<size_t>(c)] / 2;
    out.ChartPlane[static_cast<size_t>(c)] =
      plane[static_cast<size_t>(c)] * frame.Scale + frame.Center(axis);
  }
  out.FaceLabels.setConstant(mesh.Cells.rows(), 4, -1);
  for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
  {
    out.FaceLabels(topology.BoundaryFaceTet[static_cast<size_t>(f)],
      topology.BoundaryFaceLocal[static_cast<size_t>(f)]) = labels[static_cast<size_t>(f)];
  }
  if (closedForm)
  {
    // Corners of M: copies are one vertex, and a chart that continues across a cut is one chart.
    const Triangles glued = IdentityFaces(topology.BoundaryFaces, mesh.Identity);
    const std::vector<int> linked = ChartsAcrossCuts(
      FacesAcrossCuts(
        topology.BoundaryFaces, BoundaryAdjacency(mesh, topology.BoundaryFaces), mesh.Copies),
      mesh.Transitions,
      labels,
      charts.FaceChart,
      chartCount);
    out.CornerCount = CountPolycubeCorners(mesh.VertexCount(), glued, linked);
  }
  else
  {
    out.CornerCount =
      CountPolycubeCorners(mesh.VertexCount(), topology.BoundaryFaces, charts.FaceChart);
  }
  out.InvertedTetCount = 0;
  out.MinVolumeRatio = std::numeric_limits<double>::infinity();
  for (Eigen::Index t = 0; t < mesh.Cells.rows(); ++t)
  {
    const double volume = TetSignedVolume(out.Positions, mesh.Cells, static_cast<int>(t));
    if (!(volume > 0.0))
    {
      ++out.InvertedTetCount;
    }
    const double rest = TetSignedVolume(mesh.Rest, mesh.Cells, static_cast<int>(t)) * frame.Scale *
      frame.Scale * frame.Scale;
    out.MinVolumeRatio = std::min(out.MinVolumeRatio, volume / rest);
  }
  // A vertex is on its planes when it is within 1e-9 of the diagonal of each (DESIGN.md's
  // tolerance for distinct points): released vertices that the flattening brought that close
  // count as flat.
  out.MaxPlaneDeviation = 0.0;
  std::vector<char> offPlane(static_cast<size_t>(out.Positions.rows()), 0);
  for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
  {
    const int chart = charts.FaceChart[static_cast<size_t>(f)];
    const int axis = charts.ChartLabel[static_cast<size_t>(chart)] / 2;
    for (int c = 0; c < 3; ++c)
    {
      const int v = topology.BoundaryFaces(f, c);
      const double deviation =
        std::abs(out.Positions(v, axis) - out.ChartPlane[static_cast<size_t>(chart)]);
      out.MaxPlaneDeviation = std::max(out.MaxPlaneDeviation, deviation);
      if (params.Flatten && deviation > 1e-9 * frame.Scale)
      {
        offPlane[static_cast<size_t>(v)] = 1;
      }
    }
  }
  out.UnflattenedVertexCount = static_cast<int>(std::count(offPlane.begin(), offPlane.end(), 1));
  if (out.UnflattenedVertexCount > 0)
  {
    std::ostringstream message;
    message << out.UnflattenedVertexCount
            << " vertices stay off their chart planes by more than 1e-9 of the diagonal (at most "
            << out.MaxPlaneDeviation / frame.Scale
            << " of it): snapping them would invert a tet or fold a chart face";
    out.Warnings.push_back(message.str());
  }
  // Unit-diagonal positions: the tolerance is 1e-3 of the diagonal.
  constexpr double TurnBackTolerance = 1e-3;
  const std::vector<PolycubeCrease> creases = ComputePolycubeCreases(
    mesh.X, topology.BoundaryFaces, CreaseAdjacency(mesh, topology.BoundaryFaces), charts);
  out.CreaseTurnBack =
    frame.Scale * MaxCreaseTurnBack(creases, TurnBackTolerance, &out.TurnedBackCreaseCount);
  // Both shapes have a unit diagonal, so the stretch compares like with like.
  out.SquashedCreaseCount = CountSquashedCreases(mesh.Rest,
    creases,
    PolycubeResult::SquashedCreaseStretch,
    PolycubeResult::SquashedCreaseMinLength,
    &out.MinCreaseStretch);
  // Say where the hexes will suffer, and what to try: both defects come from the labelling, and
  // the normal difference weight changes the labelling (on rockerarm, Uniform guidance, its
  // squashed edge is gone at 2, the smoothed hexes' minimum going from 0.21 to 0.53, and 0.48 at
  // 1.5; but other models do worse there, so it is no better default).
  if (out.SquashedCreaseCount > 0)
  {
    std::ostringstream message;
    message << out.SquashedCreaseCount
            << " polycube edges keep less than a quarter of their input length along their axis "
               "(the most squashed "
            << std::lround(100.0 * out.MinCreaseStretch)
            << " %): the hexes along them are stretched. Their vertices carry flag "
            << PolycubeVertexDefect::OnSquashedCrease
            << " in PolycubeDefect; another NormalDifferenceWeight (e.g. 1.5 or 2) gives another "
               "labelling, which may not have them";
    out.Warnings.push_back(message.str());
  }
  if (out.TurnedBackCreaseCount > 0)
  {
    std::ostringstream message;
    message << out.TurnedBackCreaseCount << " polycube edges run back along their axis (by up to "
            << out.CreaseTurnBack
            << " in input units): the faces between the turning points fold when flattened. "
               "Their vertices carry flag "
            << PolycubeVertexDefect::OnTurnedBackCrease << " in PolycubeDefect";
    out.Warnings.push_back(message.str());
  }
  out.VertexDefects.assign(static_cast<size_t>(out.Positions.rows()), 0);
  for (size_t v = 0; v < offPlane.size(); ++v)
  {
    out.VertexDefects[v] = offPlane[v] ? PolycubeVertexDefect::OffChartPlane : 0;
  }
  for (const PolycubeCrease& crease : creases)
  {
    const int flags =
      (crease.TurnBack > TurnBackTolerance ? PolycubeVertexDefect::OnTurnedBackCrease : 0) |
      (IsSquashedCrease(mesh.Rest,
         crease,
         PolycubeResult::SquashedCreaseStretch,
         PolycubeResult::SquashedCreaseMinLength)
          ? PolycubeVertexDefect::OnSquashedCrease
          : 0);
    for (int v : crease.Vertices)
    {
      out.VertexDefects[static_cast<size_t>(v)] |= flags;
    }
  }
  out.FoldedFaceCount = 0;
  for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
  {
    const int label = labels[static_cast<size_t>(f)];
    const Eigen::RowVector3d p0 = out.Positions.row(topology.BoundaryFaces(f, 0));
    const Eigen::Vector3d normal = (out.Positions.row(topology.BoundaryFaces(f, 1)) - p0)
                                     .cross(out.Positions.row(topology.BoundaryFaces(f, 2)) - p0)
                                     .transpose();
    if (!((label % 2 == 0 ? 1.0 : -1.0) * normal(label / 2) > 0.0))
    {
      ++out.FoldedFaceCount;
    }
  }
  if (out.FoldedFaceCount > 0)
  {
    std::ostringstream message;
    message << out.FoldedFaceCount << " boundary faces (of " << out.InitiallyFoldedFaceCount
            << " when flattening started) stay folded over their chart's direction";
    out.Warnings.push_back(message.str());
  }
  out.TotalSeconds = SecondsSince(totalStart);
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace

Status ComputePolycube(const TetMesh& input,
  const PolycubeParameters& params,
  PolycubeResult& out,
  const Progress& progress,
  const std::vector<Eigen::Matrix3d>& tetFrames,
  const PolycubeCuts* cuts)
{
  const auto start = Clock::now();
  // This guidance's setting of when the barrier widens, and the other one for a retry.
  const bool frameGuided = !tetFrames.empty();
  PolycubeParameters first = params;
  PolycubeParameters second = params;
  first.StarvedHalvingsPerIteration = frameGuided ? params.FrameGuidedStarvedHalvingsPerIteration
                                                  : params.StarvedHalvingsPerIteration;
  second.StarvedHalvingsPerIteration = frameGuided ? params.StarvedHalvingsPerIteration
                                                   : params.FrameGuidedStarvedHalvingsPerIteration;
  // The first run reports up to 3/4, a retry the rest.
  Status status =
    ComputePolycubeOnce(input, first, out, ProgressPart(progress, 0.0, 0.75), tetFrames, cuts);
  if (!status)
  {
    return status;
  }
  if (out.MinCreaseStretch < params.SquashedRetryStretch)
  {
    bool aborted = false;
    PolycubeResult retry;
    status = ComputePolycubeOnce(
      input, second, retry, ProgressPart(progress, 0.75, 0.25, &aborted), tetFrames, cuts);
    if (aborted)
    {
      return status;
    }
    if (!status)
    {
      // The first result stands.
      out.Warnings.push_back(
        "a second deformation against the squashed polycube edge failed: " + status.Message());
    }
    else if (retry.MinCreaseStretch > out.MinCreaseStretch ||
      (retry.MinCreaseStretch == out.MinCreaseStretch &&
        retry.UnflattenedVertexCount < out.UnflattenedVertexCount))
    {
      out = std::move(retry);
    }
    out.Retried = true;
  }
  out.TotalSeconds = SecondsSince(start);
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
