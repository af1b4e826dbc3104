#pragma once
// Helpers for the glTF loader tests: a builder that writes small glTF files with embedded base64
// buffers, and a per-test temporary directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/math.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

namespace relt::test {

using Json = nlohmann::json;

inline std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                   b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const uint32_t v = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

// Builds a glTF document with one buffer. Indices returned are glTF array indices.
class GltfBuilder {
 public:
  static constexpr int kUByte = 5121, kUShort = 5123, kUInt = 5125, kFloat = 5126;

  Json doc = {{"asset", {{"version", "2.0"}}}};
  std::vector<uint8_t> bin;

  int addView(const void* data, size_t bytes, int stride = 0) {
    while (bin.size() % 4) bin.push_back(0);
    Json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (stride) view["byteStride"] = stride;
    bin.insert(bin.end(), static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + bytes);
    return push("bufferViews", view);
  }
  int addAccessor(int view, int componentType, size_t count, const char* type, size_t byteOffset = 0) {
    Json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
    if (view >= 0) a["bufferView"] = view;
    if (byteOffset) a["byteOffset"] = byteOffset;
    return push("accessors", a);
  }
  int positions(const std::vector<Vec3>& p) {
    return addAccessor(addView(p.data(), p.size() * sizeof(Vec3)), kFloat, p.size(), "VEC3");
  }
  template <class T>
  int indices(const std::vector<T>& idx) {
    const int type = sizeof(T) == 1 ? kUByte : sizeof(T) == 2 ? kUShort : kUInt;
    return addAccessor(addView(idx.data(), idx.size() * sizeof(T)), type, idx.size(), "SCALAR");
  }
  int mesh(const Json& primitive) { return push("meshes", Json{{"primitives", Json::array({primitive})}}); }
  // A mesh of one primitive from positions and (optional) u16 indices.
  int triangleMesh(const std::vector<Vec3>& p, const std::vector<uint16_t>& idx = {}, int material = -1,
                   int mode = -1) {
    Json prim = {{"attributes", {{"POSITION", positions(p)}}}};
    if (!idx.empty()) prim["indices"] = indices(idx);
    if (material >= 0) prim["material"] = material;
    if (mode >= 0) prim["mode"] = mode;
    return mesh(prim);
  }
  int node(const Json& n) { return push("nodes", n); }
  int material(const Json& m) { return push("materials", m); }
  int camera(double yfov = 0.8) {
    return push("cameras", Json{{"type", "perspective"}, {"perspective", {{"yfov", yfov}, {"znear", 0.01}}}});
  }
  void scene(const std::vector<int>& roots, const Json& extras = Json()) {
    Json s = {{"nodes", roots}};
    if (!extras.is_null()) s["extras"] = extras;
    push("scenes", s);
  }

  Json finish() const {
    Json d = doc;
    if (!bin.empty())
      d["buffers"] =
          Json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
    return d;
  }

 private:
  int push(const char* key, const Json& v) {
    doc[key].push_back(v);
    return static_cast<int>(doc[key].size()) - 1;
  }
};

// A fresh directory per test (tests may run as parallel processes).
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("relt_gltf_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::string writeText(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::string writeJson(const Json& doc, const std::string& name = "scene.gltf") { return writeText(name, doc.dump()); }
  Scene load(const Json& doc) { return loadGltf(writeJson(doc)); }
  // The message of the InputError loading `doc` throws; fails the test if it does not throw.
  std::string loadError(const Json& doc) {
    const std::string path = writeJson(doc);
    try {
      loadGltf(path);
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      return e.what();
    }
    ADD_FAILURE() << "expected an InputError";
    return "";
  }

  std::filesystem::path dir_;
};

}  // namespace relt::test
