// SPDX-License-Identifier: BSD-3-Clause
// Captures the error messages an algorithm reports, so tests can assert what the user is told.
#pragma once

#include <vtkCommand.h>
#include <vtkObject.h>

#include <string>

class ErrorCapture : public vtkCommand
{
public:
  static ErrorCapture* New() { return new ErrorCapture; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    if (callData)
    {
      this->Messages += static_cast<const char*>(callData);
      this->Messages += "\n";
    }
  }
  bool Mentions(const std::string& words) const
  {
    return this->Messages.find(words) != std::string::npos;
  }
  void Clear() { this->Messages.clear(); }
  std::string Messages;

  /// Observes errors and warnings of `object` (they are then not printed by VTK).
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
};
