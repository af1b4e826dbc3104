// The glTF loader against real files (tests/data/gltf, see its README for provenance) and against
// small synthesised files, one property per test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include "gltf_test_support.h"
#include "scene/gltf_loader.h"

namespace relt::test {
namespace {

std::string dataPath(const std::string& rel) { return sourcePath("tests/data/gltf/" + rel); }

Vec3 geometricNormal(const Scene& s, const Triangle& t) {
  return glm::normalize(
      glm::cross(s.positions[t.v[1]] - s.positions[t.v[0]], s.positions[t.v[2]] - s.positions[t.v[0]]));
}

// Shows the whole message when the expected part is missing.
::testing::AssertionResult contains(const std::string& message, const std::string& part) {
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << message << "\" does not contain \"" << part << "\"";
}

bool hasWarning(const Scene& s, const std::string& part) {
  return std::any_of(s.warnings.begin(), s.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

std::vector<std::string> gltfFilesUnder(const std::string& rel) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dataPath(rel))) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
      out.push_back(std::filesystem::relative(e.path(), dataPath(rel)).generic_string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// ---------------------------------------------------------------------------------------------
// Every valid file loads into a consistent scene.

class ValidFile : public ::testing::TestWithParam<std::string> {};

TEST_P(ValidFile, LoadsIntoAConsistentScene) {
  const Scene s = loadGltf(dataPath("valid/" + GetParam()));
  ASSERT_EQ(s.normals.size(), s.positions.size());
  for (const Triangle& t : s.triangles) {
    for (uint32_t v : t.v) ASSERT_LT(v, s.positions.size());
    ASSERT_LT(t.material, s.materials.size());
    EXPECT_GT(
        glm::length(glm::cross(s.positions[t.v[1]] - s.positions[t.v[0]], s.positions[t.v[2]] - s.positions[t.v[0]])),
        0.0f);
    for (uint32_t v : t.v) {
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(s.positions[v], s.bounds.lo)));
      EXPECT_TRUE(glm::all(glm::lessThanEqual(s.positions[v], s.bounds.hi)));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(TestData, ValidFile, ::testing::ValuesIn(gltfFilesUnder("valid")), testName);

TEST(ValidFiles, TriangleWithoutSceneOrMaterialGetsTheDefaultGreyLambert) {
  const Scene s = loadGltf(dataPath("valid/Khronos-Triangle/Triangle.gltf"));
  ASSERT_EQ(s.triangles.size(), 1u);
  const Material& m = s.materials[s.triangles[0].material];
  EXPECT_EQ(m.kind, MaterialKind::Lambert);
  EXPECT_EQ(m.baseColor, Color(0.8f));
  EXPECT_TRUE(s.warnings.empty());
}

TEST(ValidFiles, SimpleMeshesInstancesItsMeshTwice) {
  const Scene s = loadGltf(dataPath("valid/Khronos-SimpleMeshes/SimpleMeshes.gltf"));
  EXPECT_EQ(s.triangles.size(), 2u);  // one triangle, two nodes
  EXPECT_EQ(s.bounds.lo, Vec3(0, 0, 0));
  EXPECT_EQ(s.bounds.hi, Vec3(2, 1, 0));  // the second instance is translated by +x
}

TEST(ValidFiles, BoxMatrixHierarchyKeepsShadingNormalsOnTheFrontSide) {
  const Scene s = loadGltf(dataPath("valid/Khronos-Box/Box.gltf"));
  ASSERT_EQ(s.triangles.size(), 12u);
  EXPECT_NEAR(s.bounds.lo.x, -0.5f, 1e-6f);
  EXPECT_NEAR(s.bounds.hi.y, 0.5f, 1e-6f);
  EXPECT_NEAR(s.bounds.hi.z, 0.5f, 1e-6f);
  for (const Triangle& t : s.triangles) {
    const Vec3 n = s.normals[t.v[0]];
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(n, geometricNormal(s, t)), 0.99f);
    EXPECT_GT(glm::dot(n, s.positions[t.v[0]]), 0.0f);  // outward on a centred box
  }
  // pbrMetallicRoughness gives only baseColorFactor: metallicFactor defaults to 1 in glTF.
  EXPECT_EQ(s.materials[0].kind, MaterialKind::Conductor);
  EXPECT_NEAR(s.materials[0].baseColor.x, 0.8f, 1e-6f);
}

TEST(ValidFiles, SparseAccessorSubstitutesPositions) {
  const Scene s = loadGltf(dataPath("valid/Khronos-SimpleSparseAccessor/SimpleSparseAccessor.gltf"));
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_EQ(s.bounds.hi, Vec3(6, 4, 0));  // the base data is at most y = 1
  EXPECT_NE(std::find(s.positions.begin(), s.positions.end(), Vec3(3, 3, 0)), s.positions.end());
}

TEST(ValidFiles, CamerasKeepsThePerspectiveOneAndWarnsAboutTheOrthographicOne) {
  const Scene s = loadGltf(dataPath("valid/Khronos-Cameras/Cameras.gltf"));
  ASSERT_EQ(s.cameras.size(), 1u);  // the file's two camera nodes: perspective + orthographic
  const PerspectiveCamera& c = s.cameras[0];
  EXPECT_EQ(c.name, "camera0");
  EXPECT_EQ(c.position, Vec3(0.5f, 0.5f, 3.0f));
  EXPECT_FLOAT_EQ(c.yfov, 0.7f);
  ASSERT_TRUE(c.aspect);
  EXPECT_FLOAT_EQ(*c.aspect, 1.0f);
  EXPECT_EQ(c.toWorld, Mat3(1.0f));
  EXPECT_TRUE(hasWarning(s, "orthographic"));
  EXPECT_EQ(s.triangles.size(), 2u);
}

TEST(ValidFiles, CubeReadsItsExternalBinAndWarnsOnceAboutTextures) {
  const Scene s = loadGltf(dataPath("valid/Cube/Cube.gltf"));
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_EQ(std::count_if(s.warnings.begin(), s.warnings.end(),
                          [](const std::string& w) { return w.find("baseColor textures") != std::string::npos; }),
            1);
}

TEST(ValidFiles, GlbFilesLoad) {
  const Scene box = loadGltf(dataPath("valid/tinygltf-box01/box01.glb"));
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_EQ(box.materials[0].kind, MaterialKind::Lambert);
  EXPECT_NEAR(box.materials[0].alpha, 0.33f * 0.33f, 1e-5f);
  const Scene tri = loadGltf(dataPath("valid/tinygltf-zero-sized-bin-chunk/zero-sized-bin-chunk-issue-440.glb"));
  EXPECT_EQ(tri.triangles.size(), 1u);
  EXPECT_TRUE(tri.materials[0].doubleSided);
  const Scene morph = loadGltf(dataPath("valid/tinygltf-SparseMorphTargets/singleBlendshapeCube_sparse.glb"));
  EXPECT_EQ(morph.triangles.size(), 12u);
  EXPECT_TRUE(hasWarning(morph, "morph targets"));
}

TEST(ValidFiles, EmissiveStrengthScalesEmissiveFactor) {
  const Scene s = loadGltf(dataPath("valid/validator-extensions/KHR_materials_emissive_strength/valid.gltf"));
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.materials[0].emission, Color(2, 0, 0));
  EXPECT_EQ(s.materials[1].emission, Color(0, 1, 0));  // default strength 1
  EXPECT_FALSE(s.materials[2].isEmissive());           // strength 0
}

TEST(ValidFiles, ExtensionMaterialsWithoutMetallicFactorAreConductors) {
  // glTF's metallicFactor defaults to 1 and a metal transmits nothing, so these stay conductors.
  for (const char* f : {"KHR_materials_ior", "KHR_materials_transmission", "KHR_materials_volume"}) {
    const Scene s = loadGltf(dataPath(std::string("valid/validator-extensions/") + f + "/valid.gltf"));
    ASSERT_FALSE(s.materials.empty()) << f;
    for (const Material& m : s.materials) EXPECT_EQ(m.kind, MaterialKind::Conductor) << f;
  }
  const Scene volume = loadGltf(dataPath("valid/validator-extensions/KHR_materials_volume/valid.gltf"));
  EXPECT_TRUE(hasWarning(volume, "KHR_materials_volume"));
}

class ValidatorFiles : public TempDirTest {};

TEST_F(ValidatorFiles, TransmissionWithZeroMetallicIsADielectric) {
  std::ifstream in(dataPath("valid/validator-extensions/KHR_materials_ior/valid.gltf"));
  Json doc = Json::parse(in);
  doc["materials"][0]["pbrMetallicRoughness"] = {{"metallicFactor", 0.0}};
  doc["materials"][0]["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 1.0}};
  const Scene s = load(doc);
  EXPECT_EQ(s.materials[0].kind, MaterialKind::Dielectric);
  EXPECT_FLOAT_EQ(s.materials[0].ior, 2.0f);
}

TEST_F(ValidatorFiles, SpotLightPlacedByANodeBecomesASpot) {
  std::ifstream in(dataPath("valid/validator-extensions/KHR_lights_punctual/valid.gltf"));
  Json doc = Json::parse(in);
  EXPECT_TRUE(load(doc).punctualLights.empty());  // defined but placed by no node
  doc["nodes"] = Json::array({{{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}});
  const Scene s = load(doc);
  ASSERT_EQ(s.punctualLights.size(), 1u);
  const PunctualLight& l = s.punctualLights[0];
  EXPECT_TRUE(l.spot);
  EXPECT_EQ(l.position, Vec3(1, 2, 3));
  EXPECT_EQ(l.direction, Vec3(0, 0, -1));
  EXPECT_NEAR(l.cosInner, std::cos(0.2f), 1e-6f);
  EXPECT_NEAR(l.cosOuter, std::cos(1.0f), 1e-6f);
  EXPECT_NEAR(l.intensity.x, 0.75f * 2.45f, 1e-5f);
  EXPECT_NEAR(l.intensity.y, 0.3f * 2.45f, 1e-5f);
}

TEST(ValidFiles, CoreNodeAndMeshLoadWithTheirWarnings) {
  const Scene node = loadGltf(dataPath("valid/validator-extensions/core-node/valid.gltf"));
  EXPECT_EQ(node.cameras.size(), 1u);
  EXPECT_TRUE(hasWarning(node, "skins"));
  // Accessors without a bufferView are zeros: every triangle is degenerate and dropped.
  EXPECT_TRUE(node.triangles.empty());
  const Scene mesh = loadGltf(dataPath("valid/validator-extensions/core-mesh/valid.gltf"));
  EXPECT_TRUE(mesh.triangles.empty());
}

// ---------------------------------------------------------------------------------------------
// Every invalid file fails with one InputError naming the file and the problem. A new file in
// tests/data/gltf/invalid is picked up automatically and must at least throw InputError.

const std::map<std::string, std::string> kInvalidExpectations = {
    {"draco-box/Box.gltf", "extensionsRequired: KHR_draco_mesh_compression (Draco-compressed meshes) is not supported"},
    {"tinygltf-bounds-checking/integer-out-of-bounds.gltf", "bufferViews[0]: byteLength"},
    {"tinygltf-bounds-checking/invalid-buffer-index.gltf", "bufferViews[1]: buffer refers to buffers[1]"},
    {"tinygltf-bounds-checking/invalid-buffer-view-index.gltf", "accessors[0]: bufferView refers to bufferViews[1]"},
    {"tinygltf-bounds-checking/invalid-primitive-indices.gltf",
     "meshes[0].primitives[0]: indices refers to accessors[1]"},
    {"validator-extensions/spot_invalid_angles.gltf", "innerConeAngle < outerConeAngle"},
    {"validator/accessor/invalid_sparse_count_and_stride.gltf", "accessors[0].sparse: count 2"},
    {"validator/accessor/unresolved_bufferviews.gltf", "accessors[0]: bufferView refers to bufferViews[0]"},
    {"validator/asset/1_0_version.gltf", "asset.version: glTF 1.0 is not supported"},
    {"validator/asset/invalid_version.gltf", "asset.version: \"1.0.1-dev\" is not a valid glTF version"},
    {"validator/buffer/invalid_uri_data.gltf", "buffers[0]: malformed data URI"},
    {"validator/buffer/invalid_uri_data_bytelength.gltf", "byteLength"},
    {"validator/buffer/not_found.gltf", "buffers[0]: cannot read \"not_found.bin\""},
    {"validator/glb/chunk_too_big.glb", "GLB chunk 0: truncated chunk header"},
    {"validator/glb/empty_file.glb", "the file is empty"},
    {"validator/glb/invalid_magic.glb", "invalid magic"},
    {"validator/glb/invalid_version.glb", "container version 0"},
    {"validator/glb/length_mismatch.glb", "declares 49 bytes but the file has 48"},
    {"validator/glb/only_header.glb", "no JSON chunk"},
    {"validator/glb/truncated_chunk_data.glb", "truncated"},
    {"validator/json/empty_file.gltf", "the file is empty"},
    {"validator/json/invalid_object.gltf", "must be a JSON object"},
    {"validator/json/invalid_syntax.gltf", "invalid JSON: parse error at line 1, column 2"},
    {"validator/mesh_data/index_buffer_oob.gltf", "index 5 at position 5 of accessors[0] is out of range"},
    {"validator/node/node_loop.gltf", "cycle: nodes[0] -> nodes[1] -> nodes[2] -> nodes[0]"},
    {"validator/node/node_loop_scene.gltf", "nodes[0]: lists itself as a child: the node hierarchy has a cycle"},
    {"validator/root/empty_object.gltf", "asset: is missing"},
    {"validator/root/undefined_used_extensions.gltf", "extensionsRequired: KHR_extension is not supported"},
    {"validator/scene/unresolved_node.gltf", "scenes[0].nodes[0]: refers to nodes[0], which does not exist"},
};

class InvalidFile : public ::testing::TestWithParam<std::string> {};

TEST_P(InvalidFile, FailsWithOneInputErrorNamingFileAndProblem) {
  const std::string path = dataPath("invalid/" + GetParam());
  try {
    loadGltf(path);
    FAIL() << "loaded without error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_FALSE(e.reason().empty());
    auto it = kInvalidExpectations.find(GetParam());
    if (it != kInvalidExpectations.end()) EXPECT_TRUE(contains(msg, it->second)) << msg;
  }
}

INSTANTIATE_TEST_SUITE_P(TestData, InvalidFile, ::testing::ValuesIn(gltfFilesUnder("invalid")), testName);

TEST(InvalidFiles, EveryExpectationHasItsFile) {
  const std::vector<std::string> files = gltfFilesUnder("invalid");
  for (const auto& [file, expected] : kInvalidExpectations)
    EXPECT_NE(std::find(files.begin(), files.end(), file), files.end()) << file;
}

TEST(InvalidFiles, MissingFileIsAnInputError) { EXPECT_THROW(loadGltf(dataPath("no/such/file.gltf")), InputError); }

// ---------------------------------------------------------------------------------------------
// Synthesised files.

const std::vector<Vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

class Synthesised : public TempDirTest {};

TEST_F(Synthesised, NodeCycleIsRejected) {
  GltfBuilder b;
  b.node(Json::object());
  b.node({{"children", {2}}});
  b.node({{"children", {1}}});
  EXPECT_TRUE(contains(loadError(b.finish()), "cycle: nodes[1] -> nodes[2] -> nodes[1]"));
}

TEST_F(Synthesised, NodeWithTwoParentsIsRejected) {
  GltfBuilder b;
  b.node({{"children", {2}}});
  b.node({{"children", {2}}});
  b.node(Json::object());
  EXPECT_TRUE(contains(loadError(b.finish()), "nodes[2]: has two parents (nodes[0] and nodes[1])"));
}

TEST_F(Synthesised, NonFinitePositionIsRejected) {
  GltfBuilder b;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, nan, 0}})}});
  EXPECT_TRUE(contains(loadError(b.finish()), "POSITION (accessors[0]) has a non-finite value at vertex 2"));
  GltfBuilder c;
  const float inf = std::numeric_limits<float>::infinity();
  c.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, inf}});  // unused meshes are checked too
  EXPECT_TRUE(contains(loadError(c.finish()), "non-finite"));
}

