// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>
#include <utility>

namespace polycubehex
{

/// The outcome of a core algorithm: success, or a failure with a message a user can act on.
class Status
{
public:
  static Status Success() { return Status(true, std::string()); }
  static Status Failure(std::string message) { return Status(false, std::move(message)); }

  bool Ok() const { return this->IsOk; }
  explicit operator bool() const { return this->IsOk; }
  const std::string& Message() const { return this->Text; }

private:
  Status(bool ok, std::string text)
    : IsOk(ok)
    , Text(std::move(text))
  {
  }
  bool IsOk;
  std::string Text;
};

/// Progress callback handed to every long core algorithm. It receives the fraction done in
/// [0, 1] and returns false when the caller wants the algorithm to stop (abort).
using Progress = std::function<bool(double)>;

/// Calls `progress` if it is set; returns false when the caller asked to abort.
inline bool ReportProgress(const Progress& progress, double fraction)
{
  return !progress || progress(fraction);
}

/// `whole`'s progress over [from, from + width] as a progress over [0, 1], for one step of a
/// longer run. With `refused`, a refusal (abort) is remembered there, so that the caller can
/// tell an aborted step from a failed one.
inline Progress ProgressPart(const Progress& whole,
  double from,
  double width,
  bool* refused = nullptr)
{
  return [whole, from, width, refused](double f)
  {
    const bool go = ReportProgress(whole, from + width * f);
    if (!go && refused)
    {
      *refused = true;
    }
    return go;
  };
}

} // namespace polycubehex
