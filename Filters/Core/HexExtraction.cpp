// SPDX-License-Identifier: BSD-3-Clause
#include "HexExtraction.h"

#include "MemoryBudget.h"

#include "HexDoublets.h"
#include "HexLatticeExtraction.h"
#include "HexLatticePadding.h"
#include "HexMeshValidity.h"
#include "HexPadding.h"
#include "HexPaddingPlacement.h"
#include "HexResolution.h"
#include "HexScaledJacobian.h"
#include "HexSmoothing.h"
#include "HexUntangling.h"
#include "IntegerRounding.h"
#include "PolycubeSeams.h"
#include "ThreadCount.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <thread>

namespace polycubehex
{
namespace
{
constexpr int FaceTable[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

double SignedVolume(const Points& x, const Tets& cells, int t)
{
  const Eigen::Vector3d a = x.row(cells(t, 0)).transpose();
  return (x.row(cells(t, 1)).transpose() - a)
           .dot((x.row(cells(t, 2)).transpose() - a).cross(x.row(cells(t, 3)).transpose() - a)) /
    6.0;
}

/// Refuses a mesh with a non-positive tet; `volume` receives the total volume.
Status CheckPositive(const Points& x, const Tets& cells, const char* space, double& volume)
{
  // Flat tets count as inverted: a volume below 1e-14 of the bounding-box diagonal cubed that
  // is also below 1e-12 of the cube of the tet's own longest edge (a height under about 1e-11 of
  // it, where barycentric coordinates lose their digits). The second test spares a small, thin
  // but sound tet that a flattening leaves at a polycube's fold (rockerarm's closed form at
  // CutMeshBoundaryAlignmentWeight 1000 has one of 1.1e-14 of the diagonal cubed).
  const double diagonal = (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
  const double meshFloor = 1e-14 * diagonal * diagonal * diagonal;
  int bad = 0;
  int first = -1;
  double firstVolume = 0.0;
  volume = 0.0;
  for (int t = 0; t < cells.rows(); ++t)
  {
    const double v = SignedVolume(x, cells, t);
    volume += v;
    if (v > meshFloor)
    {
      continue;
    }
    double longest = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        longest = std::max(longest, (x.row(cells(t, i)) - x.row(cells(t, j))).squaredNorm());
      }
    }
    longest = std::sqrt(longest);
    if (!(v > 1e-12 * longest * longest * longest))
    {
      first = bad == 0 ? t : first;
      firstVolume = bad == 0 ? v : firstVolume;
      ++bad;
    }
  }
  if (bad > 0)
  {
    std::ostringstream message;
    message << bad << " tet(s) are inverted or flat in the " << space << " positions (first: tet "
            << first << ", volume " << firstVolume << "); hex extraction needs positive tets";
    return Status::Failure(message.str());
  }
  return Status::Success();
}

Status CheckInput(const PolycubeTetMesh& input)
{
  const Eigen::Index vertexCount = input.OriginalVertices.rows();
  if (input.Cells.rows() == 0 || vertexCount == 0)
  {
    return Status::Failure("the input has no tets");
  }
  if (input.PolycubeVertices.rows() != vertexCount)
  {
    return Status::Failure("the input has " + std::to_string(vertexCount) +
      " original positions but " + std::to_string(input.PolycubeVertices.rows()) +
      " polycube positions");
  }
  if (input.Cells.minCoeff() < 0 || input.Cells.maxCoeff() >= vertexCount)
  {
    return Status::Failure("a tet refers to a vertex that does not exist");
  }
  if (input.FaceLabels.rows() != input.Cells.rows() || (input.FaceLabels.array() < 0).all())
  {
    return Status::Failure("the input has no polycube labels (PolycubeLabels, 4 per tet): "
                           "run the polycube deformation first");
  }
  if (!input.OriginalVertices.allFinite() || !input.PolycubeVertices.allFinite())
  {
    return Status::Failure("the input has non-finite positions");
  }
  return Status::Success();
}

/// Drops the per-hex rows of the hexes `removed` (ascending indices before the removal) from
/// `lattice`, whose Mesh.Cells has already lost them.
void RemoveLatticeHexRows(LatticeHexMesh& lattice, const std::vector<int>& removed)
{
  if (removed.empty())
  {
    return;
  }
  const Eigen::Index before = lattice.HexCenters.rows();
  std::vector<char> gone(static_cast<size_t>(before), 0);
  for (int h : removed)
  {
    gone[static_cast<size_t>(h)] = 1;
  }
  auto keepRows = [&](Points& rows)
  {
    if (rows.rows() != before)
    {
      return;
    }
    Eigen::Index kept = 0;
    for (Eigen::Index h = 0; h < before; ++h)
    {
      if (!gone[static_cast<size_t>(h)])
      {
        rows.row(kept++) = rows.row(h);
      }
    }
    rows.conservativeResize(kept, Eigen::NoChange);
  };
  keepRows(lattice.HexCenters);
  keepRows(lattice.HexOrigins);
  if (lattice.HexCornerRotations.size() == static_cast<size_t>(8 * before))
  {
    std::vector<Eigen::Matrix3i> rotations;
    for (Eigen::Index h = 0; h < before; ++h)
    {
      for (int k = 0; k < 8 && !gone[static_cast<size_t>(h)]; ++k)
      {
        rotations.push_back(lattice.HexCornerRotations[static_cast<size_t>(8 * h + k)]);
      }
    }
    lattice.HexCornerRotations = std::move(rotations);
  }
}
/// One extraction at `scaleFactor` times the scale the targets ask for (extractHexMesh retries
/// at other factors).
Status ExtractHexMeshOnce(const PolycubeTetMesh& input,
  const HexExtractionParameters& params,
  double scaleFactor,
  HexExtractionResult& result,
  const Progress& progress)
{
  result = HexExtractionResult();
  Status status = CheckInput(input);
  if (!status)
  {
    return status;
  }
  if (params.TargetEdgeLength <= 0.0 && params.TargetHexCount < 1)
  {
    return Status::Failure("set TargetHexCount >= 1 or TargetEdgeLength > 0");
  }
  if (params.Padding && !(params.PaddingThickness > 0.0 && params.PaddingThickness < 0.5))
  {
    return Status::Failure("PaddingThickness must lie in (0, 0.5) hex edges");
  }
  const Tets& cells = input.Cells;

  // The core works on the input normalised to a unit diagonal (DESIGN.md, "Scale").
  const Eigen::RowVector3d low = input.OriginalVertices.colwise().minCoeff();
  const Eigen::RowVector3d high = input.OriginalVertices.colwise().maxCoeff();
  const Eigen::RowVector3d centre = 0.5 * (low + high);
  const double diagonal = (high - low).norm() > 0.0 ? (high - low).norm() : 1.0;
  const Points original = (input.OriginalVertices.rowwise() - centre) / diagonal;

  double inputVolume = 0.0;
  double polycubeVolume = 0.0;
  if (!(status = CheckPositive(original, cells, "original", inputVolume)))
  {
    return status;
  }
  if (!(status = CheckPositive(input.PolycubeVertices, cells, "polycube", polycubeVolume)))
  {
    return status;
  }

  // A closed-form polycube is cut open: find its seams and their transitions.
  PolycubeSeams cutSeams;
  if (!input.CutRotations.empty() &&
    !(status = FindPolycubeSeams(input.OriginalVertices,
        input.PolycubeVertices,
        cells,
        input.FaceLabels,
        input.CutRotations,
        input.CutTranslations,
        cutSeams)))
  {
    return status;
  }
  const bool hasSeams = !cutSeams.Empty();
  ChartPlanes charts;
  if (!(status = ComputeChartPlanes(
          input.PolycubeVertices, cells, input.FaceLabels, charts, hasSeams ? &cutSeams : nullptr)))
  {
    return status;
  }
  result.ChartCount = static_cast<int>(charts.ChartLabel.size());
  result.PlaneCount = static_cast<int>(charts.PlaneAxis.size());

  // Each labelled face must face its label's direction in the polycube, and its area counts
  // towards the padding layer's share of the hex budget.
  double polycubeArea = 0.0;
  const Eigen::RowVector3d polycubeExtent =
    input.PolycubeVertices.colwise().maxCoeff() - input.PolycubeVertices.colwise().minCoeff();
  const double degenerateArea = 1e-12 * polycubeExtent.squaredNorm();
  int against = 0;
  int labelled = 0;
  int firstAgainst = -1;
  for (int t = 0; t < cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int label = input.FaceLabels(t, k);
      if (label < 0)
      {
        continue;
      }
      const Eigen::Vector3d a = input.PolycubeVertices.row(cells(t, FaceTable[k][0])).transpose();
      const Eigen::Vector3d b = input.PolycubeVertices.row(cells(t, FaceTable[k][1])).transpose();
      const Eigen::Vector3d c = input.PolycubeVertices.row(cells(t, FaceTable[k][2])).transpose();
      const Eigen::Vector3d normal = (b - a).cross(c - a);
      polycubeArea += 0.5 * normal.norm();
      const double along = (label % 2 == 0 ? 1.0 : -1.0) * normal[label / 2];
      ++labelled;
      // A face flattened to (numerically) zero area has no direction to check; it contributes
      // no lattice point of its own, so it cannot mislead the extraction.
      if (normal.norm() <= degenerateArea)
      {
        continue;
      }
      if (!(along > 0.5 * normal.norm()))
      {
        firstAgainst = against == 0 ? t : firstAgainst;
        ++against;
      }
    }
  }
  if (against > 0.01 * labelled)
  {
    return Status::Failure(std::to_string(against) + " of " + std::to_string(labelled) +
      " boundary faces do not face the direction of their polycube label in the polycube (first "
      "in tet " +
      std::to_string(firstAgainst) + "); the labels and the polycube positions disagree");
  }
  if (against > 0)
  {
    // A few such faces sit where the deformation could not flatten its labels (it leaves those
    // vertices a hair off their planes); the rounding puts them on the planes and the hexes
    // there may come out inverted, which the validity report shows.
    result.Warnings.push_back(std::to_string(against) +
      " boundary faces do not face the direction of their polycube label in the polycube "
      "(first in tet " +
      std::to_string(firstAgainst) + "); the hexes near them may be inverted");
  }

