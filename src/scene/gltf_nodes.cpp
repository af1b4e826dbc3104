#include "scene/gltf_nodes.h"

#include <algorithm>

#include <glm/gtc/quaternion.hpp>

namespace relt::gltf {

namespace {

// glTF 2.0 requires a unit rotation quaternion. The validator's tolerance on its length is the
// largest error of signed 8-bit quantization (glTF-Validator, unitLengthThresholdVec4); within it
// the rotation is renormalised, beyond it no reading of the file is the author's.
constexpr double kUnitQuaternionTolerance = 0.00769;

// The validator's NODE_MATRIX_NON_TRS: glTF requires a matrix that is translation * rotation *
// scale. relt would draw a projective or sheared matrix as given, other renderers decompose it, so
// no image is the author's. Columns must be orthogonal (relative tolerance) and nonzero.
bool decomposableToTrs(const glm::dmat4& m) {
  if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) return false;
  const glm::dvec3 c[3] = {glm::dvec3(m[0]), glm::dvec3(m[1]), glm::dvec3(m[2])};
  for (int i = 0; i < 3; ++i) {
    if (!(glm::length(c[i]) > 0.0)) return false;
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(glm::dot(c[i], c[j])) > 1e-4 * glm::length(c[i]) * glm::length(c[j])) return false;
  }
  return true;
}

glm::dmat4 localTransform(const Context& ctx, const Json& o, const std::string& element) {
  const bool hasTrs = getMember(ctx, o, "translation", element) || getMember(ctx, o, "rotation", element) ||
                      getMember(ctx, o, "scale", element);
  if (getMember(ctx, o, "matrix", element)) {
    if (hasTrs) ctx.fail(element, "has both matrix and translation/rotation/scale (glTF allows one or the other)");
    const std::vector<double> v = getNumbers(ctx, o, "matrix", element, 16, {});
    glm::dmat4 m(1.0);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = v[size_t(c * 4 + r)];  // glTF matrices are column-major
    if (!decomposableToTrs(m))
      ctx.fail(element, "matrix " + brief(Json(v)) + " is not a translation, rotation and scale (glTF requires one)");
    return m;
  }
  const std::vector<double> t = getNumbers(ctx, o, "translation", element, 3, {0, 0, 0});
  const std::vector<double> q = getNumbers(ctx, o, "rotation", element, 4, {0, 0, 0, 1});
  const std::vector<double> s = getNumbers(ctx, o, "scale", element, 3, {1, 1, 1});
  glm::dquat rotation(q[3], q[0], q[1], q[2]);  // glTF stores x, y, z, w; glm takes w first
  const double norm = glm::length(rotation);
  if (!(std::abs(norm - 1.0) <= kUnitQuaternionTolerance))
    ctx.fail(element, "rotation " + brief(Json(q)) + " is not a unit quaternion (length " + brief(Json(norm)) + ")");
  rotation /= norm;  // exporters round; renormalise so the rotation stays rigid
  glm::dmat4 m = glm::mat4_cast(rotation);
  for (int r = 0; r < 3; ++r) {
    m[0][r] *= s[0];
    m[1][r] *= s[1];
    m[2][r] *= s[2];
  }
  m[3] = glm::dvec4(t[0], t[1], t[2], 1.0);  // T * R * S
  return m;
}

// With at most one parent per node, the hierarchy is a forest unless following parents loops.
void checkAcyclic(const Context& ctx, const std::vector<Node>& nodes) {
  const uint32_t unvisited = UINT32_MAX;
  std::vector<uint32_t> walk(nodes.size(), unvisited);
  for (uint32_t start = 0; start < nodes.size(); ++start) {
    std::optional<uint32_t> cur = start;
    while (cur && walk[*cur] == unvisited) {
      walk[*cur] = start;
      cur = nodes[*cur].parent;
    }
    if (!cur || walk[*cur] != start) continue;
    // *cur lies on a cycle: list it in parent -> child order, starting at its smallest index.
    std::vector<uint32_t> cycle{*cur};
    for (uint32_t n = *nodes[*cur].parent; n != *cur; n = *nodes[n].parent) cycle.push_back(n);
    std::reverse(cycle.begin(), cycle.end());
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
    std::string path;
    for (size_t k = 0; k < cycle.size() && k < 8; ++k) path += indexed("nodes", cycle[k]) + " -> ";
    path += cycle.size() > 8 ? "... -> " + indexed("nodes", cycle[0]) : indexed("nodes", cycle[0]);
    ctx.fail(indexed("nodes", cycle[0]), "the node hierarchy has a cycle: " + path);
  }
}

}  // namespace