TEST_F(Synthesised, IndexOutOfRangeIsRejected) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 3})}});
  EXPECT_TRUE(contains(loadError(b.finish()),
                       "index 3 at position 2 of accessors[1] is out of range: POSITION has 3 vertices"));
}

TEST_F(Synthesised, DanglingReferencesAreRejectedByName) {
  struct Case {
    std::function<void(Json&)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](Json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7; },
       "meshes[0].primitives[0]: attributes.POSITION refers to accessors[7]"},
      {[](Json& d) { d["meshes"][0]["primitives"][0]["material"] = 2; }, "material refers to materials[2]"},
      {[](Json& d) { d["nodes"][0]["mesh"] = 5; }, "nodes[0]: mesh refers to meshes[5]"},
      {[](Json& d) { d["nodes"][0]["camera"] = 0; }, "nodes[0]: camera refers to cameras[0]"},
      {[](Json& d) { d["nodes"][0]["children"] = Json::array({9}); }, "nodes[0].children[0]: refers to nodes[9]"},
      {[](Json& d) { d["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0; },
       "light refers to KHR_lights_punctual.lights[0]"},
      {[](Json& d) { d["accessors"][0]["bufferView"] = 4; }, "accessors[0]: bufferView refers to bufferViews[4]"},
      {[](Json& d) { d["bufferViews"][0]["buffer"] = 1; }, "bufferViews[0]: buffer refers to buffers[1]"},
      {[](Json& d) { d["scene"] = 3; }, "scene refers to scenes[3]"},
      {[](Json& d) { d["scenes"][0]["nodes"] = Json::array({"x"}); }, "scenes[0].nodes[0]: must be an index"},
  };
  for (const Case& c : cases) {
    GltfBuilder b;
    b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
    b.scene({0});
    Json doc = b.finish();
    c.edit(doc);
    EXPECT_TRUE(contains(loadError(doc), c.expected)) << c.expected;
  }
}

