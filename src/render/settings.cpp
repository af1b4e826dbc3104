#include "render/settings.h"

#include <charconv>

namespace relt {

double shortestDecimal(float v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  double out = v;
  std::from_chars(text, end, out);
  return out;
}

nlohmann::json RenderSettings::toJson() const {
  nlohmann::json j;
  j["scene"] = scenePath;
  j["output"] = output;
  if (!png.empty()) j["png"] = png;
  j["integrator"] = integrator.name;
  if (spp) j["spp"] = *spp;
  if (seconds) j["time"] = *seconds;
  j["width"] = width;
  j["height"] = height;
  j["max_depth"] = maxDepth;
  j["seed"] = seed;
  j["camera"] = camera;
  j["exposure"] = shortestDecimal(exposure);
  j["mis"] = misHeuristicName(heuristic);
  j["threads"] = threads;
  if (integrator.settingsJson) integrator.settingsJson(*this, j);
  return j;
}

}  // namespace relt