  // 1. Resolution.
  result.LatticeScale = ComputeLatticeScale(polycubeVolume,
                          polycubeArea,
                          inputVolume * diagonal * diagonal * diagonal,
                          params.TargetHexCount,
                          params.TargetEdgeLength,
                          params.Padding) *
    scaleFactor;
  result.TargetLatticeScale = result.LatticeScale / scaleFactor;
  if (!(result.LatticeScale > 0.0))
  {
    return Status::Failure("cannot choose a resolution from these targets");
  }
  {
    // About 2 kB per hex at the peak (lattice points per tet, their keys, the padding copies,
    // the smoothing's adjacency), measured within a factor of two on rockerarm.
    const double s = result.LatticeScale;
    const double hexes = polycubeVolume * s * s * s + (params.Padding ? polycubeArea * s * s : 0.0);
    if (!(status = CheckMemoryEstimate(
            "hex extraction of about " + std::to_string(static_cast<long long>(hexes)) + " hexes",
            2048.0 * hexes,
            "lower TargetHexCount or raise TargetEdgeLength")))
    {
      return status;
    }
  }
  const Eigen::RowVector3d polycubeCentre = 0.5 *
    (input.PolycubeVertices.colwise().minCoeff() + input.PolycubeVertices.colwise().maxCoeff());