TEST_F(Synthesised, AccessorBeyondItsBufferViewIsRejected) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
  Json doc = b.finish();
  doc["accessors"][0]["count"] = 4;
  EXPECT_TRUE(
      contains(loadError(doc), "accessors[0]: its elements occupy bytes [0, 48) of bufferViews[0], which has only 36"));
  doc["accessors"][0]["count"] = 3;
  doc["bufferViews"][0]["byteLength"] = 400;
  EXPECT_TRUE(contains(loadError(doc), "bufferViews[0]: bytes [0, 400) lie outside buffers[0]"));
}

// Points and lines are valid glTF: such primitives are not drawn, the rest of the file is, and
// their data is checked as any other (an index out of range is an error, as for the validator).
TEST_F(Synthesised, NonTriangleModesAreNotDrawn) {
  const std::vector<std::pair<int, std::string>> modes = {{0, "primitives of mode POINTS are not drawn"},
                                                          {1, "primitives of mode LINES are not drawn"},
                                                          {2, "primitives of mode LINE_LOOP are not drawn"},
                                                          {3, "primitives of mode LINE_STRIP are not drawn"}};
  for (const auto& [mode, warning] : modes) {
    GltfBuilder b;
    b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, -1, mode)}});
    b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
    const Scene s = load(b.finish());
    EXPECT_EQ(s.triangles.size(), 1u) << mode;
    EXPECT_TRUE(hasWarning(s, warning)) << warning;
  }
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 3}, -1, 1)}});
  EXPECT_TRUE(contains(loadError(b.finish()), "index 3 at position 2 of accessors[1] is out of range"));
}

TEST_F(Synthesised, StripAndFanBecomeFrontFacingTriangles) {
  // A strip zig-zags up the y axis; a fan turns around vertex 0. All triangles must face +z.
  GltfBuilder b;
  const std::vector<Vec3> stripCcw = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  const std::vector<Vec3> fan = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}};
  b.node({{"mesh", b.triangleMesh(stripCcw, {}, -1, 5)}});
  b.node({{"mesh", b.triangleMesh(fan, {0, 1, 2, 3, 4}, -1, 6)}, {"translation", {0, 0, 5}}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.triangles.size(), 4u + 3u);
  for (const Triangle& t : s.triangles) EXPECT_GT(geometricNormal(s, t).z, 0.99f);
}

