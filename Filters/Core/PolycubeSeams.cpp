// SPDX-License-Identifier: BSD-3-Clause
#include "PolycubeSeams.h"

#include "TopologyAdjacency.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace polycubehex
{
namespace
{
/// The three input points of a face, sorted: the key two copies of one face share.
using FaceKey = std::array<std::array<double, 3>, 3>;

FaceKey KeyOf(const Points& original, const std::array<int, 3>& face)
{
  FaceKey key;
  for (int i = 0; i < 3; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      key[i][a] = original(face[i], a);
    }
  }
  std::sort(key.begin(), key.end());
  return key;
}
} // namespace

Status FindPolycubeSeams(const Points& original,
  const Points& polycube,
  const Tets& cells,
  const Tets& faceLabels,
  const std::vector<Eigen::Matrix3i>& rotations,
  const std::vector<Eigen::Vector3d>& translations,
  PolycubeSeams& seams)
{
  const int tetCount = static_cast<int>(cells.rows());
  seams = PolycubeSeams();
  seams.Neighbor.setConstant(tetCount, 4, -1);
  seams.Cut.setConstant(tetCount, 4, -1);
  seams.Side.setZero(tetCount, 4);
  seams.Rotations = rotations;
  seams.Translations = translations;
  if (rotations.size() != translations.size())
  {
    return Status::Failure("the cuts have " + std::to_string(rotations.size()) +
      " transitions but " + std::to_string(translations.size()) + " translations");
  }
  if (faceLabels.rows() != tetCount || polycube.rows() != original.rows())
  {
    return Status::Failure("the seams need one label row per tet and two positions per vertex");
  }
  TetAdjacency adjacency;
  Status status = BuildTetAdjacency(static_cast<int>(original.rows()), cells, adjacency);
  if (!status)
  {
    return status;
  }

  // 1. Unlabelled boundary faces, paired by their input points.
  std::map<FaceKey, std::vector<std::array<int, 2>>> byPoints;
  for (int t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (adjacency.Neighbor(t, k) < 0 && faceLabels(t, k) < 0)
      {
        const std::array<int, 3> face = { cells(t, TetFaceTable[k][0]),
          cells(t, TetFaceTable[k][1]),
          cells(t, TetFaceTable[k][2]) };
        byPoints[KeyOf(original, face)].push_back({ t, k });
      }
    }
  }
  if (!byPoints.empty() && rotations.empty())
  {
    return Status::Failure(std::to_string(byPoints.size()) +
      " boundary faces have no polycube label and there is no cut (CutTransitions) to explain "
      "them");
  }

  // 2. Each pair: the cut and direction whose transition maps one side onto the other.
  const double size =
    std::max(1e-300, (polycube.colwise().maxCoeff() - polycube.colwise().minCoeff()).norm());
  const double tolerance = 1e-6 * size;
  std::set<std::array<int, 3>> copies;
  for (const auto& entry : byPoints)
  {
    const std::vector<std::array<int, 2>>& faces = entry.second;
    if (faces.size() != 2)
    {
      std::ostringstream message;
      message << "a boundary face without polycube label (tet " << faces[0][0] << ", face "
              << faces[0][1] << ") is not a cut face: " << faces.size() - 1
              << " other faces lie on its input points (a cut face has exactly one)";
      return Status::Failure(message.str());
    }
    const int t = faces[0][0];
    const int n = faces[1][0];
    // Vertex i of t's face and its copy in n's face.
    std::array<std::array<int, 2>, 3> pairs;
    for (int i = 0; i < 3; ++i)
    {
      const int v = cells(t, TetFaceTable[faces[0][1]][i]);
      pairs[i] = { v, -1 };
      for (int j = 0; j < 3; ++j)
      {
        const int w = cells(n, TetFaceTable[faces[1][1]][j]);
        if (original.row(w) == original.row(v))
        {
          pairs[i][1] = w;
        }
      }
    }
    double best = std::numeric_limits<double>::max();
    int bestCut = -1;
    int bestSide = 0;
    for (int c = 0; c < static_cast<int>(rotations.size()); ++c)
    {
      const Eigen::Matrix3d pi = rotations[static_cast<size_t>(c)].cast<double>();
      for (int side : { -1, 1 })
      {
        double residual = 0.0;
        for (const auto& pair : pairs)
        {
          const Eigen::Vector3d from = polycube.row(pair[0]).transpose();
          const Eigen::Vector3d to = polycube.row(pair[1]).transpose();
          // t on the minus side: to = Pi from + t_c; on the plus side: from = Pi to + t_c.
          const Eigen::Vector3d gap = side < 0
            ? Eigen::Vector3d(to - pi * from - translations[static_cast<size_t>(c)])
            : Eigen::Vector3d(from - pi * to - translations[static_cast<size_t>(c)]);
          residual = std::max(residual, gap.cwiseAbs().maxCoeff());
        }
        if (residual < best)
        {
          best = residual;
          bestCut = c;
          bestSide = side;
        }
      }
    }
    if (!(best <= tolerance))
    {
      std::ostringstream message;
      message << "the cut face of tet " << t << " and its copy in tet " << n
              << " are not related by any cut's transition (closest off by " << best / size
              << " of the polycube's size); the polycube does not satisfy its cut transitions";
      return Status::Failure(message.str());
    }
    seams.Neighbor(t, faces[0][1]) = n;
    seams.Neighbor(n, faces[1][1]) = t;
    seams.Cut(t, faces[0][1]) = bestCut;
    seams.Cut(n, faces[1][1]) = bestCut;
    seams.Side(t, faces[0][1]) = bestSide;
    seams.Side(n, faces[1][1]) = -bestSide;
    for (const auto& pair : pairs)
    {
      copies.insert(bestSide < 0 ? std::array<int, 3>{ pair[0], pair[1], bestCut }
                                 : std::array<int, 3>{ pair[1], pair[0], bestCut });
    }
  }
  for (const auto& copy : copies)
  {
    seams.Copies.push_back({ copy[0], copy[1], copy[2] });
  }
  return Status::Success();
}

} // namespace polycubehex