  // 2. Integer planes. Whether greedy rounding keeps every tet positive depends on where the
  //    planes fall between integers, so a failure is retried at slightly different scales (the
  //    hex count is a target, not a promise); the first success wins. The fast path is tried
  //    at every scale first, the slow fallbacks only at the target scale after all failed.
  auto start = std::chrono::steady_clock::now();
  IntegerRoundingParameters rounding;
  rounding.CandidateCount = params.RoundingCandidates;
  rounding.MinimumVolumeRatio = params.MinimumVolumeRatio;
  rounding.SmoothMap = params.MapSmoothing;
  IntegerRoundingResult rounded;
  const double factors[] = { 1.0, 1.01, 0.99, 1.02, 0.98, 1.03, 0.97 };
  const int attempts = std::max(1, std::min(params.RoundingAttempts, 7));
  const double targetScale = result.LatticeScale;
  std::unique_ptr<IntegerRoundingResult> bestEffort;
  double bestEffortScale = targetScale;
  // Rounds at `factor` times the target scale; the status of roundPolycubePlanes.
  auto roundAt = [&](double factor, bool fastPathOnly)
  {
    result.LatticeScale = targetScale * factor;
    const Points reference =
      (input.PolycubeVertices.rowwise() - polycubeCentre) * result.LatticeScale;
    // In the lattice, u = s (x - c): u_plus = Pi u_minus + s (t + Pi c - c).
    for (int c = 0; c < cutSeams.CutCount(); ++c)
    {
      const Eigen::Vector3d centreColumn = polycubeCentre.transpose();
      cutSeams.Translations[static_cast<size_t>(c)] = result.LatticeScale *
        (input.CutTranslations[static_cast<size_t>(c)] +
          cutSeams.Rotations[static_cast<size_t>(c)].cast<double>() * centreColumn - centreColumn);
    }
    rounding.FastPathOnly = fastPathOnly;
    const Status roundingStatus = roundPolycubePlanes(
      original,
      reference,
      cells,
      charts,
      rounding,
      rounded,
      [&progress](double p) { return ReportProgress(progress, 0.3 * p); },
      hasSeams ? &cutSeams : nullptr);
    ++result.RoundingAttempts;
    if (roundingStatus && rounded.BestEffort && !bestEffort)
    {
      // Keep the first best-effort rounding in case no scale gives a clean one.
      bestEffort = std::make_unique<IntegerRoundingResult>(rounded);
      bestEffortScale = result.LatticeScale;
    }
    return roundingStatus;
  };
  auto aborted = [](const Status& s) { return s.Message().find("aborted") != std::string::npos; };
  bool clean = false;
  bool unflattenable = false;
  for (int attempt = 0; attempt < attempts && !clean && !unflattenable; ++attempt)
  {
    status = roundAt(factors[attempt], attempts > 1);
    if (!status && aborted(status))
    {
      return status;
    }
    clean = status && !rounded.BestEffort;
    unflattenable = status && rounded.UnflattenableCharts; // then no scale does better
  }
  if (!clean && !unflattenable && attempts > 1)
  {
    // The slow fallbacks (barrier relaxation, careful rounding), at the target scale.
    status = roundAt(factors[0], false);
    if (!status && aborted(status))
    {
      return status;
    }
  }
  if (!status && bestEffort && status.Message().find("aborted") == std::string::npos)
  {
    status = Status::Success();
    rounded.BestEffort = true;
  }
  if (status && rounded.BestEffort && bestEffort)
  {
    rounded = *bestEffort;
    result.LatticeScale = bestEffortScale;
  }
  if (status && rounded.BestEffort)
  {
    result.RoundingInvertedTetCount = rounded.InvertedTetCount;
    result.Warnings.push_back("integer rounding could not keep every tet positive (" +
      rounded.BestEffortReason + "); " + std::to_string(rounded.InvertedTetCount) +
      " tets stay inverted, and the hexes near them may be too");
  }
  if (!status)
  {
    return status;
  }
  result.RoundedPolycube = rounded.Positions;
  if (hasSeams)
  {
    // From here on the cutSeams map lattice frames: their translations are the rounded integers.
    if (rounded.MaxPlaneFraction > 1e-6)
    {
      std::ostringstream message;
      message << "integer rounding left a chart plane or a cut translation "
              << rounded.MaxPlaneFraction
              << " off an integer (the transitions fix a plane at a half translation); the hex "
                 "mesh cannot be stitched across the cuts";
      return Status::Failure(message.str());
    }
    for (int c = 0; c < cutSeams.CutCount(); ++c)
    {
      cutSeams.Translations[static_cast<size_t>(c)] =
        rounded.CutTranslations[static_cast<size_t>(c)].array().round().matrix();
    }
    result.IntegerCutTranslations = cutSeams.Translations;
  }
  result.RoundingFallbackCount = rounded.FallbackCount;
  result.RoundingPath = rounded.BestEffort ? "best effort"
    : rounded.Relaxed                      ? "relaxed"
    : rounded.CarefulPath                  ? "careful"
                                           : "fast";
  result.MaxPlaneShift = rounded.MaxPlaneShift;
  result.RoundingMinVolumeRatio = rounded.MinVolumeRatio;
  result.MapEnergyBefore = rounded.MapSmoothing.EnergyBefore;
  result.MapEnergyAfter = rounded.MapSmoothing.EnergyAfter;
  result.MapSmoothingIterations = rounded.MapSmoothing.Iterations;
  result.RoundingSeconds = Seconds(start);

