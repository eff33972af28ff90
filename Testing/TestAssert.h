// SPDX-License-Identifier: BSD-3-Clause
// A tiny assertion harness shared by the core and filter tests: each failed check prints
// where and why, and the test's main returns the number of failures (0 = pass).
#pragma once

#include <cmath>
#include <iostream>

namespace polycubehex_test
{
inline int& FailureCount()
{
  static int count = 0;
  return count;
}
} // namespace polycubehex_test

#define PCH_CHECK(condition)                                                                       \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl;     \
      ++polycubehex_test::FailureCount();                                                          \
    }                                                                                              \
  } while (false)

#define PCH_CHECK_NEAR(actual, expected, tolerance)                                                \
  do                                                                                               \
  {                                                                                                \
    const double pchActual = (actual);                                                             \
    const double pchExpected = (expected);                                                         \
    if (!(std::fabs(pchActual - pchExpected) <= (tolerance)))                                      \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": " #actual " = " << pchActual                 \
                << ", expected " << pchExpected << " +- " << (tolerance) << std::endl;            \
      ++polycubehex_test::FailureCount();                                                          \
    }                                                                                              \
  } while (false)

#define PCH_TEST_RESULT()                                                                          \
  (polycubehex_test::FailureCount() == 0                                                           \
      ? (std::cout << "all checks passed" << std::endl, 0)                                         \
      : (std::cerr << polycubehex_test::FailureCount() << " check(s) failed" << std::endl, 1))
