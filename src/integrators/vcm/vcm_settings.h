#pragma once
// vcm's own settings: which techniques, and the merging radius and its shrinking (defaults:
// vcm/vcm_renderer.h).
#include "render/settings.h"
#include "vcm/vcm_renderer.h"

namespace relt {

struct VcmIntegratorSettings final : SettingsOf<VcmIntegratorSettings> {
  VcmSettings vcm;
};

}  // namespace relt
