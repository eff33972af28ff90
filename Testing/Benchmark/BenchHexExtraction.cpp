// SPDX-License-Identifier: BSD-3-Clause
// Times extractHexMesh on a saved polycube and prints the wall seconds per stage (median of the
// runs) and the quality, so that the hex stage can be tuned without re-running the deformation.
// Not run by CTest.
//
//   BenchHexExtraction polycube.bin [hexes = 20000] [runs = 3]
//
// polycube.bin: int32 #V, int32 #T, then #V by 3 float64 original positions, #V by 3 float64
// polycube positions, #T by 4 int32 tets, #T by 4 int32 PolycubeLabels (all row-major).
#include "HexExtraction.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

using namespace polycubehex;

namespace
{
double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

template<class Matrix>
bool ReadRows(std::ifstream& file, Matrix& m, Eigen::Index rows)
{
  m.resize(rows, m.cols());
  Eigen::Matrix<typename Matrix::Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> raw(
    rows, m.cols());
  file.read(reinterpret_cast<char*>(raw.data()),
    static_cast<std::streamsize>(raw.size() * sizeof(typename Matrix::Scalar)));
  m = raw;
  return static_cast<bool>(file);
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: BenchHexExtraction polycube.bin [hexes] [runs]\n");
    return 2;
  }
  std::ifstream file(argv[1], std::ios::binary);
  int counts[2] = { 0, 0 };
  file.read(reinterpret_cast<char*>(counts), sizeof(counts));
  PolycubeTetMesh input;
  input.OriginalVertices.resize(counts[0], 3);
  input.PolycubeVertices.resize(counts[0], 3);
  input.Cells.resize(counts[1], 4);
  input.FaceLabels.resize(counts[1], 4);
  if (!file || !ReadRows(file, input.OriginalVertices, counts[0]) ||
    !ReadRows(file, input.PolycubeVertices, counts[0]) || !ReadRows(file, input.Cells, counts[1]) ||
    !ReadRows(file, input.FaceLabels, counts[1]))
  {
    std::fprintf(stderr, "cannot read %s\n", argv[1]);
    return 1;
  }
  HexExtractionParameters params;
  params.TargetHexCount = argc > 2 ? std::atoi(argv[2]) : 20000;
  const int runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;

  std::vector<double> rounding, extraction, padding, untangling, smoothing, measures, total;
  HexExtractionResult result;
  for (int run = 0; run < runs; ++run)
  {
    const Status status = extractHexMesh(input, params, result);
    if (!status)
    {
      std::fprintf(stderr, "%s\n", status.Message().c_str());
      return 1;
    }
    rounding.push_back(result.RoundingSeconds);
    extraction.push_back(result.ExtractionSeconds);
    padding.push_back(result.PaddingSeconds);
    untangling.push_back(result.UntanglingSeconds);
    smoothing.push_back(result.SmoothingSeconds);
    measures.push_back(result.MeasuresSeconds);
    const double sum = result.RoundingSeconds + result.ExtractionSeconds + result.PaddingSeconds +
      result.UntanglingSeconds + result.SmoothingSeconds + result.MeasuresSeconds;
    total.push_back(sum);
    std::printf("run %d: rounding %.2f extraction %.2f padding %.2f untangling %.2f smoothing %.2f "
                "measures %.2f total %.2f\n",
      run,
      result.RoundingSeconds,
      result.ExtractionSeconds,
      result.PaddingSeconds,
      result.UntanglingSeconds,
      result.SmoothingSeconds,
      result.MeasuresSeconds,
      sum);
  }
  std::printf("median: rounding %.2f extraction %.2f padding %.2f untangling %.2f smoothing %.2f "
              "measures %.2f total %.2f\n",
    Median(rounding),
    Median(extraction),
    Median(padding),
    Median(untangling),
    Median(smoothing),
    Median(measures),
    Median(total));
  std::printf("hexes %d (padding %d), SJ min %.6f mean %.6f (raw %.6f %.6f, untangled %.6f %.6f, "
              "%d inverted, %d rounds, %d iterations, %d released), "
              "inverted %d, sweeps %d, rounding attempts %d, best-effort inverted tets %d\n",
    result.HexCount,
    result.PaddingHexCount,
    result.ScaledJacobianMin,
    result.ScaledJacobianMean,
    result.ScaledJacobianMinBeforeSmoothing,
    result.ScaledJacobianMeanBeforeSmoothing,
    result.ScaledJacobianMinAfterUntangling,
    result.ScaledJacobianMeanAfterUntangling,
    result.InvertedHexCountAfterUntangling,
    result.UntanglingRounds,
    result.UntanglingIterations,
    result.ReleasedBoundaryVertexCount,
    result.InvertedHexCount,
    result.SmoothingSweeps,
    result.RoundingAttempts,
    result.RoundingInvertedTetCount);
  // A checksum of the mesh's bits, to tell whether a change altered the result.
  std::uint64_t hash = 1469598103934665603ull;
  auto mix = [&hash](const void* data, size_t bytes)
  {
    for (size_t i = 0; i < bytes; ++i)
    {
      hash = (hash ^ static_cast<const unsigned char*>(data)[i]) * 1099511628211ull;
    }
  };
  mix(result.Mesh.Vertices.data(), sizeof(double) * result.Mesh.Vertices.size());
  mix(result.Mesh.Cells.data(), sizeof(int) * result.Mesh.Cells.size());
  std::printf("checksum %016llx\n", static_cast<unsigned long long>(hash));
  return 0;
}
