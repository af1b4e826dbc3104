// meb: Metropolised bidirectional estimators (thesis chapter 6): vcm's techniques, the light
// subpaths drawn by a visibility chain and a contribution chain coupled by replica exchange (src/meb).
#include "integrators/meb/meb_integrator.h"

#include "integrators/shared_options.h"
#include "integrators/meb/meb_render.h"
#include "integrators/meb/meb_settings.h"

namespace relt {
namespace {

void addMebOptions(CLI::App& cmd, IntegratorSettings& own) {
  MebSettings& m = dynamic_cast<MebIntegratorSettings&>(own).meb;
  cmd.add_option("--meb-pairs", m.pairs, "meb: chain pairs per iteration (each draws an equal share of its light subpaths)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd.add_option("--meb-initial-paths", m.initialPaths,
                 "meb: independent light subpaths per iteration that start the chains and the normalisers (0: 10000, "
                 "or one per pixel if fewer)")
      ->check(CLI::Range(0, 1 << 24))
      ->capture_default_str();
  cmd.add_option("--meb-large-step", m.largeStepProbability, "meb: the visibility chain's large step probability")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd.add_option("--meb-radius", m.vcm.radius, "meb: the first iteration's merging radius in pixel footprints (as vcm's)")
      ->check(CLI::Range(1e-3, 1e4))
      ->capture_default_str();
  cmd.add_option("--meb-alpha", m.vcm.alpha, "meb: the radius of iteration i is r_1 i^((alpha - 1) / 2)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
}

void addMebSettingsJson(const RenderSettings& s, nlohmann::json& j) {
  const MebSettings& m = s.own.get<MebIntegratorSettings>().meb;
  addDirectSettingsJson(s, j);
  j["meb_pairs"] = m.pairs;
  j["meb_initial_paths"] = m.initialPaths;
  j["meb_large_step"] = m.largeStepProbability;
  j["meb_radius"] = m.vcm.radius;
  j["meb_alpha"] = m.vcm.alpha;
}

}  // namespace

const IntegratorEntry& mebIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "meb";
    e.kind.directEmissionApart = true;
    e.kind.settingsJson = addMebSettingsJson;
    e.summary = "Metropolised bidirectional estimators: vcm with light subpaths from a visibility and a contribution chain";
    e.sharedOptions = {"--spp", "--direct-emission-spp"};
    e.makeSettings = makeSettingsOf<MebIntegratorSettings>;
    e.addOptions = addMebOptions;
    e.render = renderMeb;
    return e;
  }();
  return entry;
}

}  // namespace relt
