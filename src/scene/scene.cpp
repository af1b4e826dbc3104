#include "scene/scene.h"

namespace relt {

size_t Scene::emissiveTriangleCount() const {
  size_t n = 0;
  for (const Triangle& t : triangles)
    if (materials[t.material].isEmissive()) ++n;
  return n;
}

const PerspectiveCamera* Scene::findCamera(const std::string& name) const {
  for (const PerspectiveCamera& c : cameras)
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace relt