  // The seams in lattice frames (integer translations), or none for a uniform polycube.
  const PolycubeSeams* seams = hasSeams ? &cutSeams : nullptr;

  // 3. Lattice cubes, seamless across the cuts (a vertex or cube on a seam is found from both
  //    sides and kept once).
  start = std::chrono::steady_clock::now();
  LatticeHexMesh lattice;
  status = extractLatticeHexes(
    original,
    rounded.Positions,
    cells,
    charts,
    LatticeExtractionParameters(),
    lattice,
    [&progress](double p) { return ReportProgress(progress, 0.3 + 0.3 * p); },
    seams);
  if (!status)
  {
    return status;
  }
  if (lattice.Mesh.Cells.rows() == 0)
  {
    return Status::Failure("no hex fits in the polycube at this resolution; raise "
                           "TargetHexCount or lower TargetEdgeLength");
  }
  if (lattice.InconsistentSeamCount > 0)
  {
    result.Warnings.push_back(std::to_string(lattice.InconsistentSeamCount) +
      " lattice points on the cuts did not match across them; the hex mesh may have seams");
  }
  result.ExtractionSeconds = Seconds(start);
  // A pinched boundary (two cubes touching along an edge only, where the rounding left tets
  // inverted) cannot be padded: the padding quad over the edge would have four hexes.
  {
    std::vector<int> pinching;
    result.RemovedPinchHexCount =
      RemovePinchingHexes(lattice.Mesh, ComputeHexScaledJacobians(lattice.Mesh), &pinching);
    RemoveLatticeHexRows(lattice, pinching);
  }

