#pragma once
// glTF materials -> relt materials (DESIGN §5): metallic-roughness conductor or Lambert,
// KHR_materials_transmission (+ _ior) dielectric, emission from emissiveFactor x
// KHR_materials_emissive_strength.
#include <vector>

#include "material/material.h"
#include "scene/gltf_json.h"

namespace relt::gltf {

// Every entry of the top-level `materials` array, in file order; validates all of them.
std::vector<Material> parseMaterials(Context& ctx, const Json& doc);

// Used by primitives without a material index.
Material defaultMaterial();

}  // namespace relt::gltf
