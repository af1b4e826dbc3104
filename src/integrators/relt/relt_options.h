#pragma once
// relt's own options (the ladder's family and levels, the exchanges, where chains live), their
// checks and its settings in stats.json.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "integrators/integrator.h"

namespace relt {

void addReltOptions(CLI::App& command, IntegratorSettings& own);
// Family options belong to their family; kitaoka's four levels are fixed; permutation's cost
// bounds its levels; the levels' layers need an EXR. Throws InputError.
void validateReltOptions(RenderSettings& settings, const GivenOptions& given);
void addReltSettingsJson(const RenderSettings& settings, nlohmann::json& j);

}  // namespace relt
