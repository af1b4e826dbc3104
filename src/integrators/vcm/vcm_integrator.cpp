// vcm: vertex connection and merging, every bidirectional technique and photon merging under one
// MIS (src/vcm).
#include "integrators/vcm/vcm_integrator.h"

#include "integrators/shared_options.h"
#include "integrators/vcm/vcm_render.h"
#include "integrators/vcm/vcm_settings.h"

namespace relt {
namespace {

void addVcmOptions(CLI::App& cmd, IntegratorSettings& own) {
  VcmSettings& v = dynamic_cast<VcmIntegratorSettings&>(own).vcm;
  cmd.add_option_function<std::string>(
         "--vcm-mode", [&v](const std::string& name) { v.mode = *parseVcmMode(name); },
         "vcm: techniques (vcm: all; bpt: connections only, bdpt's estimator; ppm: merging only, progressive "
         "photon mapping)")
      ->check(CLI::IsMember({"vcm", "bpt", "ppm"}))
      ->default_str(vcmModeName(v.mode));
  cmd.add_option("--vcm-radius", v.radius,
                 "vcm: the first iteration's merging radius in pixel footprints (the width a pixel covers at the "
                 "median distance of what the camera sees)")
      ->check(CLI::Range(1e-3, 1e4))
      ->capture_default_str();
  cmd.add_option("--vcm-alpha", v.alpha, "vcm: the radius of iteration i is r_1 i^((alpha - 1) / 2)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
}

void addVcmSettingsJson(const RenderSettings& s, nlohmann::json& j) {
  const VcmSettings& v = s.own.get<VcmIntegratorSettings>().vcm;
  addDirectSettingsJson(s, j);
  j["vcm_mode"] = vcmModeName(v.mode);
  if (v.mode != VcmMode::Bpt) {
    j["vcm_radius"] = v.radius;
    j["vcm_alpha"] = v.alpha;
  }
}

}  // namespace

const IntegratorEntry& vcmIntegrator() {
  static const IntegratorEntry entry = [] {
    IntegratorEntry e;
    e.kind.name = "vcm";
    e.kind.directEmissionApart = true;
    e.kind.settingsJson = addVcmSettingsJson;
    e.summary = "vertex connection and merging";
    e.sharedOptions = {"--spp", "--direct-emission-spp"};
    e.makeSettings = makeSettingsOf<VcmIntegratorSettings>;
    e.addOptions = addVcmOptions;
    e.render = renderVcm;
    return e;
  }();
  return entry;
}

}  // namespace relt
