#pragma once
// The renderable scene: world-space triangles (instances flattened), materials, lights, cameras
// and render defaults. Produced by the glTF loader; consumed by the ray tracer and integrators.
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "material/material.h"

namespace relt {

struct Triangle {
  uint32_t v[3];      // indices into Scene::positions / Scene::normals
  uint32_t material;  // index into Scene::materials
};

struct PerspectiveCamera {
  std::string name;
  Vec3 position{0.0f};
  Mat3 toWorld{1.0f};           // columns: camera right (+x), up (+y), backward (+z); looks down -z
  float yfov = 0.8f;            // vertical field of view, radians
  std::optional<float> aspect;  // width / height from the file, if given
};

// KHR_lights_punctual point or spot light. Intensity in candela (W/sr in relt's units) times colour.
struct PunctualLight {
  std::string name;
  Vec3 position{0.0f};
  Vec3 direction{0.0f, 0.0f, -1.0f};  // spot axis (world)
  Color intensity{0.0f};
  bool spot = false;
  float cosInner = 1.0f, cosOuter = 0.0f;  // spot cone, cosines of the angles
};

// Limits of the render settings, from the scene or the command line.
inline constexpr int kMaxImageSide = 16384;
inline constexpr int kMaxDepth = 256;
// World-space coordinates (vertices after their transforms, cameras, lights) must lie within
// +-kMaxCoordinate: beyond it squared distances and the products of MIS weights overflow single
// precision (and Embree rejects rays whose origin exceeds 1.8e18).
inline constexpr double kMaxCoordinate = 1e15;

// Render settings a scene may carry in its scene-level `extras` (see README, "Scene format").
struct RenderDefaults {
  int width = 256;
  int height = 256;
  int maxDepth = 8;   // maximum number of path segments
  std::optional<int> benchWidth, benchHeight;
};

struct Scene {
  std::string file;  // where it was loaded from, for messages
  std::vector<Vec3> positions;
  // Per-vertex shading normals, same size as positions; a zero vector means the file gave none
  // for that vertex and the geometric normal is used.
  std::vector<Vec3> normals;
  std::vector<Triangle> triangles;
  std::vector<Material> materials;
  std::vector<PerspectiveCamera> cameras;
  std::vector<PunctualLight> punctualLights;
  RenderDefaults defaults;
  Bounds3 bounds;
  std::vector<std::string> warnings;  // one line each, printed once by the executable

  size_t emissiveTriangleCount() const;
  const PerspectiveCamera* findCamera(const std::string& name) const;  // nullptr if absent
};

}  // namespace relt
