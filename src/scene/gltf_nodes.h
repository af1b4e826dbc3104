#pragma once
// The glTF node hierarchy: local transforms (matrix or TRS), the checks that make it a forest
// (no cycles, at most one parent), the choice of scene, and world transforms of the nodes it renders.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/gltf_json.h"

namespace relt::gltf {

struct Node {
  std::string name;
  glm::dmat4 local{1.0};
  std::optional<uint32_t> mesh, camera, light;
  std::vector<uint32_t> children;
  std::optional<uint32_t> parent;
};

struct NodeCounts {
  size_t meshes = 0, cameras = 0, lights = 0, skins = 0;
};

// Parses every node and checks the hierarchy is a forest.
std::vector<Node> parseNodes(Context& ctx, const Json& doc, const NodeCounts& counts);

struct SceneChoice {
  std::vector<uint32_t> roots;
  const Json* scene = nullptr;  // the chosen scene object, if the file has scenes
  std::string element;          // "scenes[0]", or empty
};

// The `scene` property, else scene 0; without scenes, every root node. Validates all scenes.
SceneChoice chooseScene(const Context& ctx, const Json& doc, const std::vector<Node>& nodes);

struct PlacedNode {
  uint32_t node;
  glm::dmat4 world;
};

// Nodes reachable from the roots with world = parent * local, parents before children.
std::vector<PlacedNode> placeNodes(const std::vector<Node>& nodes, const std::vector<uint32_t>& roots);

}  // namespace relt::gltf
