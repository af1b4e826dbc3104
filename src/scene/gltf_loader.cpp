// glTF 2.0 -> Scene. The JSON is read with nlohmann_json and the buffers are decoded here rather
// than by tinygltf 2.7: that version rejects valid files (an indices accessor without a
// bufferView), reports malformed data URIs as missing files, and reads buffers before we could
// refuse an unsupported required extension. Everything is validated before it is used; the order
// of the checks (JSON structure, then buffer I/O, then data) lets a bad file fail fast and by name.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <regex>
#include <set>

#include "core/memory.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_container.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_nodes.h"

namespace relt {

namespace {

using namespace gltf;

// Extensions relt implements completely, so a file may require them.
const std::set<std::string> kSupportedExtensions = {"KHR_materials_emissive_strength", "KHR_materials_ior",
                                                    "KHR_materials_transmission", "KHR_lights_punctual"};

// What the commonly required extensions do, for a more helpful refusal.
const std::map<std::string, std::string> kExtensionPurpose = {
    {"KHR_draco_mesh_compression", "Draco-compressed meshes"},
    {"EXT_meshopt_compression", "meshopt-compressed buffers"},
    {"KHR_mesh_quantization", "quantized vertex attributes"},
    {"KHR_texture_basisu", "Basis Universal textures"},
    {"EXT_texture_webp", "WebP textures"},
    {"KHR_texture_transform", "texture transforms"},
    {"KHR_materials_pbrSpecularGlossiness", "the specular-glossiness material model"},
    {"KHR_materials_unlit", "unlit materials"},
    {"KHR_materials_volume", "volumetric materials"},
    {"EXT_mesh_gpu_instancing", "GPU instancing"},
};

const char* kModeNames[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                            "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
constexpr uint32_t kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;

void checkAsset(const Context& ctx, const Json& doc) {
  const Json* asset = getObject(ctx, doc, "asset", "");
  if (!asset) ctx.fail("asset", "is missing (every glTF file has an asset object with a version)");
  const std::optional<std::string> version = getString(ctx, *asset, "version", "asset");
  if (!version) ctx.fail("asset.version", "is missing");
  static const std::regex kVersion("([0-9]+)\\.([0-9]+)");
  std::smatch m;
  if (!std::regex_match(*version, m, kVersion))
    ctx.fail("asset.version", brief(Json(*version)) + " is not a valid glTF version (expected \"2.0\")");
  if (m[1] == "1") ctx.fail("asset.version", "glTF " + *version + " is not supported: convert the file to glTF 2.0");
  if (m[1] != "2") ctx.fail("asset.version", "glTF " + *version + " is not supported (relt reads glTF 2.x)");
  if (const std::optional<std::string> minVersion = getString(ctx, *asset, "minVersion", "asset")) {
    if (!std::regex_match(*minVersion, m, kVersion))
      ctx.fail("asset.minVersion", brief(Json(*minVersion)) + " is not a valid glTF version");
    if (m[1] != "2" || m[2] != "0")
      ctx.fail("asset.minVersion", "the file needs glTF " + *minVersion + " features; relt reads glTF 2.0");
  }
}

std::vector<std::string> stringList(const Context& ctx, const Json& doc, const char* key) {
  std::vector<std::string> out;
  if (const Json* list = getArray(ctx, doc, key, ""))
    for (size_t i = 0; i < list->size(); ++i) {
      if (!(*list)[i].is_string()) ctx.fail(indexed(key, i), "must be a string, got " + brief((*list)[i]));
      out.push_back((*list)[i].get<std::string>());
    }
  return out;
}

// Runs before any buffer is read, so an unsupported required extension (e.g. Draco, whose data
// would not decode anyway) is reported by name rather than as a confusing buffer error.
void checkExtensions(Context& ctx, const Json& doc) {
  for (const std::string& name : stringList(ctx, doc, "extensionsRequired")) {
    if (kSupportedExtensions.count(name)) continue;
    auto purpose = kExtensionPurpose.find(name);
    ctx.fail("extensionsRequired", printable(name) +
                                       (purpose != kExtensionPurpose.end() ? " (" + purpose->second + ")" : "") +
                                       " is not supported");
  }
  for (const std::string& name : stringList(ctx, doc, "extensionsUsed"))
    if (!kSupportedExtensions.count(name)) ctx.warn("extension " + printable(name) + " is not supported; ignored");
}

// A primitive as declared, before any data is read.
struct PrimitiveDecl {
  std::optional<uint32_t> position, normal, indices, material;
  std::optional<uint32_t> anyAttribute;  // all attributes have one count: the vertex count
  uint32_t mode = kTriangles;
};

std::vector<std::vector<PrimitiveDecl>> parseMeshes(Context& ctx, const Json& doc, size_t accessorCount,
                                                    size_t materialCount) {
  std::vector<std::vector<PrimitiveDecl>> meshes(arraySize(ctx, doc, "meshes"));
  for (size_t m = 0; m < meshes.size(); ++m) {
    const std::string me = indexed("meshes", m);
    const Json& mesh = arrayObject(ctx, doc, "meshes", m);
    const Json* primitives = getArray(ctx, mesh, "primitives", me);
    if (!primitives || primitives->empty()) ctx.fail(me, "has no primitives");
    for (size_t p = 0; p < primitives->size(); ++p) {
      const std::string pe = me + "." + indexed("primitives", p);
      const Json& prim = (*primitives)[p];
      PrimitiveDecl d;
      const Json* attributes = getObject(ctx, prim, "attributes", pe);
      if (!attributes) ctx.fail(pe, "attributes is missing");
      // Points and lines are valid glTF that a renderer of surfaces cannot draw: not drawn.
      const uint64_t mode = getUInt(ctx, prim, "mode", pe).value_or(kTriangles);
      if (mode > kTriangleFan) ctx.fail(pe, "mode " + std::to_string(mode) + " is not a valid primitive mode");
      if (mode < kTriangles)
        ctx.warn(std::string("primitives of mode ") + kModeNames[mode] + " are not drawn (relt renders triangles)");
      d.mode = static_cast<uint32_t>(mode);
      d.indices = getIndex(ctx, prim, "indices", pe, "accessors", accessorCount);
      d.material = getIndex(ctx, prim, "material", pe, "materials", materialCount);
      for (auto it = attributes->begin(); it != attributes->end(); ++it) {
        const uint32_t a =
            indexValue(ctx, it.value(), pe, "attributes." + printable(it.key()), "accessors", accessorCount);
        if (!d.anyAttribute) d.anyAttribute = a;
        if (it.key() == "POSITION") d.position = a;
        if (it.key() == "NORMAL") d.normal = a;
      }
      if (const Json* targets = getArray(ctx, prim, "targets", pe)) {
        for (size_t t = 0; t < targets->size(); ++t) {
          const std::string te = pe + "." + indexed("targets", t);
          const Json& target = (*targets)[t];
          if (!target.is_object()) ctx.fail(te, "must be a JSON object, got " + brief(target));
          for (auto it = target.begin(); it != target.end(); ++it)
            indexValue(ctx, it.value(), te, printable(it.key()), "accessors", accessorCount);
        }
        if (!targets->empty()) ctx.warn("morph targets are ignored; meshes keep their base shape");
      }
      meshes[m].push_back(d);
    }
  }
  return meshes;
}

struct CameraDecl {
  std::string name;
  bool perspective = true;
  bool known = true;  // false: a type glTF 2.0 does not define, skipped with a warning
  double yfov = 0.0;
  std::optional<double> aspect;
};

std::vector<CameraDecl> parseCameras(Context& ctx, const Json& doc) {
  std::vector<CameraDecl> cameras(arraySize(ctx, doc, "cameras"));
  for (size_t i = 0; i < cameras.size(); ++i) {
    const std::string element = indexed("cameras", i);
    const Json& o = arrayObject(ctx, doc, "cameras", i);
    CameraDecl& c = cameras[i];
    c.name = getString(ctx, o, "name", element).value_or("");
    const std::string type = getString(ctx, o, "type", element).value_or("");
    if (type == "perspective") {
      const Json* p = getObject(ctx, o, "perspective", element);
      if (!p) ctx.fail(element, "perspective is missing");
      const std::string pe = element + ".perspective";
      if (!getMember(ctx, *p, "yfov", pe)) ctx.fail(pe, "yfov is missing");
      c.yfov = getNumber(ctx, *p, "yfov", pe, 0.0, 0.0, kPi);
      if (!(c.yfov > 0.0 && c.yfov < kPi))
        ctx.fail(pe, "yfov " + brief(Json(c.yfov)) + " must lie strictly between 0 and pi");
      if (getMember(ctx, *p, "aspectRatio", pe)) {
        c.aspect = getNumber(ctx, *p, "aspectRatio", pe, 1.0, 0.0, INFINITY);
        if (!(*c.aspect > 0.0)) ctx.fail(pe, "aspectRatio must be positive");
      }
      const double znear = getNumber(ctx, *p, "znear", pe, 1e-3, 0.0, INFINITY);
      if (getMember(ctx, *p, "zfar", pe) && !(getNumber(ctx, *p, "zfar", pe, 0.0, 0.0, INFINITY) > znear))
        ctx.fail(pe, "zfar must be larger than znear");
    } else if (type == "orthographic") {
      if (!getObject(ctx, o, "orthographic", element)) ctx.fail(element, "orthographic is missing");
      c.perspective = false;
    } else if (getMember(ctx, o, "type", element)) {
      // An enum value outside the list is only a warning for the validator (later versions or
      // extensions may add values), so the camera is skipped rather than the file refused.
      ctx.warn(element + " has type " + brief(Json(type)) + ", which glTF 2.0 does not define: skipped");
      c.perspective = false;
      c.known = false;
    } else {
      ctx.fail(element, "type is missing (\"perspective\" or \"orthographic\")");
    }
  }
  return cameras;
}

struct LightDecl {
  std::string name;
  std::string type;
  Color intensity{0.0f};
  double inner = 0.0, outer = kPi / 4;
};

const std::string kLightsElement = "extensions.KHR_lights_punctual.lights";

const Json* lightList(const Context& ctx, const Json& doc) {
  const Json* ext = getObject(ctx, doc, "extensions", "");
  const Json* lp = ext ? getObject(ctx, *ext, "KHR_lights_punctual", "extensions") : nullptr;
  return lp ? getArray(ctx, *lp, "lights", "extensions.KHR_lights_punctual") : nullptr;
}

std::vector<LightDecl> parseLights(Context& ctx, const Json& doc) {
  std::vector<LightDecl> lights;
  const Json* list = lightList(ctx, doc);
  if (!list) return lights;
  for (size_t i = 0; i < list->size(); ++i) {
    const std::string element = indexed(kLightsElement, i);
    const Json& o = (*list)[i];
    LightDecl l;
    l.name = getString(ctx, o, "name", element).value_or("");
    const std::optional<std::string> type = getString(ctx, o, "type", element);
    if (!type) ctx.fail(element, "type is missing (\"point\", \"spot\" or \"directional\")");
    l.type = *type;
    if (l.type != "point" && l.type != "spot" && l.type != "directional")  // as for cameras: skipped
      ctx.warn(element + " has type " + brief(Json(l.type)) + ", which KHR_lights_punctual does not define: skipped");
    const std::vector<double> color = getNumbers(ctx, o, "color", element, 3, {1, 1, 1}, 0.0, 1.0);
    const double intensity = getNumber(ctx, o, "intensity", element, 1.0, 0.0, INFINITY);
    l.intensity = Color(float(color[0]), float(color[1]), float(color[2])) * float(intensity);
    if (getMember(ctx, o, "range", element) && !(getNumber(ctx, o, "range", element, 1.0, 0.0, INFINITY) > 0.0))
      ctx.fail(element, "range must be positive");
    if (l.type == "spot") {
      const Json* spot = getObject(ctx, o, "spot", element);
      if (!spot) ctx.fail(element, "spot is missing for a spot light");
      l.inner = getNumber(ctx, *spot, "innerConeAngle", element + ".spot", 0.0, -INFINITY, INFINITY);
      l.outer = getNumber(ctx, *spot, "outerConeAngle", element + ".spot", kPi / 4, -INFINITY, INFINITY);
      if (!(l.inner >= 0.0 && l.inner < l.outer && l.outer <= kPi / 2))
        ctx.fail(element + ".spot", "cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2, got " +
                                        brief(Json(l.inner)) + " and " + brief(Json(l.outer)));
    }
    lights.push_back(l);
  }
  return lights;
}

void parseRenderDefaults(const Context& ctx, const SceneChoice& choice, RenderDefaults* defaults) {
  if (!choice.scene) return;
  const Json* extras = getMember(ctx, *choice.scene, "extras", choice.element);
  if (!extras || !extras->is_object()) return;  // extras are free-form in glTF
  const std::string element = choice.element + ".extras";
  auto positive = [&](const char* key, uint64_t limit) -> std::optional<int> {
    const Json* v = getMember(ctx, *extras, key, element);
    if (!v) return std::nullopt;
    const bool ok = (v->is_number_unsigned() && v->get<uint64_t>() >= 1 && v->get<uint64_t>() <= limit);
    if (!ok)
      ctx.fail(element, std::string(key) + " must be an integer from 1 to " + std::to_string(limit) + ", got " + brief(*v));
    return static_cast<int>(v->get<uint64_t>());
  };
  if (auto v = positive("width", kMaxImageSide)) defaults->width = *v;
  if (auto v = positive("height", kMaxImageSide)) defaults->height = *v;
  if (auto v = positive("max_depth", kMaxDepth)) defaults->maxDepth = *v;
  if (auto v = positive("bench_width", kMaxImageSide)) defaults->benchWidth = *v;
  if (auto v = positive("bench_height", kMaxImageSide)) defaults->benchHeight = *v;
}

// Mesh data in the mesh's own space, triangulated and validated.
struct LocalPrimitive {
  std::vector<Vec3> positions, normals;  // normals empty when the file gives none
  std::vector<uint32_t> triangles;       // 3 indices per triangle, counter-clockwise = front
  std::optional<uint32_t> material;
};

// Shading normals, unit length or zero (Scene::normals: "use the geometric normal").
std::vector<Vec3> readNormals(Context& ctx, const AccessorReader& reader, uint32_t accessor, const std::string& element) {
  std::vector<Vec3> normals = reader.readVec3(accessor, element, "NORMAL");
  for (size_t v = 0; v < normals.size(); ++v) {
    // NaN or infinite normals are corrupt data (the validator's ACCESSOR_INVALID_FLOAT), not a
    // direction to fall back from.
    if (!isFinite(normals[v]))
      ctx.fail(element, "NORMAL (" + indexed("accessors", accessor) + ") has a non-finite value at vertex " +
                            std::to_string(v));
    const float len = glm::length(normals[v]);
    // The validator's tolerance (unitLengthThresholdVec3); relt renormalises either way.
    if (!(std::abs(len - 1.0f) <= 0.00674f))
      ctx.warn("NORMAL vectors that are not of unit length are renormalised (zero ones: the geometric normal)");
    normals[v] = (std::isfinite(len) && len > 0.0f) ? normals[v] / len : Vec3(0.0f);
  }
  return normals;
}

// Vertex indices, checked against the vertex count.
std::vector<uint32_t> readIndices(const Context& ctx, const AccessorReader& reader, uint32_t accessor,
                                  size_t vertexCount, const std::string& element) {
  std::vector<uint32_t> indices = reader.readIndices(accessor, element);
  const uint32_t restart = reader.restartValue(accessor);
  for (size_t i = 0; i < indices.size(); ++i) {
    // glTF 2.0 §3.7.2.1: indices MUST NOT hold the primitive restart value, which a GPU with
    // restart enabled would read as a break in the primitive.
    if (indices[i] == restart)
      ctx.fail(element, "index " + std::to_string(restart) + " at position " + std::to_string(i) + " of " +
                            indexed("accessors", accessor) +
                            " is the primitive restart value of its component type, which glTF forbids");
    if (indices[i] >= vertexCount)
      ctx.fail(element, "index " + std::to_string(indices[i]) + " at position " + std::to_string(i) + " of " +
                            indexed("accessors", accessor) + " is out of range: POSITION has " +
                            std::to_string(vertexCount) + " vertices");
  }
  return indices;
}

// Triangles from the mode's vertex order; strip and fan orders follow glTF 2.0 §3.7.2.1 so that
// winding, hence the front face, is kept.
std::vector<uint32_t> triangulate(Context& ctx, uint32_t mode, std::vector<uint32_t> indices) {
  const size_t n = indices.size();
  std::vector<uint32_t> triangles;
  if (mode == kTriangles) {
    // The validator only warns (MESH_PRIMITIVE_INCOMPATIBLE_MODE); a GPU draws the whole triangles.
    if (n % 3 != 0) ctx.warn("TRIANGLES primitives whose vertex count is not a multiple of 3: the last 1 or 2 are not drawn");
    indices.resize(n - n % 3);
    triangles = std::move(indices);
  } else if (mode == kTriangleStrip) {
    for (size_t i = 0; i + 2 < n; ++i)
      triangles.insert(triangles.end(), {indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]});
  } else if (mode == kTriangleFan) {
    for (size_t i = 0; i + 2 < n; ++i) triangles.insert(triangles.end(), {indices[i + 1], indices[i + 2], indices[0]});
  }
  return triangles;  // points and lines: none (warned)
}

// A primitive that is not drawn (no POSITION, points, lines) has its data checked all the same,
// as a mesh that no node uses has.
LocalPrimitive readPrimitive(Context& ctx, const AccessorReader& reader, const PrimitiveDecl& d,
                             const std::string& element) {
  LocalPrimitive out;
  out.material = d.material;
  // Without POSITION the other attributes give the vertex count (none: no vertices), as for the
  // validator, so that indices are checked all the same.
  size_t vertexCount = d.anyAttribute ? reader.count(*d.anyAttribute) : 0;
  if (d.position) {
    out.positions = reader.readVec3(*d.position, element, "POSITION");
    for (size_t v = 0; v < out.positions.size(); ++v)
      if (!isFinite(out.positions[v]))
        ctx.fail(element, "POSITION (" + indexed("accessors", *d.position) + ") has a non-finite value at vertex " +
                              std::to_string(v));
    vertexCount = out.positions.size();
    if (vertexCount > UINT32_MAX) ctx.fail(element, "has too many vertices");
  }
  if (d.normal) {
    out.normals = readNormals(ctx, reader, *d.normal, element);
    if (out.normals.size() != vertexCount)
      ctx.fail(element, "NORMAL has " + std::to_string(out.normals.size()) + " entries but " +
                            (d.position ? "POSITION" : "its first attribute") + " has " + std::to_string(vertexCount));
  }
  std::vector<uint32_t> indices;
  if (d.indices) {
    indices = readIndices(ctx, reader, *d.indices, vertexCount, element);
  } else {
    indices.resize(vertexCount);
    std::iota(indices.begin(), indices.end(), 0u);
  }
  if (!d.position) return LocalPrimitive{{}, {}, {}, d.material};  // not drawn (warned)
  out.triangles = triangulate(ctx, d.mode, std::move(indices));
  return out;
}

// Places one primitive in the world. Normals go through the cofactor matrix, which equals
// det * inverse-transpose and stays defined for singular transforms; with det < 0 the winding is
// flipped so that the front face stays the front face.
// A world-space position as a Vec3, or a failure naming `what` ("vertex 3", "its camera") when it
// lies beyond +-kMaxCoordinate.
Vec3 worldPosition(const Context& ctx, const glm::dvec3& p, const std::string& element, const std::string& what) {
  if (!(std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate && std::abs(p.z) <= kMaxCoordinate)) {
    char point[96];
    std::snprintf(point, sizeof point, "(%.4g, %.4g, %.4g)", p.x, p.y, p.z);
    ctx.fail(element, what + " lies at " + point + " in world space, beyond +-1e15, where single-precision " +
                          "distances overflow (rescale the scene, e.g. with a root node scale)");
  }
  return Vec3(p);
}

void instancePrimitive(const Context& ctx, const LocalPrimitive& prim, const glm::dmat4& world, uint32_t material,
                       const std::string& element, Scene* scene) {
  const glm::dmat3 a(world);
  const double det = glm::determinant(a);
  glm::dmat3 cofactor(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
  if (det < 0.0) cofactor = -cofactor;
  const bool flip = det < 0.0;

  const size_t base = scene->positions.size();
  if (base + prim.positions.size() > UINT32_MAX) ctx.fail(element, "the scene has too many vertices after instancing");
  for (size_t v = 0; v < prim.positions.size(); ++v) {
    const glm::dvec3 p = glm::dvec3(world * glm::dvec4(glm::dvec3(prim.positions[v]), 1.0));
    if (!isFinite(Vec3(p))) ctx.fail(element, "its world transform moves vertices to infinity");
    scene->positions.push_back(worldPosition(ctx, p, element, "vertex " + std::to_string(v)));
    Vec3 n(0.0f);
    if (!prim.normals.empty() && prim.normals[v] != Vec3(0.0f)) {
      const glm::dvec3 t = cofactor * glm::dvec3(prim.normals[v]);
      const double len = glm::length(t);
      if (std::isfinite(len) && len > 0.0) n = Vec3(t / len);
    }
    scene->normals.push_back(n);
  }
  for (size_t t = 0; t + 2 < prim.triangles.size(); t += 3) {
    Triangle tri;
    tri.v[0] = static_cast<uint32_t>(base + prim.triangles[t]);
    tri.v[1] = static_cast<uint32_t>(base + prim.triangles[t + (flip ? 2 : 1)]);
    tri.v[2] = static_cast<uint32_t>(base + prim.triangles[t + (flip ? 1 : 2)]);
    tri.material = material;
    const Vec3& p0 = scene->positions[tri.v[0]];
    const float twiceArea = glm::length(glm::cross(scene->positions[tri.v[1]] - p0, scene->positions[tri.v[2]] - p0));
    if (!(twiceArea > 0.0f) || !std::isfinite(twiceArea)) continue;  // degenerate: nothing to hit
    scene->triangles.push_back(tri);
    for (uint32_t k : tri.v) scene->bounds.extend(scene->positions[k]);
  }
}

// Rigid frame of a node (columns right, up, backward), its scale removed.
std::optional<Mat3> rigidFrame(const glm::dmat4& world) {
  const glm::dvec3 x(world[0]), z(world[2]);
  if (!(glm::length(z) > 1e-12)) return std::nullopt;
  const glm::dvec3 back = glm::normalize(z);
  const glm::dvec3 r = x - glm::dot(x, back) * back;
  if (!(glm::length(r) > 1e-12)) return std::nullopt;
  const glm::dvec3 right = glm::normalize(r);
  const glm::dvec3 up = glm::cross(back, right);
  return Mat3(Vec3(right), Vec3(up), Vec3(back));
}

std::string uniqueName(std::string name, const std::set<std::string>& taken) {
  if (!taken.count(name)) return name;
  for (int k = 2;; ++k)
    if (!taken.count(name + "." + std::to_string(k))) return name + "." + std::to_string(k);
}

// Instancing multiplies triangles: refuses a scene that cannot fit before it is built.
void checkInstancesFit(Context& ctx, const std::vector<Node>& nodes, const std::vector<PlacedNode>& placedNodes,
                       const std::vector<std::vector<LocalPrimitive>>& localMeshes) {
  uint64_t instancedTriangles = 0;
  for (const PlacedNode& placed : placedNodes)
    if (nodes[placed.node].mesh)
      for (const LocalPrimitive& prim : localMeshes[*nodes[placed.node].mesh]) instancedTriangles += prim.triangles.size() / 3;
  const uint64_t memory = physicalMemoryBytes();
  if (instancedTriangles > UINT32_MAX || !fitsInMemory(double(instancedTriangles) * kBytesPerTriangle, memory))
    ctx.fail("nodes", "the scene instances " + std::to_string(instancedTriangles) + " triangles, about " +
                          formatGiB(double(instancedTriangles) * kBytesPerTriangle) + " once loaded, more than fits in " +
                          formatGiB(double(memory)) + " of memory");
}

// A node's camera into the scene: perspective ones only, named uniquely.
void placeCamera(Context& ctx, const CameraDecl& decl, size_t index, const Node& node, const PlacedNode& placed,
                 std::set<std::string>& cameraNames, Scene& scene) {
  if (!decl.known) return;  // warned where the camera was read
  if (!decl.perspective) {
    ctx.warn(indexed("cameras", index) + " is orthographic: skipped (relt renders perspective cameras)");
    return;
  }
  const std::string element = indexed("nodes", placed.node);
  const std::optional<Mat3> frame = rigidFrame(placed.world);
  if (!frame) ctx.fail(element, "the camera's transform is degenerate (zero scale)");
  PerspectiveCamera cam;
  const std::string base = !decl.name.empty()   ? decl.name
                           : !node.name.empty() ? node.name
                                                : "camera" + std::to_string(scene.cameras.size());
  cam.name = uniqueName(base, cameraNames);
  cameraNames.insert(cam.name);
  cam.position = worldPosition(ctx, glm::dvec3(placed.world[3]), element, "its camera");
  cam.toWorld = *frame;
  cam.yfov = static_cast<float>(decl.yfov);
  if (decl.aspect) cam.aspect = static_cast<float>(*decl.aspect);
  scene.cameras.push_back(cam);
}

// A node's point or spot light into the scene (directional ones are not supported yet).
void placeLight(Context& ctx, const LightDecl& decl, const Node& node, const PlacedNode& placed, Scene& scene) {
  if (decl.type == "directional") {
    ctx.warn("directional lights are not supported yet; ignored");
    return;
  }
  if (decl.type != "point" && decl.type != "spot") return;
  const std::string element = indexed("nodes", placed.node);
  PunctualLight light;
  light.name = !decl.name.empty()   ? decl.name
               : !node.name.empty() ? node.name
                                    : "light" + std::to_string(scene.punctualLights.size());
  light.position = worldPosition(ctx, glm::dvec3(placed.world[3]), element, "its light");
  light.intensity = decl.intensity;
  if (decl.type == "spot") {
    const glm::dvec3 axis = -glm::dvec3(placed.world[2]);  // lights shine down their local -Z
    if (!(glm::length(axis) > 1e-12)) ctx.fail(element, "the spot light's transform is degenerate (zero scale)");
    light.direction = Vec3(glm::normalize(axis));
    light.spot = true;
    light.cosInner = static_cast<float>(std::cos(decl.inner));
    light.cosOuter = static_cast<float>(std::cos(decl.outer));
  }
  scene.punctualLights.push_back(light);
}

}  // namespace

Scene loadGltf(const std::string& path) {
  Context ctx(path);
  GltfSource src = readGltfSource(ctx, path);
  const Json& doc = src.doc;
  checkAsset(ctx, doc);
  checkExtensions(ctx, doc);

  // JSON structure, top-down, before any buffer is read.
  const size_t accessorCount = arraySize(ctx, doc, "accessors");
  std::vector<Material> materials = parseMaterials(ctx, doc);
  const std::vector<std::vector<PrimitiveDecl>> meshes = parseMeshes(ctx, doc, accessorCount, materials.size());
  const BufferLayout layout = parseBufferLayout(ctx, doc);
  // glTF 2.0 §3.7.2.1: a primitive without positions is valid and SHOULD not be drawn.
  for (size_t m = 0; m < meshes.size(); ++m)
    for (size_t p = 0; p < meshes[m].size(); ++p)
      if (!meshes[m][p].position) ctx.warn("mesh primitives without POSITION are not drawn");
  const std::vector<CameraDecl> cameras = parseCameras(ctx, doc);
  const std::vector<LightDecl> lights = parseLights(ctx, doc);
  NodeCounts counts;
  counts.meshes = meshes.size();
  counts.cameras = cameras.size();
  counts.lights = lights.size();
  counts.skins = arraySize(ctx, doc, "skins");
  const std::vector<Node> nodes = parseNodes(ctx, doc, counts);
  const SceneChoice choice = chooseScene(ctx, doc, nodes);
  Scene scene;
  scene.file = path;
  parseRenderDefaults(ctx, choice, &scene.defaults);
  if (arraySize(ctx, doc, "animations") > 0) ctx.warn("animations are ignored; the scene is rendered at rest");

  // Buffer data, then every mesh (instanced or not), so that bad data is reported for any mesh.
  std::vector<std::vector<uint8_t>> buffers(layout.buffers.size());
  for (size_t b = 0; b < buffers.size(); ++b)
    buffers[b] = loadBufferBytes(ctx, src, b, layout.buffers[b].uri, layout.buffers[b].byteLength);
  const AccessorReader reader(ctx, layout, buffers);
  std::vector<std::vector<LocalPrimitive>> localMeshes(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m)
    for (size_t p = 0; p < meshes[m].size(); ++p)
      localMeshes[m].push_back(
          readPrimitive(ctx, reader, meshes[m][p], indexed("meshes", m) + "." + indexed("primitives", p)));
  buffers.clear();

  const std::vector<PlacedNode> placedNodes = placeNodes(nodes, choice.roots);
  checkInstancesFit(ctx, nodes, placedNodes, localMeshes);

  scene.materials = std::move(materials);
  std::optional<uint32_t> defaultIndex;
  std::set<std::string> cameraNames;
  for (const PlacedNode& placed : placedNodes) {
    const Node& node = nodes[placed.node];
    const std::string element = indexed("nodes", placed.node);
    if (node.mesh) {
      for (const LocalPrimitive& prim : localMeshes[*node.mesh]) {
        uint32_t material;
        if (prim.material) {
          material = *prim.material;
        } else {
          if (!defaultIndex) {
            defaultIndex = static_cast<uint32_t>(scene.materials.size());
            scene.materials.push_back(defaultMaterial());
          }
          material = *defaultIndex;
        }
        instancePrimitive(ctx, prim, placed.world, material, element, &scene);
      }
    }
    if (node.camera) placeCamera(ctx, cameras[*node.camera], *node.camera, node, placed, cameraNames, scene);
    if (node.light) placeLight(ctx, lights[*node.light], node, placed, scene);
  }
  scene.warnings = ctx.takeWarnings();
  return scene;
}

}  // namespace relt