TEST_F(Synthesised, NegativeScaleFlipsWindingSoTheFrontFaceStays) {
  // The triangle faces +z with a +z normal; mirrored in x it must still face +z, normals agreeing.
  GltfBuilder b;
  const std::vector<Vec3> n = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  const int normals = b.addAccessor(b.addView(n.data(), 36), GltfBuilder::kFloat, 3, "VEC3");
  Json prim = {{"attributes", {{"POSITION", b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}, {"NORMAL", normals}}}};
  const int mesh = b.mesh(prim);
  b.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}});
  b.node({{"mesh", mesh}, {"scale", {1, 1, -2}}});  // mirrored in z: both must now face -z
  const Scene s = load(b.finish());
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_GT(geometricNormal(s, s.triangles[0]).z, 0.99f);
  EXPECT_EQ(s.normals[s.triangles[0].v[0]], Vec3(0, 0, 1));
  EXPECT_LT(geometricNormal(s, s.triangles[1]).z, -0.99f);
  EXPECT_EQ(s.normals[s.triangles[1].v[0]], Vec3(0, 0, -1));
}

TEST_F(Synthesised, NonIndexedTrianglesUseConsecutiveVertices) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}})}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.positions[s.triangles[1].v[0]], Vec3(0, 0, 1));
  EXPECT_EQ(s.normals[s.triangles[0].v[0]], Vec3(0.0f));  // the file gives no normals
}

// The validator only warns (MESH_PRIMITIVE_INCOMPATIBLE_MODE); the whole triangles are drawn.
TEST_F(Synthesised, TriangleCountNotAMultipleOfThreeDrawsTheWholeTriangles) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}})}});
  const Scene s = load(b.finish());
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_TRUE(hasWarning(s, "vertex count is not a multiple of 3: the last 1 or 2 are not drawn"));
}

// glTF 2.0 §3.7.2.1: indices MUST NOT hold the restart value (the validator's
// ACCESSOR_INDEX_PRIMITIVE_RESTART), even where it would name an existing vertex.
TEST_F(Synthesised, PrimitiveRestartIndexIsRejected) {
  GltfBuilder b;
  std::vector<Vec3> p(256, Vec3(0.0f));
  p[1] = {1, 0, 0};
  p[255] = {0, 1, 0};
  const std::vector<uint8_t> idx = {0, 1, 255};
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", b.positions(p)}}}, {"indices", b.indices(idx)}})}});
  EXPECT_TRUE(contains(loadError(b.finish()), "meshes[0].primitives[0]: index 255 at position 2 of accessors[1] is "
                                              "the primitive restart value of its component type"));
}

TEST_F(Synthesised, InterleavedStridedBufferIsRead) {
  // position, normal, position, normal, ... with byteStride 24 and accessor byteOffsets 0 and 12.
  GltfBuilder b;
  const std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 1, 0, 2, 0, 0, 0, 1};
  const int view = b.addView(interleaved.data(), interleaved.size() * 4, 24);
  const int pos = b.addAccessor(view, GltfBuilder::kFloat, 3, "VEC3", 0);
  const int nrm = b.addAccessor(view, GltfBuilder::kFloat, 3, "VEC3", 12);
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}})}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.positions[s.triangles[0].v[1]], Vec3(2, 0, 0));
  EXPECT_EQ(s.positions[s.triangles[0].v[2]], Vec3(0, 2, 0));
  EXPECT_EQ(s.normals[s.triangles[0].v[2]], Vec3(0, 0, 1));
  EXPECT_EQ(s.bounds.hi, Vec3(2, 2, 0));
}

TEST_F(Synthesised, StrideSmallerThanTheElementIsRejected) {
  GltfBuilder b;
  const std::vector<float> data(12, 0.0f);
  const int view = b.addView(data.data(), 48, 8);
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", b.addAccessor(view, GltfBuilder::kFloat, 3, "VEC3")}}}})}});
  EXPECT_TRUE(contains(loadError(b.finish()), "do not fit the byteStride 8"));
}

TEST_F(Synthesised, AllIndexComponentTypesGiveTheSameTriangles) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh(kQuad, std::vector<uint16_t>{0, 1, 2, 0, 2, 3})}});
  const int p8 = b.positions(kQuad), p32 = b.positions(kQuad);
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", p8}}},
                           {"indices", b.indices(std::vector<uint8_t>{0, 1, 2, 0, 2, 3})}})}});
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", p32}}},
                           {"indices", b.indices(std::vector<uint32_t>{0, 1, 2, 0, 2, 3})}})}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.triangles.size(), 6u);
  for (int k = 0; k < 3; ++k)
    for (int t = 0; t < 2; ++t)
      for (int v = 0; v < 3; ++v) EXPECT_EQ(s.positions[s.triangles[2 * k + t].v[v]], s.positions[s.triangles[t].v[v]]);
}

TEST_F(Synthesised, FloatIndicesAreRejected) {
  GltfBuilder b;
  const std::vector<float> idx = {0, 1, 2};
  const int acc = b.addAccessor(b.addView(idx.data(), 12), GltfBuilder::kFloat, 3, "SCALAR");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", b.positions(kQuad)}}}, {"indices", acc}})}});
  EXPECT_TRUE(contains(loadError(b.finish()),
                       "must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT SCALAR, got FLOAT SCALAR"));
}