  // 4. Padding layer. The inner copy of a boundary vertex moves PaddingThickness hexes inwards
  //    along each of its charts' normals, in the lattice, and is mapped through the tets around
  //    the vertex (HexLatticePadding.h).
  start = std::chrono::steady_clock::now();
  if (params.Padding)
  {
    LatticePaddingResult padding;
    if (!(status = addLatticePaddingLayer(original,
            rounded.Positions,
            cells,
            charts,
            params.PaddingThickness,
            lattice,
            padding,
            seams)))
    {
      return status;
    }
    result.PaddingHexCount = padding.PaddingHexCount;
    result.UnmappedPaddingVertexCount = padding.UnmappedVertexCount;
    // With Smoothing the untangling and the sweeps move the inner copies themselves, and from
    // the placed positions they did worse where the rounding left tets inverted (fertility
    // Uniform at 17,910 hexes: smoothed minimum 0.346 -> 0.064, Hausdorff 12.5 -> 26.6e-3;
    // rockerarm closed form: Hausdorff 8.4 -> 13.1e-3), so they start from the mapped ones.
    if (params.PaddingPlacement && !params.Smoothing)
    {
      HexPaddingPlacementParameters placement;
      placement.Thickness = params.PaddingThickness;
      HexPaddingPlacementResult placed;
      if (!(status = placePaddingCopies(lattice.Mesh, padding.PaddingHexCount, placement, placed)))
      {
        return status;
      }
      result.PlacedPaddingVertexCount = placed.MovedCount;
      result.OptimizedPaddingVertexCount = placed.OptimizedCount;
      result.PaddingScaledJacobianMeanBeforePlacement = placed.MeanBefore;
      result.PaddingScaledJacobianMean = placed.MeanAfter;
    }
  }
  result.PaddingSeconds = Seconds(start);
  HexMesh mesh = std::move(lattice.Mesh);
  result.LatticeVertices = std::move(lattice.LatticeVertices);
  // Charts of M: across a seam, the charts of M_c that continue each other are one (a vertex on
  // a seam sees one chart, not a feature curve; GluedVertexCharts). Each is numbered by one of
  // its M_c charts, so ChartLabel still applies (in that chart's frame).
  const std::vector<int> gluedChart = GlueChartsAcrossSeams(cells, charts, seams);
  std::vector<std::vector<int>> vertexCharts = seams && !seams->Empty()
    ? GluedVertexCharts(lattice, gluedChart)
    : std::move(lattice.VertexCharts);

