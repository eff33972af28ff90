// SPDX-License-Identifier: BSD-3-Clause
#include "FrameField.h"

#include "CubeSymmetry.h"
#include "FrameFieldEnergy.h"
#include "FrameFieldMatching.h"
#include "OctahedralField.h"
#include "TetGeometry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace polycubehex
{

namespace
{

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// Maps [0, 1] of a stage onto [begin, end] of the whole run.
Progress Stage(const Progress& progress, double begin, double end)
{
  if (!progress)
  {
    return {};
  }
  return [&progress, begin, end](double f) { return progress(begin + (end - begin) * f); };
}

// The mesh and the parameters, before anything indexes with the cells.
Status CheckMesh(const TetMesh& mesh, const FrameFieldParameters& p)
{
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  if (tetCount == 0)
  {
    return Status::Failure("The frame field needs a mesh with at least one tet.");
  }
  if (mesh.Cells.minCoeff() < 0 || mesh.Cells.maxCoeff() >= vertexCount)
  {
    return Status::Failure("A tet refers to a vertex that does not exist.");
  }
  if (!mesh.Vertices.allFinite())
  {
    return Status::Failure("The mesh has non-finite vertex coordinates.");
  }
  if (!(p.BoundaryAlignmentWeight > 0.0) || !(p.CutMeshBoundaryAlignmentWeight >= 0.0) ||
    !(p.AlignmentWeight >= 0.0) || !(p.NormalDifferenceWeight >= 0.0) ||
    !(p.NormalDifferenceMaxAngle >= 0.0 && p.NormalDifferenceMaxAngle <= 180.0) ||
    !(p.OrthogonalityWeight > 0.0) || !(p.L1Epsilon > 0.0) || !(p.GradientTolerance >= 0.0) ||
    p.MaxIterations < 0)
  {
    return Status::Failure(
      "Invalid frame field parameters: weights and epsilon must be positive "
      "(w_a, w_d and the cut-mesh alignment weight may be 0), the tolerance and iterations "
      "non-negative.");
  }
  return Status::Success();
}

// The topology and the cut faces.
Status CheckCuts(const TetMesh& mesh,
  const CutFaces& cuts,
  const TetTopology& topology,
  int& cutCount)
{
  const int tetCount = static_cast<int>(mesh.Cells.rows());
  if (topology.NonManifoldFaceCount > 0)
  {
    std::ostringstream message;
    message << "The mesh is not a manifold: " << topology.NonManifoldFaceCount
            << " faces are shared by more than two tets.";
    return Status::Failure(message.str());
  }
  cutCount = 0;
  const bool hasCuts = cuts.Ids.rows() > 0 || cuts.Sides.rows() > 0;
  if (!hasCuts)
  {
    return Status::Success();
  }
  if (cuts.Ids.rows() != tetCount || cuts.Sides.rows() != tetCount)
  {
    return Status::Failure("CutFaces must have one row per tet (or none for a mesh without cuts).");
  }
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      const int id = cuts.Ids(t, k);
      if (id < 0)
      {
        continue;
      }
      const int s = topology.Neighbors(t, k);
      std::ostringstream where;
      where << "Cut face " << k << " of tet " << t << " (cut " << id << ")";
      if (s < 0)
      {
        return Status::Failure(where.str() + " lies on the boundary.");
      }
      if (cuts.Sides(t, k) != -1 && cuts.Sides(t, k) != 1)
      {
        return Status::Failure(where.str() + " has a side other than -1 or +1.");
      }
      int l = 0;
      while (l < 4 && topology.Neighbors(s, l) != t)
      {
        ++l;
      }
      if (l == 4 || cuts.Ids(s, l) != id || cuts.Sides(s, l) != -cuts.Sides(t, k))
      {
        return Status::Failure(where.str() +
          " is not carried by the tet across it with the same id and the other side.");
      }
      cutCount = std::max(cutCount, id + 1);
    }
  }
  return Status::Success();
}

void StoreFrames(const std::vector<Eigen::Matrix3d>& frames,
  Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>& out)
{
  out.resize(static_cast<Eigen::Index>(frames.size()), 9);
  for (size_t t = 0; t < frames.size(); ++t)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        out(static_cast<Eigen::Index>(t), 3 * a + b) = frames[t](a, b);
      }
    }
  }
}

