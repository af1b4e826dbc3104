// `relt info`'s summary and the renderability check, on scenes loaded from synthesised glTF files.
#include <gtest/gtest.h>

#include "gltf_test_support.h"
#include "scene/scene_summary.h"

namespace relt::test {
namespace {

class SceneSummary : public TempDirTest {
 protected:
  // A quad with the given material, a camera node and optionally a point light of `light` intensity.
  Json quadScene(const Json& material, double light = -1.0) {
    GltfBuilder b;
    b.material(material);
    b.node({{"mesh", b.triangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 0, 2, 3}, 0)}});
    b.camera(0.5);
    b.doc["cameras"][0]["name"] = "front";
    b.node({{"camera", 0}, {"translation", {0.5, 0.5, 2}}});
    if (light >= 0.0) {
      b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", light}}};
      b.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    }
    b.scene({0, 1, 2}, {{"width", 64}, {"height", 48}, {"bench_width", 16}});
    if (light < 0.0) b.doc["scenes"][0]["nodes"] = {0, 1};
    return b.finish();
  }

  // The InputError checkRenderable throws, as "element: reason"; empty if it does not throw.
  std::string renderableError(const Scene& s) {
    try {
      checkRenderable(s);
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), s.file);
      return e.element() + ": " + e.reason();
    }
    return "";
  }

  const Json kEmissive = {{"emissiveFactor", {1, 1, 1}}, {"pbrMetallicRoughness", {{"metallicFactor", 0}}}};
  const Json kDiffuse = {{"pbrMetallicRoughness", {{"metallicFactor", 0}}}};
};

TEST_F(SceneSummary, ListsTrianglesMaterialsCamerasBoundsDefaultsAndWarnings) {
  Json doc = quadScene(kEmissive, 5.0);
  doc["extensionsUsed"] = {"KHR_texture_transform"};
  const Scene s = load(doc);
  const std::string text = summarizeScene(s);
  for (const char* part :
       {"triangles: 2 (emissive 2)", "materials: 1 (lambert 1, conductor 0, dielectric 0; emissive 1)",
        "punctual lights: 1 (point 1, spot 0)", "cameras: 1", "\"front\": yfov 28.65 deg",
        "bounds: (0, 0, 0) to (1, 1, 0)", "render defaults: 64x48, max depth 8, bench 16x48", "warnings: 1",
        "KHR_texture_transform"})
    EXPECT_NE(text.find(part), std::string::npos) << "missing \"" << part << "\" in\n" << text;
}

TEST_F(SceneSummary, RenderableSceneHasCameraAndEmitter) {
  EXPECT_EQ(renderableError(load(quadScene(kEmissive))), "");
  EXPECT_EQ(renderableError(load(quadScene(kDiffuse, 2.0))), "");  // a point light is enough
}

TEST_F(SceneSummary, SceneWithoutCameraIsNotRenderable) {
  Json doc = quadScene(kEmissive);
  doc["scenes"][0]["nodes"] = Json::array({0});
  EXPECT_EQ(renderableError(load(doc)).rfind("scene: no camera", 0), 0u);
}

TEST_F(SceneSummary, SceneWithoutEmitterIsNotRenderable) {
  const std::string expected = "scene: no emitter";
  EXPECT_EQ(renderableError(load(quadScene(kDiffuse))).rfind(expected, 0), 0u);
  EXPECT_EQ(renderableError(load(quadScene(kDiffuse, 0.0))).rfind(expected, 0), 0u);  // a black light emits nothing
  EXPECT_NE(renderableError(load(quadScene(kDiffuse))).find("add an emissive material or a KHR_lights_punctual light"),
            std::string::npos);
}

TEST_F(SceneSummary, ZeroAreaEmissiveTriangleIsNoEmitter) {
  Scene s = load(quadScene(kEmissive));
  ASSERT_EQ(renderableError(s), "");
  for (Vec3& p : s.positions) p = Vec3(0.0f);  // the loader drops such triangles; the check must not count them
  EXPECT_EQ(renderableError(s).rfind("scene: no emitter", 0), 0u);
}

}  // namespace
}  // namespace relt::test

namespace relt::test {
namespace {

// Radiance that overflows single precision once multiplied along a path is refused, for emissive
// materials and punctual lights alike; bright but physical sources (the sun is ~1e9) are fine.
TEST_F(SceneSummary, AbsurdlyBrightSourcesAreNotRenderable) {
  Json hot = kEmissive;
  hot["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e38;
  EXPECT_NE(renderableError(load(quadScene(hot))).find("above 1e15 would overflow single precision"), std::string::npos);
  EXPECT_NE(renderableError(load(quadScene(kDiffuse, 1e30))).find("intensity above 1e15"), std::string::npos);
  Json bright = kEmissive;
  bright["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e9;
  EXPECT_EQ(renderableError(load(quadScene(bright))), "");
}

}  // namespace
}  // namespace relt::test
