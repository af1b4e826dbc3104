#pragma once
// erpt's own settings: its chains' length and the two biased noise filters (defaults: mcmc/erpt.h).
#include "mcmc/erpt.h"
#include "render/settings.h"

namespace relt {

struct ErptIntegratorSettings final : SettingsOf<ErptIntegratorSettings> {
  int chainLength = ErptSettings{}.chainLength;
  int maxConsecutive = ErptSettings{}.maxConsecutive;
  bool proposalFilter = false;  // scale pixels by blurred / actual proposed mutations
};

// The chains' settings of an erpt render: chain length, step sizes and the consecutive-sample filter.
ErptSettings erptSettings(const RenderSettings& settings);

}  // namespace relt