  // 5. Untangling and smoothing, boundary vertices held on the input surface.
  start = std::chrono::steady_clock::now();
  const Eigen::VectorXd rawQuality = ComputeHexScaledJacobians(mesh);
  result.ScaledJacobianMinBeforeSmoothing = rawQuality.minCoeff();
  result.ScaledJacobianMeanBeforeSmoothing = rawQuality.mean();
  result.ScaledJacobianMinAfterUntangling = result.ScaledJacobianMinBeforeSmoothing;
  result.ScaledJacobianMeanAfterUntangling = result.ScaledJacobianMeanBeforeSmoothing;
  result.InvertedHexCountAfterUntangling = static_cast<int>((rawQuality.array() <= 0.0).count());
  const bool untangle = params.Smoothing && params.Untangling;
  const bool smooth = params.Smoothing && params.SmoothingIterations > 0;
  if (untangle || smooth)
  {
    const bool cut = seams && !seams->Empty();
    const HexSmoothingSurface surface = MakeChartSurface(original,
      cells,
      charts.FaceChart,
      cut ? gluedChart : std::vector<int>(),
      cut ? SeamVertexIdentity(static_cast<int>(original.rows()), seams) : std::vector<int>());
    // Where the untangling stops changes what the smoothing reaches, either way (rockerarm's
    // closed form 0.402 or 0.591), so with UntanglingPaths 2 the untangling forks where its
    // inverted count first stalls (HexUntanglingParameters::ForkStallRounds): the second path
    // ends its main rounds there, both paths are smoothed, and the better mesh is kept. The
    // paths share their rounds up to the fork; after it the second runs on a thread of its own
    // (the smoothing is serial). Each path keeps its own projection through its untangling and
    // smoothing, so that the smoothing moves the vertices the untangling released the same way.
    const int pathCount = untangle ? std::clamp(params.UntanglingPaths, 1, 2) : 1;
    HexSurfaceProjection projection(surface, vertexCharts, mesh, params.SoftFeatureAngle);
    // After the projection has taken its boundary from the whole mesh: the vertices a removed
    // hex uncovers were interior and stay free (HexDoublets.h). Overlapping hexes first, as
    // their quads hide doublets from the face count.
    if (params.RemoveDoublets)
    {
      result.RemovedDoubletHexCount = RemoveOverlappingHexes(mesh, rawQuality);
      result.RemovedDoubletHexCount +=
        RemoveBoundaryDoublets(mesh, ComputeHexScaledJacobians(mesh));
    }
    // What one path made; the better one's goes into the result.
    struct PathOutcome
    {
      HexMesh Mesh;
      HexUntanglingResult Untangled;
      HexSmoothingResult Smoothed;
      int Released = 0;
      HexQualitySummary Quality;
    };
    PathOutcome outcomes[2];
    Status statuses[2] = { Status::Success(), Status::Success() };
    double pathUntanglingSeconds[2] = { 0.0, 0.0 };
    const double preparationSeconds = Seconds(start); // the projection and doublets
    auto smoothPath = [&](PathOutcome& outcome,
                        HexSurfaceProjection& pathProjection,
                        Status& pathStatus,
                        const Progress& pathProgress)
    {
      if (smooth)
      {
        HexSmoothingParameters smoothing;
        smoothing.Iterations = params.SmoothingIterations;
        if (!params.Polish)
        {
          smoothing.PolishPasses = 0;
        }
        smoothing.PolishReleaseAngle = params.PolishReleaseAngle;
        smoothing.PolishSharpEdgeAngle = params.PolishSharpEdgeAngle;
        smoothing.MeanSearchSweeps = params.MeanSearchSweeps;
        pathStatus =
          smoothHexMesh(outcome.Mesh, pathProjection, smoothing, outcome.Smoothed, pathProgress);
        if (!pathStatus)
        {
          return;
        }
      }
      outcome.Released = pathProjection.ReleasedCount();
      outcome.Quality = SummarizeHexQuality(ComputeHexScaledJacobians(outcome.Mesh));
    };
    auto runSecond = [&](UntanglingFork& fork, const Progress& pathProgress)
    {
      const auto secondStart = std::chrono::steady_clock::now();
      statuses[1] = resumeUntangling(
        fork, outcomes[1].Mesh, outcomes[1].Untangled, ProgressPart(pathProgress, 0.0, 0.5));
      pathUntanglingSeconds[1] = Seconds(secondStart);
      if (statuses[1])
      {
        smoothPath(
          outcomes[1], *fork.Projection(), statuses[1], ProgressPart(pathProgress, 0.5, 0.5));
      }
    };
    // Only the calling thread reports progress (a VTK filter's progress events belong to it);
    // the second path stops when the first is aborted or fails.
    std::atomic<bool> cancelled{ false };
    const Progress mainProgress = [&progress, &cancelled](double f)
    {
      const bool go = ReportProgress(progress, f);
      if (!go)
      {
        cancelled = true;
      }
      return go;
    };
    const bool sideBySide = ThreadCount() > 1;
    const unsigned threadCapBefore = ThreadCap;
    bool forked = false;
    UntanglingFork pendingFork;
    std::thread second;
    // Joins the second path and lifts the thread cap, at the end of the paths or on any exit.
    struct SecondPathJoin
    {
      std::thread& Thread;
      unsigned CapBefore;
      void operator()()
      {
        if (this->Thread.joinable())
        {
          this->Thread.join();
        }
        ThreadCap = this->CapBefore;
      }
      ~SecondPathJoin() { (*this)(); }
    } joinSecond{ second, threadCapBefore };
    std::function<void(UntanglingFork &&)> onStall;
    if (pathCount > 1)
    {
      onStall = [&](UntanglingFork&& fork)
      {
        forked = true;
        if (sideBySide)
        {
          // One thread each from here: two paths of parallel loops on two cores would make
          // every loop wait for a descheduled chunk.
          ThreadCap = 1;
          second = std::thread(
            [&runSecond, &cancelled](UntanglingFork pathFork)
            {
              ThreadCap = 1;
              runSecond(pathFork, [&cancelled](double) { return !cancelled.load(); });
            },
            std::move(fork));
        }
        else
        {
          pendingFork = std::move(fork);
        }
      };
    }
    const double mainWidth = 0.3 / pathCount;
    outcomes[0].Mesh = std::move(mesh);
    const auto mainStart = std::chrono::steady_clock::now();
    if (untangle)
    {
      statuses[0] = untangleHexMesh(outcomes[0].Mesh,
        projection,
        HexUntanglingParameters(),
        outcomes[0].Untangled,
        ProgressPart(mainProgress, 0.65, 0.5 * mainWidth),
        onStall);
    }
    pathUntanglingSeconds[0] = Seconds(mainStart);
    if (statuses[0])
    {
      smoothPath(outcomes[0],
        projection,
        statuses[0],
        ProgressPart(mainProgress, 0.65 + 0.5 * mainWidth, 0.5 * mainWidth));
    }
    if (!statuses[0])
    {
      cancelled = true;
    }
    joinSecond();
    if (statuses[0] && pendingFork.Impl)
    {
      runSecond(pendingFork, ProgressPart(progress, 0.65 + mainWidth, mainWidth));
    }
    for (const Status& pathStatus : statuses)
    {
      if (!pathStatus)
      {
        return pathStatus;
      }
    }
    const int bestPath =
      forked && BetterHexQuality(outcomes[1].Quality, outcomes[0].Quality, params.PathMinimumMargin)
      ? 1
      : 0;
    PathOutcome& best = outcomes[bestPath];
    // Wall-clock seconds: after the fork the paths run side by side.
    const double stepSeconds = Seconds(start);
    const double untanglingSeconds =
      preparationSeconds + std::max(pathUntanglingSeconds[0], pathUntanglingSeconds[1]);
    const double smoothingSeconds = std::max(0.0, stepSeconds - untanglingSeconds);
    mesh = std::move(best.Mesh);
    if (untangle)
    {
      result.ScaledJacobianMinAfterUntangling = best.Untangled.MinAfter;
      result.ScaledJacobianMeanAfterUntangling = best.Untangled.MeanAfter;
      result.InvertedHexCountAfterUntangling = best.Untangled.InvertedAfter;
      result.UntanglingRounds = best.Untangled.Rounds;
      result.UntanglingIterations = best.Untangled.Iterations;
      result.UntanglingKept = best.Untangled.Kept;
      result.UntanglingPath = bestPath + 1;
    }
    if (smooth)
    {
      result.SmoothingSweeps = best.Smoothed.Sweeps;
      result.ScaledJacobianMinBeforePolish = best.Smoothed.MinBeforePolish;
      result.PolishReleasedVertexCount = best.Smoothed.PolishReleased;
    }
    result.ReleasedBoundaryVertexCount = best.Released;
    result.UntanglingSeconds = untanglingSeconds;
    result.SmoothingSeconds = smoothingSeconds;
  }

