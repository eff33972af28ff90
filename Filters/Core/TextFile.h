// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "Status.h"

#include <string>

namespace polycubehex
{
/// Reads a whole file into `text`; fails with a message naming the path when it cannot.
Status ReadTextFile(const std::string& path, std::string& text);
} // namespace polycubehex
