#pragma once
// What `relt info` prints about a loaded scene, and the check that a scene can be rendered at all.
#include <string>

#include "scene/scene.h"

namespace relt {

// Several lines: triangles, materials by kind, emitters, lights, cameras, bounds, render defaults
// and the loader's warnings.
std::string summarizeScene(const Scene& scene);

// Throws InputError(scene.file, "scene", ...) when the scene has no camera or nothing that emits
// light (an emissive triangle of nonzero area or a punctual light of nonzero intensity).
void checkRenderable(const Scene& scene);

}  // namespace relt