std::vector<Node> parseNodes(Context& ctx, const Json& doc, const NodeCounts& counts) {
  std::vector<Node> nodes(arraySize(ctx, doc, "nodes"));
  for (size_t i = 0; i < nodes.size(); ++i) {
    const std::string element = indexed("nodes", i);
    const Json& o = arrayObject(ctx, doc, "nodes", i);
    Node& n = nodes[i];
    n.name = getString(ctx, o, "name", element).value_or("");
    n.mesh = getIndex(ctx, o, "mesh", element, "meshes", counts.meshes);
    n.camera = getIndex(ctx, o, "camera", element, "cameras", counts.cameras);
    if (getIndex(ctx, o, "skin", element, "skins", counts.skins))
      ctx.warn("skins are ignored; skinned meshes are rendered in their bind pose");
    if (const Json* children = getArray(ctx, o, "children", element))
      for (size_t k = 0; k < children->size(); ++k)
        n.children.push_back(
            indexValue(ctx, (*children)[k], element + "." + indexed("children", k), "", "nodes", nodes.size()));
    n.local = localTransform(ctx, o, element);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(n.local[c][r])) ctx.fail(element, "its transform is not finite");
    if (const Json* ext = getObject(ctx, o, "extensions", element))
      if (const Json* lp = getObject(ctx, *ext, "KHR_lights_punctual", element + ".extensions"))
        n.light = requireIndex(ctx, *lp, "light", element + ".extensions.KHR_lights_punctual",
                               "KHR_lights_punctual.lights", counts.lights);
  }
  for (uint32_t i = 0; i < nodes.size(); ++i) {
    for (uint32_t c : nodes[i].children) {
      if (c == i) ctx.fail(indexed("nodes", i), "lists itself as a child: the node hierarchy has a cycle");
      if (nodes[c].parent == i) ctx.fail(indexed("nodes", i), "lists " + indexed("nodes", c) + " twice as a child");
      if (nodes[c].parent)
        ctx.fail(indexed("nodes", c), "has two parents (" + indexed("nodes", *nodes[c].parent) + " and " +
                                          indexed("nodes", i) + "); the node hierarchy must be a tree");
      nodes[c].parent = i;
    }
  }
  checkAcyclic(ctx, nodes);
  return nodes;
}

SceneChoice chooseScene(const Context& ctx, const Json& doc, const std::vector<Node>& nodes) {
  const size_t sceneCount = arraySize(ctx, doc, "scenes");
  std::vector<std::vector<uint32_t>> sceneRoots(sceneCount);
  for (size_t s = 0; s < sceneCount; ++s) {
    const std::string element = indexed("scenes", s);
    const Json& o = arrayObject(ctx, doc, "scenes", s);
    const Json* list = getArray(ctx, o, "nodes", element);
    if (!list) continue;
    std::vector<bool> seen(nodes.size(), false);
    for (size_t k = 0; k < list->size(); ++k) {
      const uint32_t n = indexValue(ctx, (*list)[k], element + "." + indexed("nodes", k), "", "nodes", nodes.size());
      if (seen[n]) ctx.fail(element, "lists " + indexed("nodes", n) + " twice");
      if (nodes[n].parent)
        ctx.fail(element, "lists " + indexed("nodes", n) + ", which is not a root node (it is a child of " +
                              indexed("nodes", *nodes[n].parent) + ")");
      seen[n] = true;
      sceneRoots[s].push_back(n);
    }
  }
  const std::optional<uint32_t> chosen = getIndex(ctx, doc, "scene", "", "scenes", sceneCount);
  SceneChoice choice;
  if (sceneCount == 0) {
    // No scenes (the Khronos Triangle has none): render every root node.
    for (uint32_t n = 0; n < nodes.size(); ++n)
      if (!nodes[n].parent) choice.roots.push_back(n);
    return choice;
  }
  const uint32_t s = chosen.value_or(0);
  choice.roots = sceneRoots[s];
  choice.scene = &doc.at("scenes").at(s);
  choice.element = indexed("scenes", s);
  return choice;
}

std::vector<PlacedNode> placeNodes(const std::vector<Node>& nodes, const std::vector<uint32_t>& roots) {
  // Iterative: a deep chain of nodes must not overflow the call stack.
  std::vector<PlacedNode> out, stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, nodes[*it].local});
  while (!stack.empty()) {
    const PlacedNode p = stack.back();
    stack.pop_back();
    out.push_back(p);
    const std::vector<uint32_t>& children = nodes[p.node].children;
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back({*it, p.world * nodes[*it].local});
  }
  return out;
}

}  // namespace relt::gltf
