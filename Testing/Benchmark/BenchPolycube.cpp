// SPDX-License-Identifier: BSD-3-Clause
// Times ComputePolycube (uniform guidance) on a MEDIT tet mesh and prints the measures of
// DESIGN.md §4: wall seconds per phase (median of the runs), polycube residual, corners,
// inverted tets. Not run by CTest.
//
//   BenchPolycube [mesh.mesh = Data/rockerarm.mesh] [runs = 3] [output.mesh [rest.mesh]]
//   PCH_FRAMES=cuts BenchPolycube ...   (the closed form: cuts, frames with transitions)
//   PCH_ROUNDS=1 BenchPolycube ...      (prints every continuation round)
//   PCH_FLATTEN=0 ...                   (stop after labelling: the output is the deformed mesh)
//   PCH_LABELS=labels.txt ...           (writes each boundary face's label and chart id)
//   PCH_MONOTONE_REPAIR_ROUNDS=n, PCH_MONOTONE_REPAIR_TOLERANCE=t, PCH_MONOTONE_REPAIR_ITERATIONS=k
//                                       (override the crease repair's parameters)
//
// It also prints where the polycube is defective: the flagged vertices (PolycubeDefect) in
// groups, with their flags and their centre in the input.
//
// With an output path, the polycube of the last run is written as MEDIT (tets and boundary
// triangles).
#include "FrameField.h"
#include "HandleCuts.h"
#include "MeditFormat.h"
#include "PolycubeDeformation.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace polycubehex;

namespace
{
/// Where the polycube is defective: the flagged vertices (PolycubeResult::VertexDefects) in
/// groups joined through boundary triangles, largest first, each with its flags, its size and
/// its centre at the input positions, so that one knows where to look.
void PrintDefectClusters(const PolycubeResult& result)
{
  const size_t vertexCount = result.VertexDefects.size();
  std::vector<int> parent(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v)
  {
    parent[v] = static_cast<int>(v);
  }
  auto find = [&parent](int v)
  {
    while (parent[static_cast<size_t>(v)] != v)
    {
      v = parent[static_cast<size_t>(v)] =
        parent[static_cast<size_t>(parent[static_cast<size_t>(v)])];
    }
    return v;
  };
  for (Eigen::Index f = 0; f < result.BoundaryFaces.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = result.BoundaryFaces(f, k);
      const int b = result.BoundaryFaces(f, (k + 1) % 3);
      if (result.VertexDefects[static_cast<size_t>(a)] &&
        result.VertexDefects[static_cast<size_t>(b)])
      {
        parent[static_cast<size_t>(find(a))] = find(b);
      }
    }
  }
  struct Cluster
  {
    int Count = 0;
    int Flags = 0;
    Eigen::RowVector3d Sum = Eigen::RowVector3d::Zero();
  };
  std::vector<Cluster> clusters(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v)
  {
    if (result.VertexDefects[v])
    {
      Cluster& cluster = clusters[static_cast<size_t>(find(static_cast<int>(v)))];
      ++cluster.Count;
      cluster.Flags |= result.VertexDefects[v];
      cluster.Sum += result.OriginalPoints.row(static_cast<Eigen::Index>(v));
    }
  }
  clusters.erase(
    std::remove_if(clusters.begin(), clusters.end(), [](const Cluster& c) { return c.Count == 0; }),
    clusters.end());
  std::sort(clusters.begin(),
    clusters.end(),
    [](const Cluster& a, const Cluster& b) { return a.Count > b.Count; });
  std::printf(
    "defective vertices in %zu groups (flags: 1 off-plane, 2 turned-back edge, 4 squashed edge)\n",
    clusters.size());
  for (size_t c = 0; c < std::min<size_t>(clusters.size(), 10); ++c)
  {
    const Eigen::RowVector3d centre = clusters[c].Sum / clusters[c].Count;
    std::printf("  %4d vertices, flags %d, centre in the input (%.4g, %.4g, %.4g)\n",
      clusters[c].Count,
      clusters[c].Flags,
      centre[0],
      centre[1],
      centre[2]);
  }
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string path = argc > 1 ? argv[1] : "Data/rockerarm.mesh";
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  MeditMesh medit;
  const Status read = ReadMeditFile(path, medit);
  if (!read)
  {
    std::fprintf(stderr, "%s\n", read.Message().c_str());
    return 1;
  }
  TetMesh mesh;
  mesh.Vertices = medit.Vertices;
  mesh.Cells = medit.TetCells;
  std::printf("%s: %ld vertices, %ld tets\n",
    path.c_str(),
    static_cast<long>(mesh.Vertices.rows()),
    static_cast<long>(mesh.Cells.rows()));

