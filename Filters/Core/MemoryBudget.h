// SPDX-License-Identifier: BSD-3-Clause
// Guard rails against inputs that would exhaust the machine's memory: a stage estimates what it
// needs before allocating and refuses with the estimate, instead of swapping the user's ParaView
// session to death or being killed halfway.
#pragma once

#include "Status.h"

#include <string>

namespace polycubehex
{

/// Physical memory of this machine in bytes (0 when the system does not say).
double PhysicalMemoryBytes();

/// Failure when `bytes` is more than 80 % of the physical memory: "<what> needs about X GB,
/// more than this machine's Y GB of memory; <advice>". Success when memory is unknown.
Status CheckMemoryEstimate(const std::string& what, double bytes, const std::string& advice);

} // namespace polycubehex