TEST_F(Synthesised, QuantizedPositionsAreRejected) {
  GltfBuilder b;
  const std::vector<uint16_t> p = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const int acc = b.addAccessor(b.addView(p.data(), 18), GltfBuilder::kUShort, 3, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", acc}}}})}});
  EXPECT_TRUE(contains(loadError(b.finish()), "POSITION (accessors[0]) must be FLOAT VEC3, got UNSIGNED_SHORT VEC3"));
}

TEST_F(Synthesised, TrsAndMatrixGiveTheSameWorldPositions) {
  // T * R * S with R = 90 degrees about z, in TRS form and as the equivalent column-major matrix.
  const double h = std::sqrt(0.5);
  GltfBuilder b;
  const int mesh = b.triangleMesh({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  b.node({{"mesh", mesh}, {"translation", {1, 2, 3}}, {"rotation", {0, 0, h, h}}, {"scale", {2, 3, 4}}});
  b.node({{"mesh", mesh}, {"matrix", {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1}}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.triangles.size(), 2u);
  for (int v = 0; v < 3; ++v) {
    const Vec3 a = s.positions[s.triangles[0].v[v]], m = s.positions[s.triangles[1].v[v]];
    EXPECT_NEAR(glm::length(a - m), 0.0f, 1e-5f) << v;
  }
  EXPECT_NEAR(glm::length(s.positions[s.triangles[0].v[0]] - Vec3(1, 4, 3)), 0.0f, 1e-5f);  // (1,0,0) -> 2*(0,1,0) + t
}

TEST_F(Synthesised, ParentTransformsComposeWithChildren) {
  GltfBuilder b;
  const int mesh = b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.node({{"children", {1}}, {"scale", {2, 2, 2}}});
  b.node({{"mesh", mesh}, {"translation", {1, 0, 0}}});
  b.scene({0});
  const Scene s = load(b.finish());
  EXPECT_EQ(s.bounds.lo, Vec3(2, 0, 0));  // parent * child: scale applies to the translation
  EXPECT_EQ(s.bounds.hi, Vec3(4, 2, 0));
}

// The validator's NODE_MATRIX_NON_TRS: a projective, sheared or singular matrix is refused.
TEST_F(Synthesised, MatrixThatIsNotTrsIsRejected) {
  const std::vector<std::vector<double>> bad = {
      {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},  // projective last row
      {1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},    // shear
      {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};   // a zero axis
  for (const std::vector<double>& m : bad) {
    GltfBuilder b;
    b.node({{"matrix", m}});
    EXPECT_TRUE(contains(loadError(b.finish()), "is not a translation, rotation and scale (glTF requires one)"));
  }
  GltfBuilder b;  // rotation, non-uniform scale and translation together are fine
  b.node({{"matrix", {0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 5, 6, 7, 1}}});
  EXPECT_NO_THROW(load(b.finish()));
}

// JSON Schema 2020-12, which glTF's schema follows, counts 14.0 as an integer; 14.5 is not one.
TEST_F(Synthesised, IntegralFloatsAreIntegers) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
  Json doc = b.finish();
  doc["accessors"][0]["count"] = 3.0;
  doc["nodes"][0]["mesh"] = 0.0;
  EXPECT_EQ(load(doc).triangles.size(), 1u);
  doc["accessors"][0]["count"] = 2.5;
  EXPECT_TRUE(contains(loadError(doc), "accessors[0]: count must be a non-negative integer, got 2.5"));
}

TEST_F(Synthesised, MatrixTogetherWithTrsIsRejected) {
  GltfBuilder b;
  b.node({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}, {"scale", {1, 1, 1}}});
  EXPECT_TRUE(contains(loadError(b.finish()), "nodes[0]: has both matrix and translation/rotation/scale"));
}

// The validator's ROTATION_NON_UNIT: beyond its tolerance (0.00769 on the length) no reading is
// the author's; within it the rounding of an exporter is renormalised.
TEST_F(Synthesised, RotationFarFromUnitIsRejectedAndRoundingRenormalised) {
  GltfBuilder b;
  const int mesh = b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.node({{"mesh", mesh}, {"rotation", {5, 0, 0, 1}}});
  EXPECT_TRUE(contains(loadError(b.finish()), "nodes[0]: rotation [5.0,0.0,0.0,1.0] is not a unit quaternion (length 5.099"));
  b.doc["nodes"][0]["rotation"] = {0, 0, 0, 1.005};
  const Scene s = load(b.finish());
  ASSERT_EQ(s.positions.size(), 3u);
  EXPECT_EQ(s.positions[1], Vec3(1, 0, 0));  // the identity, not a scale by 1.005^2
}

// The validator's ACCESSOR_INVALID_FLOAT on NORMAL: corrupt data, not a direction to fall back from.
TEST_F(Synthesised, NonFiniteNormalIsRejected) {
  GltfBuilder b;
  const std::vector<Vec3> n = {{0, 0, 1}, {0, 0, std::numeric_limits<float>::quiet_NaN()}, {0, 0, 1}};
  const int normals = b.addAccessor(b.addView(n.data(), 36), GltfBuilder::kFloat, 3, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes",
                            {{"POSITION", b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}, {"NORMAL", normals}}}})}});
  EXPECT_TRUE(contains(loadError(b.finish()), "meshes[0].primitives[0]: NORMAL (accessors[0]) has a non-finite value at vertex 1"));
}

// glTF 2.0 §3.7.2.1 (and the validator, which only warns): a primitive without POSITION is valid
// and is not drawn.
TEST_F(Synthesised, PrimitiveWithoutPositionIsNotDrawn) {
  GltfBuilder b;
  const int normals = b.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
  b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"NORMAL", normals}}}},
                                      {{"attributes", {{"POSITION", b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}}}}}};
  b.node({{"mesh", 0}});
  const Scene s = load(b.finish());
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_TRUE(hasWarning(s, "mesh primitives without POSITION are not drawn"));
  // Its indices are still checked, against the count of its other attributes (the validator's
  // ACCESSOR_INDEX_OOB).
  GltfBuilder c;
  const std::vector<uint16_t> idx = {0, 1, 3};
  c.node({{"mesh", c.mesh({{"attributes", {{"NORMAL", c.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}})}}},
                           {"indices", c.indices(idx)}})}});
  EXPECT_TRUE(contains(loadError(c.finish()), "index 3 at position 2 of accessors[1] is out of range"));
}

// A buffer without a uri outside a GLB has no data, which glTF allows (the validator accepts it):
// only reading from it is an error.
TEST_F(Synthesised, BufferWithoutUriFailsOnlyWhenRead) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
  Json doc = b.finish();
  doc["buffers"].push_back({{"byteLength", 16}});
  doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 16}});
  EXPECT_EQ(load(doc).triangles.size(), 1u);
  doc["accessors"][0]["bufferView"] = 1;
  doc["accessors"][0]["count"] = 1;
  EXPECT_TRUE(contains(loadError(doc), "buffers[1]: has no uri (only the first buffer of a .glb file may omit it), "
                                       "but accessors[0] reads from it"));
}

TEST_F(Synthesised, DegenerateTrianglesAreDroppedSilently) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh(kQuad, {0, 1, 2, 0, 0, 1, 0, 1, 1})}});
  b.node({{"mesh", b.triangleMesh(kQuad, {0, 1, 2})}, {"scale", {1, 0, 1}}});  // flattened to a line
  const Scene s = load(b.finish());
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_TRUE(s.warnings.empty());
}

TEST_F(Synthesised, SparseAccessorWithoutBufferViewStartsFromZeros) {
  GltfBuilder b;
  const std::vector<uint16_t> which = {1, 2};
  const std::vector<Vec3> values = {{1, 0, 0}, {0, 1, 0}};
  const int iv = b.addView(which.data(), 4), vv = b.addView(values.data(), 24);
  const int acc = b.addAccessor(-1, GltfBuilder::kFloat, 3, "VEC3");
  b.doc["accessors"][acc]["sparse"] = {{"count", 2},
                                       {"indices", {{"bufferView", iv}, {"componentType", GltfBuilder::kUShort}}},
                                       {"values", {{"bufferView", vv}}}};
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", acc}}}})}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.positions[s.triangles[0].v[0]], Vec3(0, 0, 0));
  EXPECT_EQ(s.positions[s.triangles[0].v[2]], Vec3(0, 1, 0));

  b.doc["accessors"][acc]["sparse"]["count"] = 4;
  EXPECT_TRUE(contains(loadError(b.finish()), "accessors[0].sparse: count 4 is larger than the accessor's count 3"));
}

