#pragma once
// The options several integrators take but not all (the budget in samples or in mutations, the
// chain count, the Kelemen mutation's sizes, the direct-emission pass), and outputs only some write
// (relt's --trace): fields of RenderSettings, registered once here, named by each entry that takes
// them (integrator.h, sharedOptions).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "render/settings.h"

namespace relt {

void addSharedOptions(CLI::App& command, RenderSettings& settings);
// What the refusal of a shared option adds (pointing at the option to use instead), or null.
const char* sharedOptionHint(const std::string& option);
// Checks the shared options together (the smallest step below the largest); throws InputError.
void validateSharedOptions(const RenderSettings& settings);

// stats.json's settings of a Markov-chain integrator (pssmlt, mmlt, relt): its budget, the
// mutation's settings, snapshots and the direct-emission pass.
void addChainSettingsJson(const RenderSettings& settings, nlohmann::json& j);
// The direct-emission pass's --direct-emission-spp, when it is apart (pssmlt, relt, vcm, meb).
void addDirectSettingsJson(const RenderSettings& settings, nlohmann::json& j);
// The Kelemen sizes as given.
nlohmann::json smallStepJson(const RenderSettings& settings);

}  // namespace relt
