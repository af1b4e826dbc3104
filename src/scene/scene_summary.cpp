#include "scene/scene_summary.h"

#include <cstdio>

#include "core/error.h"

namespace relt {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string vec(const Vec3& v) {
  std::string s;  // appended: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&
  return s.append("(").append(num(v.x)).append(", ").append(num(v.y)).append(", ").append(num(v.z)).append(")");
}

bool hasArea(const Scene& scene, const Triangle& t) {
  const Vec3& p0 = scene.positions[t.v[0]];
  const float twiceArea = glm::length(glm::cross(scene.positions[t.v[1]] - p0, scene.positions[t.v[2]] - p0));
  return twiceArea > 0.0f;
}

}  // namespace

std::string summarizeScene(const Scene& scene) {
  size_t lambert = 0, conductor = 0, dielectric = 0, emissive = 0;
  for (const Material& m : scene.materials) {
    lambert += m.kind == MaterialKind::Lambert;
    conductor += m.kind == MaterialKind::Conductor;
    dielectric += m.kind == MaterialKind::Dielectric;
    emissive += m.isEmissive();
  }
  size_t spots = 0;
  for (const PunctualLight& l : scene.punctualLights) spots += l.spot;

  std::string s = "scene: " + scene.file + "\n";
  s += "triangles: " + std::to_string(scene.triangles.size()) + " (emissive " +
       std::to_string(scene.emissiveTriangleCount()) + "), vertices: " + std::to_string(scene.positions.size()) + "\n";
  s += "materials: " + std::to_string(scene.materials.size()) + " (lambert " + std::to_string(lambert) +
       ", conductor " + std::to_string(conductor) + ", dielectric " + std::to_string(dielectric) + "; emissive " +
       std::to_string(emissive) + ")\n";
  s += "punctual lights: " + std::to_string(scene.punctualLights.size()) + " (point " +
       std::to_string(scene.punctualLights.size() - spots) + ", spot " + std::to_string(spots) + ")\n";
  s += "cameras: " + std::to_string(scene.cameras.size()) + "\n";
  for (const PerspectiveCamera& c : scene.cameras) {
    s += "  \"" + c.name + "\": yfov " + num(c.yfov * 180.0 / kPi) + " deg, aspect " +
         (c.aspect ? num(*c.aspect) : std::string("from the image")) + ", position " + vec(c.position) + "\n";
  }
  s += "bounds: " +
       (scene.bounds.empty() ? std::string("empty") : vec(scene.bounds.lo) + " to " + vec(scene.bounds.hi)) + "\n";
  const RenderDefaults& d = scene.defaults;
  s += "render defaults: " + std::to_string(d.width) + "x" + std::to_string(d.height) + ", max depth " +
       std::to_string(d.maxDepth);
  if (d.benchWidth || d.benchHeight)
    s += ", bench " + std::to_string(d.benchWidth.value_or(d.width)) + "x" +
         std::to_string(d.benchHeight.value_or(d.height));
  s += "\n";
  s += "warnings: " + std::to_string(scene.warnings.size()) + "\n";
  for (const std::string& w : scene.warnings) s += "  " + w + "\n";
  return s;
}

void checkRenderable(const Scene& scene) {
  if (scene.cameras.empty()) throw InputError(scene.file, "scene", "no camera: add a node with a perspective camera");
  bool emitter = false;
  for (const PunctualLight& l : scene.punctualLights) emitter = emitter || !isBlack(l.intensity);
  for (size_t i = 0; i < scene.triangles.size() && !emitter; ++i) {
    const Triangle& t = scene.triangles[i];
    emitter = scene.materials[t.material].isEmissive() && hasArea(scene, t);
  }
  // Radiance far above any physical source overflows single precision once multiplied by path
  // throughputs: such a scene would render as dropped (infinite) samples.
  constexpr float kMaxEmission = 1e15f;
  for (size_t m = 0; m < scene.materials.size(); ++m)
    if (maxComponent(scene.materials[m].emission) > kMaxEmission)
      throw InputError(scene.file, "materials[" + std::to_string(m) + "] '" + scene.materials[m].name + "'",
                       "emitted radiance (emissiveFactor x emissive strength) above 1e15 would overflow single "
                       "precision; scale the scene's light units down");
  for (const PunctualLight& l : scene.punctualLights)
    if (maxComponent(l.intensity) > kMaxEmission)
      throw InputError(scene.file, "light '" + l.name + "'",
                       "intensity above 1e15 would overflow single precision; scale the scene's light units down");
  if (!emitter)
    throw InputError(
        scene.file, "scene",
        "no emitter, so the image would be black: add an emissive material or a KHR_lights_punctual light");
}

}  // namespace relt