  PolycubeParameters params;
  // Experiments without rebuilding: PCH_<NAME>=value overrides a few settings.
  auto overrideDouble = [](const char* name, double& target)
  {
    if (const char* value = std::getenv(name))
    {
      target = std::atof(value);
    }
  };
  auto overrideInt = [](const char* name, int& target)
  {
    if (const char* value = std::getenv(name))
    {
      target = std::atoi(value);
    }
  };
  overrideDouble("PCH_NORMAL_DIFFERENCE_WEIGHT", params.NormalDifferenceWeight);
  overrideInt("PCH_FLATTEN_ROUNDS", params.FlattenRounds);
  overrideInt("PCH_FLATTEN_ITERATIONS", params.FlattenIterations);
  overrideInt("PCH_FLATTEN_HOMOTOPY_STEPS", params.FlattenHomotopySteps);
  overrideInt("PCH_FLATTEN_RELAX_ITERATIONS", params.FlattenRelaxIterations);
  overrideDouble("PCH_FLATTEN_FREEZE_BELOW", params.FlattenFreezeBelow);
  if (std::getenv("PCH_DIRECT"))
  {
    params.LinearSolver = PolycubeParameters::LinearSolverType::Direct;
  }
  overrideInt("PCH_COLLAPSE_RELABEL_ATTEMPTS", params.CollapseRelabelAttempts);
  overrideDouble("PCH_ALIGNMENT_WEIGHT", params.AlignmentWeight);
  overrideDouble("PCH_ALIGNMENT_WEIGHT_GROWTH", params.AlignmentWeightGrowth);
  overrideDouble("PCH_ALIGNMENT_EPSILON", params.AlignmentEpsilon);
  overrideDouble("PCH_ALIGNMENT_EPSILON_DECAY", params.AlignmentEpsilonDecay);
  overrideDouble("PCH_MIN_ALIGNMENT_EPSILON", params.MinAlignmentEpsilon);
  overrideInt("PCH_MAX_ROUNDS", params.MaxRounds);
  overrideDouble("PCH_COLLAPSE_AREA_RATIO", params.CollapseAreaRatio);
  overrideInt("PCH_MONOTONE_REPAIR_ROUNDS", params.MonotoneRepairRounds);
  overrideDouble("PCH_MONOTONE_REPAIR_TOLERANCE", params.MonotoneRepairTolerance);
  overrideInt("PCH_MONOTONE_REPAIR_ITERATIONS", params.MonotoneRepairIterations);
  overrideDouble("PCH_MIN_CHART_AREA_FRACTION", params.MinChartAreaFraction);
  overrideInt("PCH_ITERATIONS_PER_ROUND", params.IterationsPerRound);
  overrideDouble("PCH_AREA_WEIGHT", params.AreaWeight);
  overrideDouble("PCH_BARRIER_WEIGHT", params.BarrierWeight);
  overrideDouble("PCH_BARRIER_THRESHOLD", params.BarrierThreshold);
  overrideDouble("PCH_ALIGNMENT_BARRIER_THRESHOLD", params.AlignmentBarrierThreshold);
  if (const char* value = std::getenv("PCH_FLATTEN"))
  {
    params.Flatten = std::atoi(value) != 0;
  }
  // PCH_FRAMES=1: FrameField guidance with the frame field of the uncut mesh; PCH_FRAMES=cuts:
  // the closed form (handle cuts, the frame field with its transitions, the cut mesh).
  std::vector<Eigen::Matrix3d> frames;
  PolycubeCuts cuts;
  const bool closedForm =
    std::getenv("PCH_FRAMES") && std::string(std::getenv("PCH_FRAMES")) == "cuts";
  if (std::getenv("PCH_FRAMES"))
  {
    FrameFieldResult field;
    CutFaces cutFaces;
    if (closedForm)
    {
      HandleCutResult handles;
      const Status cut = ComputeHandleCuts(mesh, HandleCutParameters(), handles);
      if (!cut)
      {
        std::fprintf(stderr, "%s\n", cut.Message().c_str());
        return 1;
      }
      cutFaces.Ids = handles.CutFaces;
      cutFaces.Sides = handles.CutSide;
      cuts.FaceCut = handles.CutFaces;
      cuts.FaceSide = handles.CutSide;
    }
    const auto frameStart = std::chrono::steady_clock::now();
    const Status computed = ComputeFrameField(mesh, cutFaces, FrameFieldParameters(), field);
    for (Eigen::Index c = 0; c < field.CutTransitions.rows(); ++c)
    {
      Eigen::Matrix3i pi;
      for (int a = 0; a < 9; ++a)
      {
        pi(a / 3, a % 3) = field.CutTransitions(c, a);
      }
      cuts.Transitions.push_back(pi);
    }
    if (!computed)
    {
      std::fprintf(stderr, "%s\n", computed.Message().c_str());
      return 1;
    }
    for (Eigen::Index t = 0; t < field.Frames.rows(); ++t)
    {
      frames.push_back(
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(field.Frames.row(t).data()));
    }
    std::printf("frame field: %.2f s, %d singular edges, alignment %.2f deg\n",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count(),
      field.SingularEdgeCount,
      field.BoundaryAlignmentError);
  }
  PolycubeResult result;
  std::vector<double> total, rotation, optimization, labeling, flattening;
  for (int run = 0; run < runs; ++run)
  {
    const Status status =
      ComputePolycube(mesh, params, result, {}, frames, closedForm ? &cuts : nullptr);
    if (!status)
    {
      std::fprintf(stderr, "%s\n", status.Message().c_str());
      return 1;
    }
    total.push_back(result.TotalSeconds);
    rotation.push_back(result.RotationSeconds);
    optimization.push_back(result.OptimizationSeconds);
    labeling.push_back(result.LabelingSeconds);
    flattening.push_back(result.FlatteningSeconds);
    std::printf("run %d: %.2f s\n", run + 1, result.TotalSeconds);
  }
  std::printf("time (median of %d): total %.2f s = rotation %.2f + optimization %.2f + labels and "
              "splits %.2f + flattening %.2f\n",
    runs,
    Median(total),
    Median(rotation),
    Median(optimization),
    Median(labeling),
    Median(flattening));
  std::printf("rounds %d, Newton iterations %d, residual before flattening %.3g (%s)\n",
    result.Rounds,
    result.Iterations,
    result.Residual,
    result.Converged ? "converged" : "NOT converged");
  std::printf("charts %d, corners %d, inverted tets %d, min volume ratio %.3g\n",
    result.ChartCount,
    result.CornerCount,
    result.InvertedTetCount,
    result.MinVolumeRatio);
  std::printf("splits: %d edges before, %d edges + %d tets after labelling; output %ld vertices, "
              "%ld tets\n",
    result.PresplitEdgeCount,
    result.SplitEdgeCount,
    result.SplitTetCount,
    static_cast<long>(result.Positions.rows()),
    static_cast<long>(result.Cells.rows()));
  if (!frames.empty())
  {
    std::printf("frame fit residual %.4g\n", result.FrameFitResidual);
  }
  std::printf("vertices off their chart plane %d (%d released at the snap), max plane deviation "
              "%.3g (input units), "
              "folded faces %d (%d before flattening)\n",
    result.UnflattenedVertexCount,
    result.ReleasedVertexCount,
    result.MaxPlaneDeviation,
    result.FoldedFaceCount,
    result.InitiallyFoldedFaceCount);
  std::printf(
    "flattening: anchor deviation %.3g of the diagonal before the snap, %d "
    "line-search halvings, %d homotopy steps (smallest fraction %.3g, %d anchors frozen)\n",
    result.FlattenDeviation,
    result.FlattenHalvings,
    result.FlattenHomotopySteps,
    result.FlattenHomotopyFraction,
    result.FlattenFrozenAnchors);
  std::printf("crease turn-back %.3g before flattening, %.3g after (input units), %d edges "
              "turning back over 1e-3 of the diagonal\n",
    result.CreaseTurnBackBeforeFlattening,
    result.CreaseTurnBack,
    result.TurnedBackCreaseCount);
  std::printf("squashed creases %d, smallest stretch %.3g\n",
    result.SquashedCreaseCount,
    result.MinCreaseStretch);
  std::printf("crease repair: %d rounds, %d faces shaved\n",
    result.MonotoneRepairRounds,
    result.ShavedFaceCount);
  std::printf("faces relabelled: %d by the clean-up, %d because the flattening collapsed them\n",
    result.RelabelledFaceCount,
    result.CollapseRelabelledFaceCount);
  PrintDefectClusters(result);
  if (std::getenv("PCH_ROUNDS"))
  {
    std::printf("round  weight     eps     barrier residual  minvol    arap      it  cg  infeas "
                "armijo step     seconds\n");
    for (size_t k = 0; k < result.RoundLog.size(); ++k)
    {
      const PolycubeRound& r = result.RoundLog[k];
      std::printf(
        "%5zu  %-9.3g  %-6.3g  %-6.2g  %-8.3g  %-8.2g  %-8.3g  %2d  %3d %6d %6d  %-8.2g %.2f%s\n",
        k,
        r.Weight,
        r.Epsilon,
        r.BarrierThreshold,
        r.Residual,
        r.MinVolumeRatio,
        r.Arap,
        r.Iterations,
        r.CgIterations,
        r.InfeasibleTrials,
        r.ArmijoTrials,
        r.LastStep,
        r.Seconds,
        r.LineSearchFailed ? "  line search failed" : "");
    }
  }
  for (const auto& warning : result.Warnings)
  {
    std::printf("warning: %s\n", warning.c_str());
  }