TEST_F(Synthesised, SparseIndexOutOfRangeIsRejected) {
  GltfBuilder b;
  const std::vector<uint8_t> which = {7, 0, 0, 0};
  const std::vector<Vec3> values = {{1, 0, 0}};
  const int iv = b.addView(which.data(), 1), vv = b.addView(values.data(), 12);
  const int acc = b.addAccessor(-1, GltfBuilder::kFloat, 3, "VEC3");
  b.doc["accessors"][acc]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", iv}, {"componentType", GltfBuilder::kUByte}}},
                                       {"values", {{"bufferView", vv}}}};
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", acc}}}})}});
  EXPECT_TRUE(contains(loadError(b.finish()), "accessors[0].sparse: index 7 is out of range (count 3)"));
}

TEST_F(Synthesised, LegacyByteStrideZeroMeansTightlyPacked) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
  Json doc = b.finish();
  doc["bufferViews"][0]["byteStride"] = 0;
  EXPECT_EQ(load(doc).triangles.size(), 1u);
}

TEST_F(Synthesised, MaterialsMapToRendererKinds) {
  GltfBuilder b;
  b.material(
      {{"name", "grey"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}, {"metallicFactor", 0.0}}}});
  b.material({{"pbrMetallicRoughness", {{"metallicFactor", 0.5}, {"roughnessFactor", 0.5}}},
              {"extras", {{"microfacet", "beckmann"}}}});
  b.material(
      {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
       {"extensions",
        {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}, {"KHR_materials_ior", {{"ior", 1.33}}}}}});
  b.material({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
              {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}}}}});
  b.material({{"emissiveFactor", {1, 0.5, 0}},
              {"doubleSided", true},
              {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 10}}}}}});
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});  // no material: default appended
  const Scene s = load(b.finish());
  ASSERT_EQ(s.materials.size(), 6u);
  EXPECT_EQ(s.materials[0].kind, MaterialKind::Lambert);
  EXPECT_EQ(s.materials[0].name, "grey");
  EXPECT_NEAR(s.materials[0].baseColor.y, 0.4f, 1e-6f);
  EXPECT_FLOAT_EQ(s.materials[0].alpha, 1.0f);  // roughnessFactor defaults to 1
  EXPECT_EQ(s.materials[1].kind, MaterialKind::Conductor);
  EXPECT_FLOAT_EQ(s.materials[1].alpha, 0.25f);
  EXPECT_EQ(s.materials[1].distribution, Microfacet::Beckmann);
  EXPECT_EQ(s.materials[2].kind, MaterialKind::Dielectric);
  EXPECT_FLOAT_EQ(s.materials[2].ior, 1.33f);
  EXPECT_FLOAT_EQ(s.materials[2].alpha, 0.0f);
  EXPECT_EQ(s.materials[2].distribution, Microfacet::GGX);
  EXPECT_EQ(s.materials[3].kind, MaterialKind::Dielectric);
  EXPECT_FLOAT_EQ(s.materials[3].ior, 1.5f);
  EXPECT_EQ(s.materials[4].emission, Color(10, 5, 0));
  EXPECT_TRUE(s.materials[4].doubleSided);
  EXPECT_EQ(s.triangles[0].material, 5u);
  EXPECT_EQ(s.materials[5].baseColor, Color(0.8f));
}

TEST_F(Synthesised, BadMaterialValuesAreRejected) {
  const std::vector<std::pair<Json, std::string>> cases = {
      {{{"extras", {{"microfacet", "phong"}}}}, "materials[0].extras: microfacet \"phong\" is not supported"},
      {{{"extras", {{"microfacet", 3}}}}, "microfacet 3 is not supported"},
      {{{"pbrMetallicRoughness", {{"roughnessFactor", 2}}}}, "roughnessFactor 2 is out of range"},
      {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1}}}}}, "baseColorFactor must be an array of 4 numbers"},
      {{{"emissiveFactor", {1, -1, 0}}}, "emissiveFactor[1] -1 is out of range"},
      {{{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}}, "ior 0.5 must be 0 or at least 1"},
      {{{"doubleSided", "yes"}}, "doubleSided must be true or false"},
  };
  for (const auto& [material, expected] : cases) {
    GltfBuilder b;
    b.material(material);
    EXPECT_TRUE(contains(loadError(b.finish()), expected)) << expected;
  }
}

