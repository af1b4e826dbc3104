#pragma once
// What an integrator is to the rest of relt: a name and traits (render/settings.h, IntegratorKind),
// its own settings (render/own_settings.h) and the command-line options that write them, their
// validation, and a render from a loaded scene to the written outputs. Each integrator's folder
// defines one IntegratorEntry; registry.cpp lists them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "checkpoint/checkpoint_io.h"
#include "core/clock.h"
#include "parallel/job.h"
#include "render/renderer.h"
#include "render/settings.h"

namespace relt {

// What a render hands its integrator: the scene ready on this rank, the settings with the scene's
// defaults filled in, the checkpoint plan, and the checkpoint it continues (if any).
struct RenderContext {
  Job& job;
  Renderer& renderer;
  const RenderSettings& settings;
  CheckpointPlan& plan;
  std::optional<Resumed>& resumed;
  Clock::time_point wallStart;  // the render's start, loading included (stats.json's wall_seconds)
};

// The options of the render command the user gave, by long name ("--levels").
using GivenOptions = std::vector<std::string>;

struct IntegratorEntry {
  IntegratorKind kind;
  const char* summary = "";  // one line for --help
  // The options shared by several integrators (shared_options.h) that this one takes.
  std::vector<std::string> sharedOptions;
  // Its own settings with their defaults (or none: then it has no options of its own), and the
  // options only it takes, registered to write into `own` (one of its makeSettings()).
  std::unique_ptr<IntegratorSettings> (*makeSettings)() = nullptr;
  void (*addOptions)(CLI::App& command, IntegratorSettings& own) = nullptr;
  // Completes and checks the settings after parsing; throws InputError (or none).
  void (*validate)(RenderSettings& settings, const GivenOptions& given) = nullptr;
  // Renders and, on the root, writes the outputs; collective over the job.
  void (*render)(RenderContext& context) = nullptr;
};

// An entry's makeSettings for settings of type T.
template <class T>
std::unique_ptr<IntegratorSettings> makeSettingsOf() {
  return std::make_unique<T>();
}

}  // namespace relt
