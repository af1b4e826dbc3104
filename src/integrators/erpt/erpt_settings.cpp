#include "integrators/erpt/erpt_settings.h"

namespace relt {

ErptSettings erptSettings(const RenderSettings& settings) {
  const auto& own = settings.own.get<ErptIntegratorSettings>();
  ErptSettings es;
  es.chainLength = own.chainLength;
  es.sizes = KelemenSizes{settings.smallStepMin, settings.smallStepMax};
  es.maxConsecutive = own.maxConsecutive;
  return es;
}

}  // namespace relt
