#pragma once
// glTF 2.0 (.gltf and .glb) -> Scene, with validation. Any problem is one InputError naming the
// file, the element (e.g. "meshes[2].primitives[0]") and the reason.
#include <string>

#include "scene/scene.h"

namespace relt {

Scene loadGltf(const std::string& path);

}  // namespace relt
