// SPDX-License-Identifier: BSD-3-Clause
#include "HexResolution.h"

#include <algorithm>
#include <cmath>

namespace polycubehex
{

double ComputeLatticeScale(double polycubeVolume,
  double polycubeArea,
  double inputVolume,
  int targetHexCount,
  double targetEdgeLength,
  bool padding)
{
  if (!(polycubeVolume > 0.0))
  {
    return 0.0;
  }
  if (targetEdgeLength > 0.0)
  {
    return inputVolume > 0.0 ? std::cbrt(inputVolume / polycubeVolume) / targetEdgeLength : 0.0;
  }
  if (targetHexCount <= 0)
  {
    return 0.0;
  }
  const double count = static_cast<double>(targetHexCount);
  double s = std::cbrt(count / polycubeVolume);
  if (!padding || !(polycubeArea > 0.0))
  {
    return s;
  }
  // f(s) = V s^3 + A s^2 - N is increasing and convex for s > 0 and f(cbrt(N/V)) > 0, so
  // Newton from there decreases monotonically to the root.
  for (int iteration = 0; iteration < 100; ++iteration)
  {
    const double f = polycubeVolume * s * s * s + polycubeArea * s * s - count;
    const double df = 3.0 * polycubeVolume * s * s + 2.0 * polycubeArea * s;
    const double step = f / df;
    s -= step;
    if (std::fabs(step) <= 1e-14 * s)
    {
      break;
    }
  }
  return std::max(s, 0.0);
}

} // namespace polycubehex