  // 6. Measures and output in the input's units.
  start = std::chrono::steady_clock::now();
  result.ScaledJacobian = ComputeHexScaledJacobians(mesh);
  result.HexCount = static_cast<int>(mesh.Cells.rows());
  const HexQualitySummary quality = SummarizeHexQuality(result.ScaledJacobian);
  result.ScaledJacobianMin = quality.Min;
  result.ScaledJacobianMean = quality.Mean;
  result.InvertedHexCount = quality.Inverted;
  HexMeshValidity validity;
  if (checkHexMeshValidity(mesh, validity))
  {
    result.IrregularBoundaryVertexCount = validity.IrregularBoundaryVertexCount;
  }
  result.BoundaryQuads = ComputeHexBoundaryQuads(mesh);
  result.BoundaryQuadLabels.assign(result.BoundaryQuads.rows(), -1);
  for (int q = 0; q < result.BoundaryQuads.rows(); ++q)
  {
    // The quad's chart is the one all four of its vertices lie on.
    std::vector<int> common = vertexCharts[result.BoundaryQuads(q, 0)];
    for (int k = 1; k < 4; ++k)
    {
      const std::vector<int>& other = vertexCharts[result.BoundaryQuads(q, k)];
      std::vector<int> both;
      std::set_intersection(
        common.begin(), common.end(), other.begin(), other.end(), std::back_inserter(both));
      common.swap(both);
    }
    if (common.size() == 1)
    {
      result.BoundaryQuadLabels[q] = charts.ChartLabel[common[0]];
    }
  }
  result.MeasuresSeconds = Seconds(start);
  mesh.Vertices = (mesh.Vertices * diagonal).rowwise() + centre;
  result.Mesh = std::move(mesh);
  ReportProgress(progress, 1.0);
  return Status::Success();
}

/// The quality summary of an extraction's result.
HexQualitySummary QualityOf(const HexExtractionResult& result)
{
  return { result.ScaledJacobianMin, result.ScaledJacobianMean, result.InvertedHexCount };
}
} // namespace

