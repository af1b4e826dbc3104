#pragma once
// Reading a glTF file: the .gltf JSON text or the .glb container (header, JSON chunk, BIN chunk),
// and the bytes of each buffer (data: URI, external file or the GLB BIN chunk).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/gltf_json.h"

namespace relt::gltf {

struct GltfSource {
  Json doc;                                 // the root object
  std::optional<std::vector<uint8_t>> bin;  // the GLB BIN chunk, if any
  std::filesystem::path dir;                // where relative URIs are resolved
  bool glb = false;
};

// Reads and parses the file; the container layout and the JSON syntax are checked here.
GltfSource readGltfSource(Context& ctx, const std::string& path);

// Standard base64 (RFC 4648) with optional '=' padding; nullopt on any other character.
std::optional<std::vector<uint8_t>> decodeBase64(std::string_view text);

// The bytes of buffers[index], at least byteLength of them (only the first byteLength are used).
// buffers[0] of a .glb file takes the BIN chunk out of `src`. Any other buffer without a uri gives
// no bytes: glTF allows such a buffer (the validator accepts it, and compression extensions use
// one as a fallback), so only reading from it fails, in AccessorReader.
std::vector<uint8_t> loadBufferBytes(const Context& ctx, GltfSource& src, size_t index,
                                     const std::optional<std::string>& uri, uint64_t byteLength);

}  // namespace relt::gltf