TEST_F(Synthesised, CamerasTakeTheNodeFrameWithoutScale) {
  GltfBuilder b;
  const double h = std::sqrt(0.5);
  b.camera(0.5);
  b.doc["cameras"][0]["name"] = "main";
  b.camera(0.9);
  b.node({{"camera", 0}, {"translation", {0, 1, 5}}, {"rotation", {0, h, 0, h}}, {"scale", {3, 3, 3}}});
  b.node({{"camera", 1}, {"name", "side"}});
  b.node({{"camera", 1}});
  b.node({{"camera", 0}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.cameras.size(), 4u);
  const PerspectiveCamera& c = s.cameras[0];
  EXPECT_EQ(c.name, "main");
  EXPECT_EQ(c.position, Vec3(0, 1, 5));
  // 90 degrees about +y: right -> -z, backward -> +x.
  EXPECT_NEAR(glm::length(c.toWorld[0] - Vec3(0, 0, -1)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(c.toWorld[1] - Vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(c.toWorld[2] - Vec3(1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_FALSE(c.aspect);
  EXPECT_EQ(s.cameras[1].name, "side");
  EXPECT_EQ(s.cameras[2].name, "camera2");
  EXPECT_EQ(s.cameras[3].name, "main.2");  // names stay unique for --camera
  EXPECT_NE(s.findCamera("side"), nullptr);
}

TEST_F(Synthesised, PointAndDirectionalLights) {
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"intensity", 4}, {"color", {1, 0.5, 0.25}}, {"name", "bulb"}}, {{"type", "directional"}}};
  b.node({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  const Scene s = load(b.finish());
  ASSERT_EQ(s.punctualLights.size(), 1u);
  EXPECT_EQ(s.punctualLights[0].name, "bulb");
  EXPECT_FALSE(s.punctualLights[0].spot);
  EXPECT_EQ(s.punctualLights[0].position, Vec3(1, 2, 3));
  EXPECT_EQ(s.punctualLights[0].intensity, Color(4, 2, 1));
  EXPECT_TRUE(hasWarning(s, "directional lights are not supported yet; ignored"));
}

TEST_F(Synthesised, SpotDirectionFollowsTheNodeRotation) {
  GltfBuilder b;
  const double h = std::sqrt(0.5);
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.3}}}}};
  b.node({{"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});  // -90 deg about x
  const Scene s = load(b.finish());
  ASSERT_EQ(s.punctualLights.size(), 1u);
  EXPECT_NEAR(glm::length(s.punctualLights[0].direction - Vec3(0, -1, 0)), 0.0f, 1e-6f);  // pointing down
  EXPECT_NEAR(s.punctualLights[0].cosOuter, std::cos(0.3f), 1e-6f);
}

TEST_F(Synthesised, SceneExtrasBecomeRenderDefaults) {
  GltfBuilder b;
  b.scene({}, {{"width", 320},
               {"height", 200},
               {"max_depth", 12},
               {"bench_width", 64},
               {"bench_height", 40},
               {"comment", "other extras are ignored"}});
  const Scene s = load(b.finish());
  EXPECT_EQ(s.defaults.width, 320);
  EXPECT_EQ(s.defaults.height, 200);
  EXPECT_EQ(s.defaults.maxDepth, 12);
  EXPECT_EQ(s.defaults.benchWidth, 64);
  EXPECT_EQ(s.defaults.benchHeight, 40);

  GltfBuilder none;
  none.scene({});
  EXPECT_EQ(load(none.finish()).defaults.width, 256);
}

TEST_F(Synthesised, BadSceneExtrasAreRejected) {
  // Absurd sizes too: a 16385-pixel side or a depth of 257 is refused before anything is allocated.
  const std::vector<Json> bad = {{{"width", "320"}},       {{"height", 0}},         {{"max_depth", -3}},
                                 {{"width", 1.5}},         {{"bench_width", true}}, {{"bench_height", 1e12}},
                                 {{"width", 16385}},       {{"max_depth", 257}},    {{"height", 2147483648.0}}};
  for (const Json& extras : bad) {
    GltfBuilder b;
    b.scene({}, extras);
    const std::string key = extras.begin().key();
    const std::string range = key == "max_depth" ? "from 1 to 256" : "from 1 to 16384";
    EXPECT_TRUE(contains(loadError(b.finish()), "scenes[0].extras: " + key + " must be an integer " + range))
        << extras.dump();
  }
  GltfBuilder edge;
  edge.scene({}, {{"width", 16384}, {"max_depth", 256}});
  EXPECT_EQ(load(edge.finish()).defaults.width, 16384) << "the limits themselves are allowed";
}

TEST_F(Synthesised, SceneChoiceFollowsTheSceneProperty) {
  GltfBuilder b;
  const int mesh = b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.node({{"mesh", mesh}});
  b.node({{"mesh", mesh}, {"translation", {5, 0, 0}}});
  b.scene({0}, {{"width", 10}});
  b.scene({1}, {{"width", 20}});
  Json doc = b.finish();
  EXPECT_EQ(load(doc).bounds.lo.x, 0.0f);  // no `scene`: scene 0
  doc["scene"] = 1;
  const Scene s = load(doc);
  EXPECT_EQ(s.bounds.lo.x, 5.0f);
  EXPECT_EQ(s.defaults.width, 20);
  doc.erase("scenes");
  doc.erase("scene");
  EXPECT_EQ(load(doc).triangles.size(), 2u);  // no scenes: every root node
}

TEST_F(Synthesised, SceneListingAChildNodeIsRejected) {
  GltfBuilder b;
  b.node({{"children", {1}}});
  b.node(Json::object());
  b.scene({0, 1});
  EXPECT_TRUE(contains(loadError(b.finish()), "scenes[0]: lists nodes[1], which is not a root node"));
}

TEST_F(Synthesised, VersionAndRequiredExtensionsAreCheckedFirst) {
  GltfBuilder b;
  Json doc = b.finish();
  doc["asset"]["version"] = "3.0";
  EXPECT_TRUE(contains(loadError(doc), "asset.version: glTF 3.0 is not supported"));
  doc["asset"]["version"] = "2.0";
  doc["asset"]["minVersion"] = "2.1";
  EXPECT_TRUE(contains(loadError(doc), "asset.minVersion"));
  doc["asset"].erase("minVersion");
  // Required extensions are refused before the (missing) buffer file is read.
  doc["buffers"] = {{{"byteLength", 12}, {"uri", "missing.bin"}}};
  doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  EXPECT_TRUE(contains(loadError(doc),
                       "extensionsRequired: KHR_mesh_quantization (quantized vertex attributes) is not supported"));
  doc["extensionsRequired"] = {"KHR_materials_transmission", "KHR_lights_punctual"};
  doc.erase("buffers");
  const Scene s = load(doc);
  EXPECT_EQ(std::count_if(s.warnings.begin(), s.warnings.end(),
                          [](const std::string& w) { return w.find("KHR_mesh_quantization") != std::string::npos; }),
            1);
}

TEST_F(Synthesised, MalformedBuffersAreRejected) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
  Json doc = b.finish();
  std::string uri = doc["buffers"][0]["uri"];
  doc["buffers"][0]["uri"] = uri.substr(0, uri.size() - 8) + "!!!!!!!!";
  EXPECT_TRUE(contains(loadError(doc), "buffers[0]: the data URI is not valid base64"));
  doc["buffers"][0]["uri"] = "data:text/plain;base64,AAAA";
  EXPECT_TRUE(contains(loadError(doc), "buffers[0]: malformed data URI"));
  doc["buffers"][0]["uri"] = uri;
  doc["buffers"][0]["byteLength"] = 400;
  EXPECT_TRUE(contains(loadError(doc), "buffers[0]: byteLength 400 is larger than the 36 bytes of its data URI"));
  doc["buffers"][0].erase("uri");
  EXPECT_TRUE(contains(loadError(doc), "buffers[0]: has no uri"));
}

TEST_F(Synthesised, ExternalBufferIsResolvedRelativeToTheFile) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
  Json doc = b.finish();
  std::filesystem::create_directories(dir_ / "sub dir");
  std::ofstream(dir_ / "sub dir" / "data file.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(b.bin.data()), static_cast<std::streamsize>(b.bin.size()));
  doc["buffers"][0]["uri"] = "sub%20dir/data%20file.bin";
  EXPECT_EQ(load(doc).triangles.size(), 1u);
}

TEST_F(Synthesised, GlbContainerLoadsByExtensionAndByMagic) {
  GltfBuilder b;
  b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
  Json doc = b.doc;
  doc["buffers"] = {{{"byteLength", b.bin.size()}}};
  std::string json = doc.dump();
  while (json.size() % 4) json += ' ';
  std::vector<uint8_t> bin = b.bin;
  while (bin.size() % 4) bin.push_back(0);
  std::string glb;
  auto u32 = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  glb += "glTF";
  u32(2);
  u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  u32(static_cast<uint32_t>(json.size()));
  glb += "JSON";
  glb += json;
  u32(static_cast<uint32_t>(bin.size()));
  glb.append("BIN\0", 4);
  glb.append(reinterpret_cast<const char*>(bin.data()), bin.size());
  EXPECT_EQ(loadGltf(writeText("scene.glb", glb)).triangles.size(), 1u);
  EXPECT_EQ(loadGltf(writeText("misnamed.gltf", glb)).triangles.size(), 1u);
  // Truncated anywhere: an error, never a crash.
  for (size_t cut : {size_t(5), size_t(16), size_t(30), glb.size() - 1}) {
    EXPECT_THROW(loadGltf(writeText("cut.glb", glb.substr(0, cut))), InputError) << cut;
  }
  // Bytes after the declared length lie outside the GLB: the validator's GLB_EXTRA_DATA warning.
  const Scene extra = loadGltf(writeText("extra.glb", glb + "tail"));
  EXPECT_EQ(extra.triangles.size(), 1u);
  EXPECT_TRUE(hasWarning(extra, "GLB: 4 bytes after the declared length are ignored"));
}

TEST_F(Synthesised, WrongJsonTypesAreRejectedNotMisread) {
  const std::vector<std::pair<std::function<void(Json&)>, std::string>> cases = {
      {[](Json& d) { d["nodes"] = Json::object(); }, "nodes must be an array"},
      {[](Json& d) { d["nodes"][0] = 3; }, "nodes[0]: must be a JSON object, got 3"},
      {[](Json& d) {
         d["nodes"][0]["translation"] = {1, 2};
       },
       "translation must be an array of 3 numbers"},
      {[](Json& d) {
         d["nodes"][0]["rotation"] = {0, 0, 0, 0};
       },
       "is not a unit quaternion"},
      {[](Json& d) { d["accessors"][0]["count"] = -1; }, "accessors[0]: count must be a non-negative integer"},
      {[](Json& d) { d["accessors"][0]["type"] = "VEC5"; }, "type \"VEC5\" is not a valid accessor type"},
      {[](Json& d) { d["accessors"][0]["componentType"] = 5124; }, "componentType 5124 is not a valid"},
      {[](Json& d) { d["meshes"][0]["primitives"] = Json::array(); }, "meshes[0]: has no primitives"},
      {[](Json& d) { d["bufferViews"][0]["byteStride"] = 6; }, "byteStride 6 must be a multiple of 4"},
      {[](Json& d) { d["meshes"][0]["primitives"][0]["mode"] = 9; }, "mode 9 is not a valid primitive mode"},
      {[](Json& d) { d["asset"] = "2.0"; }, "asset must be a JSON object"},
      {[](Json& d) { d["extensionsRequired"] = Json::array({7}); }, "extensionsRequired[0]: must be a string"},
  };
  for (const auto& [edit, expected] : cases) {
    GltfBuilder b;
    b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}});
    Json doc = b.finish();
    edit(doc);
    EXPECT_TRUE(contains(loadError(doc), expected)) << expected;
  }
}