Status extractHexMesh(const PolycubeTetMesh& input,
  const HexExtractionParameters& params,
  HexExtractionResult& result,
  const Progress& progress)
{
  // Where the lattice falls on the polycube's folds decides what the untangling and the
  // smoothing can reach, so a poor smoothed mesh is extracted again at a lattice scale 1 %
  // larger, then 1 % smaller, and the best is kept (ScaleRetries).
  const bool mayRetry = params.Smoothing && params.ScaleRetries > 0;
  const double firstShare = mayRetry ? 0.6 : 1.0;
  Status status =
    ExtractHexMeshOnce(input, params, 1.0, result, ProgressPart(progress, 0.0, firstShare));
  if (!status || !mayRetry)
  {
    return status;
  }
  // Relative to the scale the first extraction ended at (its rounding may have moved it).
  const double firstFactor = result.LatticeScale / result.TargetLatticeScale;
  const double steps[] = { 1.01, 0.99 };
  const int retries = std::min(params.ScaleRetries, 2);
  double discardedSeconds = 0.0;
  int tried = 0;
  std::vector<std::string> failedRetries; // the kept mesh's own warnings stay with it
  for (int k = 0; k < retries && result.ScaledJacobianMin < params.ScaleRetryBelow; ++k)
  {
    const auto start = std::chrono::steady_clock::now();
    bool aborted = false;
    const double from = firstShare + (1.0 - firstShare) * k / retries;
    const double width = (1.0 - firstShare) / retries;
    HexExtractionResult retry;
    status = ExtractHexMeshOnce(
      input, params, firstFactor * steps[k], retry, ProgressPart(progress, from, width, &aborted));
    ++tried;
    if (aborted)
    {
      return Status::Failure("hex extraction aborted");
    }
    if (status && BetterHexQuality(QualityOf(retry), QualityOf(result), params.PathMinimumMargin))
    {
      discardedSeconds += result.TotalSeconds();
      result = std::move(retry);
    }
    else
    {
      discardedSeconds += Seconds(start);
      if (!status)
      {
        failedRetries.push_back("the extraction at a scale " +
          std::string(steps[k] > 1.0 ? "1 % larger" : "1 % smaller") +
          " failed: " + status.Message());
      }
    }
  }
  result.Warnings.insert(result.Warnings.end(), failedRetries.begin(), failedRetries.end());
  if (tried > 0 && result.ScaledJacobianMin < params.ScaleRetryBelow)
  {
    std::ostringstream message;
    message << "the smoothed minimum scaled Jacobian stays at " << result.ScaledJacobianMin
            << ", below " << params.ScaleRetryBelow << ", after " << tried + 1
            << " extractions at lattice scales 1 % apart; the worst hexes follow the polycube's "
               "folds and squashed edges (its PolycubeDefect flags), which another polycube "
               "(e.g. another NormalDifferenceWeight) or another TargetHexCount may avoid";
    result.Warnings.push_back(message.str());
  }
  result.ScaleRetryCount = tried;
  result.DiscardedSeconds = discardedSeconds;
  ReportProgress(progress, 1.0);
  return Status::Success();
}

} // namespace polycubehex