/// Steps 1-5 with the initial field's boundary alignment weight `initialWeight`.
Status ComputeFrameFieldOnce(const TetMesh& input,
  const CutFaces& cuts,
  const FrameFieldParameters& parameters,
  double initialWeight,
  FrameFieldResult& out,
  const Progress& progress)
{
  out = FrameFieldResult();
  out.InitialAlignmentWeight = initialWeight;
  // Work on a copy with a unit bounding-box diagonal (DESIGN.md "Scale"); rotations and the
  // relative measures need no mapping back.
  TetMesh mesh;
  mesh.Cells = input.Cells;
  mesh.Vertices = ToUnitDiagonal(ComputeUnitDiagonalFrame(input.Vertices), input.Vertices);
  const int tetCount = static_cast<int>(mesh.Cells.rows());

  Status status = CheckMesh(mesh, parameters);
  if (!status)
  {
    return status;
  }
  TetTopology topology;
  ComputeTetTopology(static_cast<int>(mesh.Vertices.rows()), mesh.Cells, topology);
  int cutCount = 0;
  status = CheckCuts(mesh, cuts, topology, cutCount);
  if (!status)
  {
    return status;
  }
  for (int t = 0; t < tetCount; ++t)
  {
    if (!(TetSignedVolume(mesh.Vertices, mesh.Cells, t) > 0.0))
    {
      std::ostringstream message;
      message << "Tet " << t << " has a non-positive volume; the frame field needs positively "
              << "oriented tets (VTK order).";
      return Status::Failure(message.str());
    }
  }
  const Tets noCuts;
  const Tets& faceCut = cutCount > 0 ? cuts.Ids : noCuts;
  const Tets& faceSide = cutCount > 0 ? cuts.Sides : noCuts;

  // 1. Initial field (§3.2).
  auto clock = std::chrono::steady_clock::now();
  std::vector<Eigen::Matrix3d> frames;
  OctahedralFieldParameters initial;
  initial.BoundaryAlignmentWeight = initialWeight;
  status =
    ComputeOctahedralField(mesh, topology, initial, frames, nullptr, Stage(progress, 0.0, 0.2));
  if (!status)
  {
    return status;
  }
  out.InitialFieldSeconds = Seconds(clock);

  // 2. Matching along a minimum spanning tree of the cut mesh's dual graph.
  clock = std::chrono::steady_clock::now();
  MatchFramesAlongSpanningTree(topology.Neighbors, faceCut, frames);
  StoreFrames(frames, out.InitialFrames);
  out.MatchingSeconds = Seconds(clock);
  if (!ReportProgress(progress, 0.25))
  {
    return Status::Failure("Aborted.");
  }

  // 3. Energy (1) by L-BFGS, then the rotation part of each matrix.
  clock = std::chrono::steady_clock::now();
  FrameFieldEnergyWeights weights;
  weights.Alignment = parameters.AlignmentWeight;
  weights.NormalDifference = parameters.NormalDifferenceWeight;
  weights.NormalDifferenceMaxAngle = parameters.NormalDifferenceMaxAngle;
  weights.Orthogonality = parameters.OrthogonalityWeight;
  weights.L1Epsilon = parameters.L1Epsilon;
  const FrameFieldEnergy energy(mesh, topology, faceCut, faceSide, weights);
  std::vector<double> x(static_cast<size_t>(energy.VariableCount()));
  for (int t = 0; t < tetCount; ++t)
  {
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(x.data() + 9 * t) = frames[t];
  }
  FrameFieldMinimization minimization;
  status = MinimizeFrameFieldEnergy(energy,
    x,
    parameters.GradientTolerance,
    parameters.MaxIterations,
    minimization,
    Stage(progress, 0.25, 0.9));
  if (!status)
  {
    return status;
  }
  std::vector<Eigen::Matrix3d> initialFrames = frames;
  for (int t = 0; t < tetCount; ++t)
  {
    const Eigen::Matrix3d m =
      Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(x.data() + 9 * t);
    Eigen::Vector3d sigma;
    PolarRotation(m, frames[t], sigma);
  }
  out.FrameEnergy = minimization.FinalEnergy;
  out.InitialFrameEnergy = minimization.InitialEnergy;
  out.FinalGradientNorm = minimization.FinalGradientNorm;
  out.FrameIterations = minimization.Iterations;
  out.Converged = minimization.Converged;
  out.SolverReport = minimization.Report;
  out.OptimizationSeconds = Seconds(clock);

  // 4. Transitions, eq. (6): per cut the cube rotation maximising
  // sum_f A_f trace(Pi R_minus R_plus^T).
  clock = std::chrono::steady_clock::now();
  std::vector<Eigen::Matrix3d> correlation(static_cast<size_t>(cutCount), Eigen::Matrix3d::Zero());
  for (int t = 0; t < tetCount && cutCount > 0; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (faceCut(t, k) < 0 || faceSide(t, k) != -1)
      {
        continue;
      }
      const int s = topology.Neighbors(t, k);
      const Eigen::Vector3d p0 = mesh.Vertices.row(mesh.Cells(t, TetFaceTable[k][0])).transpose();
      const Eigen::Vector3d p1 = mesh.Vertices.row(mesh.Cells(t, TetFaceTable[k][1])).transpose();
      const Eigen::Vector3d p2 = mesh.Vertices.row(mesh.Cells(t, TetFaceTable[k][2])).transpose();
      const double area = 0.5 * (p1 - p0).cross(p2 - p0).norm();
      correlation[faceCut(t, k)] += area * frames[t] * frames[s].transpose();
    }
  }
  out.CutTransitions.resize(cutCount, 9);
  for (int c = 0; c < cutCount; ++c)
  {
    const Eigen::Matrix3i& pi = CubeRotation(BestCubeRotationOfProduct(correlation[c]));
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        out.CutTransitions(c, 3 * a + b) = pi(a, b);
      }
    }
  }

  // 5. Measures.
  StoreFrames(frames, out.Frames);
  out.SingularEdges = FindSingularEdges(mesh, topology, frames);
  out.SingularEdgeCount = static_cast<int>(out.SingularEdges.size());
  for (const SingularEdge& edge : out.SingularEdges)
  {
    out.InteriorSingularEdgeCount += edge.Interior ? 1 : 0;
    out.MaxSingularEdgeDepth = std::max(out.MaxSingularEdgeDepth, edge.Depth);
  }
  out.InitialSingularEdgeCount =
    static_cast<int>(FindSingularEdges(mesh, topology, initialFrames).size());
  out.BoundaryAlignmentError = ComputeBoundaryAlignmentError(mesh, topology, frames);
  out.InitialBoundaryAlignmentError = ComputeBoundaryAlignmentError(mesh, topology, initialFrames);
  out.MeasureSeconds = Seconds(clock);
  ReportProgress(progress, 1.0);
  return Status::Success();
}

