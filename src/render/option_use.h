#pragma once
// Which integrators use which render options: an option given to an integrator that does not use
// it is refused (one check over every option, mpi/main.cpp) rather than silently taken.
#include <optional>
#include <string>
#include <vector>

#include "render/settings.h"

namespace relt {

// Why `option` (its long name, "--chains") cannot be given to `integrator`, or nothing when the
// integrator uses it. Options not in the table are used by every integrator.
std::optional<std::string> unusedOptionReason(const std::string& option, Integrator integrator);

// The options of that table (every other option is used by every integrator).
std::vector<std::string> optionsNotForEveryIntegrator();

}  // namespace relt
