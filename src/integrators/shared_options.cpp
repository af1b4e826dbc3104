#include "integrators/shared_options.h"

#include <map>

#include "core/error.h"
#include "schedule/schedule.h"

namespace relt {

void addSharedOptions(CLI::App& cmd, RenderSettings& r) {
  cmd.add_option("--spp", r.spp, "pt, bdpt, erpt, vcm, meb: samples per pixel (vcm, meb: iterations; default " + std::to_string(kDefaultSpp) + ")")
      ->check(CLI::Range(1, 1 << 24));
  cmd.add_option("--mutations-per-pixel", r.mutationsPerPixel,
                 "Markov-chain integrators: mutations per pixel (default " +
                     CLI::detail::to_string(kDefaultMutationsPerPixel) + ")")
      ->check(CLI::Range(1e-3, 1e6));
  cmd.add_option("--chains", r.chains, "pssmlt, mmlt: number of chains (independent of the rank count)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd.add_option("--large-step-probability", r.largeStepProbability, "pssmlt, mmlt, relt: probability of a large step")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd.add_option("--small-step-min", r.smallStepMin, "pssmlt, mmlt, erpt, relt: Kelemen small step, smallest size s1")
      ->check(CLI::Range(1e-7, 0.5))
      ->capture_default_str();
  cmd.add_option("--small-step-max", r.smallStepMax, "pssmlt, mmlt, erpt, relt: Kelemen small step, largest size s2")
      ->check(CLI::Range(1e-7, 0.5))
      ->capture_default_str();
  cmd.add_option_function<std::string>(
         "--direct-emission-spp",
         [&r](const std::string& text) { r.directSpp = text == "auto" ? kDirectSppAuto : std::stoi(text); },
         "pssmlt, relt, vcm, meb: estimate the emission seen directly or through specular surfaces only apart "
         "with N camera rays per pixel (a shifted (0,2)-sequence: powers of two are best) and leave the rest to the "
         "integrator (0: it does it all; auto: about 6 % of the budget, or 2 x mutations or samples per pixel "
         "rounded to a power of two, none when no such emission is in view)")
      ->check(CLI::IsMember({"auto"}) | CLI::Range(0, kDirectMaxSpp))
      ->default_str("auto");
  cmd.add_option("--trace", r.trace,
                 "relt: write every rank's stepping time of each group round (the scaling model's input) as JSON");
}

const char* sharedOptionHint(const std::string& option) {
  static const std::map<std::string, const char*> hints = {
      {"--spp", "pssmlt, mmlt and relt take --mutations-per-pixel"},
      {"--mutations-per-pixel", "the others take --spp"},
      {"--chains", "relt's chains are ladders x levels: --ladders, --levels"},
  };
  const auto it = hints.find(option);
  return it == hints.end() ? nullptr : it->second;
}

void validateSharedOptions(const RenderSettings& s) {
  if (s.smallStepMin >= s.smallStepMax)
    throw InputError("", "--small-step-min", "must be smaller than --small-step-max");
}

nlohmann::json smallStepJson(const RenderSettings& s) {
  return {shortestDecimal(s.smallStepMin), shortestDecimal(s.smallStepMax)};
}

void addChainSettingsJson(const RenderSettings& s, nlohmann::json& j) {
  if (!s.seconds) j["mutations_per_pixel"] = s.mutationsPerPixel.value_or(kDefaultMutationsPerPixel);  // a timed render has no such count
  j["large_step_probability"] = shortestDecimal(s.largeStepProbability);
  j["small_step"] = smallStepJson(s);
  if (s.snapshotEvery > 0.0) j["snapshot_every"] = s.snapshotEvery;
  addDirectSettingsJson(s, j);
}

void addDirectSettingsJson(const RenderSettings& s, nlohmann::json& j) {
  if (directEmissionApart(s))
    j["direct_emission_spp"] = s.directSpp == kDirectSppAuto ? nlohmann::json("auto") : nlohmann::json(s.directSpp);
}

}  // namespace relt