/// Whether the mesh has cut faces (CheckCuts validates them later).
bool HasCutFaces(const CutFaces& cuts)
{
  return cuts.Ids.rows() > 0 && (cuts.Ids.array() >= 0).any();
}
} // namespace

Status ComputeFrameField(const TetMesh& input,
  const CutFaces& cuts,
  const FrameFieldParameters& parameters,
  FrameFieldResult& out,
  const Progress& progress)
{
  // On a mesh with cuts the field may turn with the boundary around its handles, the cuts'
  // transitions taking up the turn, so it first starts from a tightly aligned initial field; the
  // paper's remedy (§6, Figure 13) when singular lines then stay inside is a smaller alignment
  // weight, BoundaryAlignmentWeight here.
  const bool aligned = parameters.CutMeshBoundaryAlignmentWeight > 0.0 && HasCutFaces(cuts);
  if (!aligned)
  {
    return ComputeFrameFieldOnce(
      input, cuts, parameters, parameters.BoundaryAlignmentWeight, out, progress);
  }
  auto clock = std::chrono::steady_clock::now();
  Status status = ComputeFrameFieldOnce(input,
    cuts,
    parameters,
    parameters.CutMeshBoundaryAlignmentWeight,
    out,
    Stage(progress, 0.0, 0.5));
  const double alignedSeconds = Seconds(clock);
  if (!status)
  {
    return status;
  }
  const int alignedSingularEdges = out.SingularEdgeCount;
  out.AlignedSingularEdgeCount = alignedSingularEdges;
  if (alignedSingularEdges == 0)
  {
    ReportProgress(progress, 1.0);
    return status;
  }
  clock = std::chrono::steady_clock::now();
  FrameFieldResult fallback;
  status = ComputeFrameFieldOnce(input,
    cuts,
    parameters,
    parameters.BoundaryAlignmentWeight,
    fallback,
    Stage(progress, 0.5, 1.0));
  if (!status)
  {
    return status;
  }
  if (fallback.SingularEdgeCount < alignedSingularEdges)
  {
    out = std::move(fallback);
    out.AlignedSingularEdgeCount = alignedSingularEdges;
    out.DiscardedSeconds = alignedSeconds;
  }
  else
  {
    out.DiscardedSeconds = Seconds(clock);
  }
  return Status::Success();
}

} // namespace polycubehex