TEST_F(Synthesised, CameraAndLightDefinitionsAreValidated) {
  const std::vector<std::pair<std::function<void(Json&)>, std::string>> cases = {
      {[](Json& d) {
         d["cameras"] = {{{"perspective", {{"yfov", 1}}}}};
       },
       "cameras[0]: type is missing"},
      {[](Json& d) {
         d["cameras"] = {{{"type", "perspective"}, {"perspective", {{"znear", 1}}}}};
       },
       "cameras[0].perspective: yfov is missing"},
      {[](Json& d) {
         d["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 4}}}}};
       },
       "yfov 4 is out of range"},
      {[](Json& d) {
         d["extensions"]["KHR_lights_punctual"]["lights"] = {{{"color", {1, 1, 1}}}};
       },
       "lights[0]: type is missing"},
      {[](Json& d) {
         d["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", -1}}};
       },
       "intensity -1 is out of range"},
      {[](Json& d) {
         d["extensions"]["KHR_lights_punctual"]["lights"] = {
             {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 2.0}}}}};
       },
       "outerConeAngle <= pi/2"},
  };
  for (const auto& [edit, expected] : cases) {
    GltfBuilder b;
    Json doc = b.finish();
    edit(doc);
    EXPECT_TRUE(contains(loadError(doc), expected)) << expected;
  }
}

// The glTF validator reports an enum value outside the list as a warning only (later versions
// may add values), so a camera or light of an unknown type is skipped, not the file refused.
TEST_F(Synthesised, UnknownCameraAndLightTypesAreSkippedWithAWarning) {
  GltfBuilder b;
  b.doc["cameras"] = {{{"type", "fisheye"}}};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "area"}, {"intensity", 2}}};
  b.node({{"camera", 0}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  const Scene s = load(b.finish());
  EXPECT_TRUE(s.cameras.empty());
  EXPECT_TRUE(s.punctualLights.empty());
  EXPECT_TRUE(hasWarning(s, "cameras[0] has type \"fisheye\", which glTF 2.0 does not define: skipped"));
  EXPECT_TRUE(hasWarning(s, "lights[0] has type \"area\", which KHR_lights_punctual does not define: skipped"));
}

TEST_F(Synthesised, DeepHierarchyDoesNotOverflowTheStack) {
  GltfBuilder b;
  const int n = 100000;
  b.doc["nodes"] = Json::array();
  for (int i = 0; i < n; ++i) b.doc["nodes"].push_back(i + 1 < n ? Json{{"children", {i + 1}}} : Json::object());
  b.doc["nodes"][n - 1]["mesh"] = b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.doc["nodes"][0]["translation"] = {1, 0, 0};
  const Scene s = load(b.finish());
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.bounds.lo, Vec3(1, 0, 0));
}

}  // namespace
}  // namespace relt::test

namespace relt::test {

// A small file can instance a mesh into more triangles than any machine holds: refused by count
// before the instances are built (100 000 triangles x 50 000 nodes = 5e9 > 2^32).
TEST_F(Synthesised, InstancingBeyondMemoryIsRefusedBeforeBuilding) {
  GltfBuilder b;
  std::vector<uint16_t> idx;
  for (int t = 0; t < 100000; ++t) idx.insert(idx.end(), {0, 1, 2});
  const int mesh = b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, idx);
  std::vector<int> roots;
  for (int n = 0; n < 50000; ++n) roots.push_back(b.node({{"mesh", mesh}, {"translation", {n, 0, 0}}}));
  b.scene(roots);
  EXPECT_TRUE(contains(loadError(b.finish()), "nodes: the scene instances 5000000000 triangles"));
}

}  // namespace relt::test

namespace relt::test {

// Coordinates beyond 1e15 overflow single-precision distances (and Embree refuses rays from
// there): found by fuzzing a scene whose buffer bytes were changed. Vertices (here moved by a
// node's scale), cameras and lights alike.
TEST_F(Synthesised, CoordinatesBeyondTheWorldLimitAreRefused) {
  GltfBuilder b;
  const int mesh = b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.node({{"mesh", mesh}, {"scale", {2e15, 1, 1}}});
  b.scene({0});
  EXPECT_TRUE(contains(loadError(b.finish()), "nodes[0]: vertex 1 lies at (2e+15, 0, 0) in world space, beyond +-1e15"));
  GltfBuilder c;
  c.camera();
  c.node({{"camera", 0}, {"translation", {0, -3e16, 0}}});
  c.scene({0});
  EXPECT_TRUE(contains(loadError(c.finish()), "nodes[0]: its camera lies at (0, -3e+16, 0)"));
  GltfBuilder edge;
  const int m = edge.triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  edge.node({{"mesh", m}, {"scale", {1e15, 1, 1}}});
  edge.scene({0});
  EXPECT_EQ(load(edge.finish()).bounds.hi.x, 1e15f) << "the limit itself is inside";
}

}  // namespace relt::test
