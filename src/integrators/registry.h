#pragma once
// Every integrator relt has, one line each in registry.cpp; the executable and the tests find and
// configure integrators only through here. Which options an integrator takes follows from its
// entry: the shared ones it names and the ones its folder registers; any other option of the table
// given to it is refused by one check (unusedOptionReason).
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
// The settings' integrator set to the one named `name` (throws std::invalid_argument if none is).
void selectIntegrator(RenderSettings& settings, const std::string& name);

// The shared options, then every integrator's own, on the render command.
void addIntegratorOptions(CLI::App& command, RenderSettings& settings);
// Why `option` (its long name) cannot be given to `integrator`, or nothing when it takes it.
// Options no integrator names or registers (--seed, --width, ...) are taken by every integrator.
std::optional<std::string> unusedOptionReason(const std::string& option, const IntegratorEntry& integrator);
// The options some integrators take and others do not.
std::vector<std::string> optionsNotForEveryIntegrator();
// The integrator's validation after the shared options' (Kelemen sizes, the direct pass's rays),
// once every given option was found to be one it takes; throws InputError.
void validateIntegratorOptions(RenderSettings& settings, const GivenOptions& given);

}  // namespace relt
