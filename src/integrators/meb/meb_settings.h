#pragma once
// meb's own settings: chain pairs, the initial set, the large steps and vcm's merging radius
// (defaults: meb/meb_renderer.h).
#include "meb/meb_renderer.h"
#include "render/settings.h"

namespace relt {

struct MebIntegratorSettings final : SettingsOf<MebIntegratorSettings> {
  MebSettings meb;
};

}  // namespace relt