  if (argc > 3)
  {
    MeditMesh out;
    out.Vertices = result.Positions;
    out.TetCells = result.Cells;
    out.TriangleCells = result.BoundaryFaces;
    const Status written = WriteMeditFile(argv[3], out);
    if (!written)
    {
      std::fprintf(stderr, "%s\n", written.Message().c_str());
      return 1;
    }
  }
  if (const char* labelPath = std::getenv("PCH_LABELS"))
  {
    // Per boundary face (the order of the output's triangles): label and chart id.
    if (FILE* file = std::fopen(labelPath, "w"))
    {
      for (size_t f = 0; f < result.BoundaryFaceLabel.size(); ++f)
      {
        std::fprintf(file, "%d %d\n", result.BoundaryFaceLabel[f], result.ChartId[f]);
      }
      std::fclose(file);
    }
  }
  if (argc > 4)
  {
    // The same mesh at its input positions (split vertices interpolated), for diagnostics.
    MeditMesh rest;
    rest.Vertices = result.OriginalPoints;
    rest.TetCells = result.Cells;
    rest.TriangleCells = result.BoundaryFaces;
    const Status written = WriteMeditFile(argv[4], rest);
    if (!written)
    {
      std::fprintf(stderr, "%s\n", written.Message().c_str());
      return 1;
    }
  }
  return 0;
}
