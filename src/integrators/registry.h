#pragma once
// Every integrator relt has, one line each in registry.cpp; the executable and the tests find and
// configure integrators only through here. Which options an integrator takes follows from its
// entry: the shared ones it names and the ones its folder registers; any other option of the table
// given to it is refused by one check (unusedOptionReason).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "integrators/integrator.h"

namespace relt {

// The integrators in the order --help lists them.
const std::vector<const IntegratorEntry*>& integrators();
// The entry named `name`, or null.
const IntegratorEntry* findIntegrator(const std::string& name);
// Adds an integrator after the built-in ones (a test's toy integrator); a name taken already throws.
void registerIntegrator(const IntegratorEntry& entry);
// Every integrator's own settings while the command line is read: each option writes into its
// integrator's, and selectIntegrator keeps the chosen one's.
using SettingsDrafts = std::map<std::string, std::unique_ptr<IntegratorSettings>>;

// The settings' integrator set to the one named `name`, with its own settings from `drafts` (null:
// their defaults); throws std::invalid_argument if no integrator has that name.
void selectIntegrator(RenderSettings& settings, const std::string& name, SettingsDrafts* drafts = nullptr);

// The shared options, writing into `settings`, then every integrator's own, into its draft.
void addIntegratorOptions(CLI::App& command, RenderSettings& settings, SettingsDrafts& drafts);
// Why `option` (its long name) cannot be given to `integrator`, or nothing when it takes it.
// Options no integrator names or registers (--seed, --width, ...) are taken by every integrator.
std::optional<std::string> unusedOptionReason(const std::string& option, const IntegratorEntry& integrator);
// The options some integrators take and others do not.
std::vector<std::string> optionsNotForEveryIntegrator();
// The integrator's validation after the shared options' (Kelemen sizes, the direct pass's rays),
// once every given option was found to be one it takes; throws InputError.
void validateIntegratorOptions(RenderSettings& settings, const GivenOptions& given);

}  // namespace relt
