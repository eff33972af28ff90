// SPDX-License-Identifier: BSD-3-Clause
// Small helpers every filter uses to attach its arrays (private to the module).
#ifndef PolycubeHexArrays_h
#define PolycubeHexArrays_h

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

namespace polycubehex
{

/// A named array of `tuples` tuples with `components` components (values not set).
template<typename ArrayType>
vtkSmartPointer<ArrayType> NewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// Adds (or replaces) the one-value field array `name`.
template<typename ArrayType, typename Value>
void SetFieldValue(vtkFieldData* fields, const char* name, Value value)
{
  vtkNew<ArrayType> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
}

} // namespace polycubehex

#endif
