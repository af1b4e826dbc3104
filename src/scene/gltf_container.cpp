#include "scene/gltf_container.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/file.h"

namespace relt::gltf {

static_assert(std::endian::native == std::endian::little, "glTF binary data is little-endian");

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t offset) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string chunkName(uint32_t type) {
  if (type == kChunkJson) return "JSON";
  if (type == kChunkBin) return "BIN";
  return "unknown";
}

// Splits a GLB container (glTF 2.0 spec, "GLB File Format Specification") into its JSON text and
// BIN chunk, checking every length against the bytes actually present.
void splitGlb(Context& ctx, const std::vector<uint8_t>& bytes, std::string* json,
              std::optional<std::vector<uint8_t>>* bin) {
  const std::string element = "GLB";
  if (bytes.size() < 12)
    ctx.fail(element, "truncated header: the file has " + std::to_string(bytes.size()) +
                          " bytes, fewer than the 12-byte GLB header");
  if (readU32(bytes, 0) != kGlbMagic) ctx.fail(element, "invalid magic: the file does not start with 'glTF'");
  const uint32_t version = readU32(bytes, 4);
  if (version != 2)
    ctx.fail(element, "container version " + std::to_string(version) + " is not supported (expected 2)");
  const uint32_t length = readU32(bytes, 8);
  if (length > bytes.size() || length < 12)
    ctx.fail(element, "the header declares " + std::to_string(length) + " bytes but the file has " +
                          std::to_string(bytes.size()) + " (truncated or corrupt)");
  // Bytes after the declared length are outside the GLB (the validator's GLB_EXTRA_DATA warning).
  if (length < bytes.size())
    ctx.warn("GLB: " + std::to_string(bytes.size() - length) + " bytes after the declared length are ignored");
  size_t offset = 12;
  bool haveJson = false;
  for (int chunk = 0; offset < length; ++chunk) {
    const std::string chunkElement = "GLB chunk " + std::to_string(chunk);
    if (length - offset < 8) ctx.fail(chunkElement, "truncated chunk header");
    const uint32_t chunkLength = readU32(bytes, offset);
    const uint32_t type = readU32(bytes, offset + 4);
    offset += 8;
    if (chunkLength > length - offset)
      ctx.fail(chunkElement, chunkName(type) + " chunk declares " + std::to_string(chunkLength) + " bytes but only " +
                                 std::to_string(length - offset) + " remain (truncated or corrupt)");
    const auto begin = bytes.begin() + static_cast<std::ptrdiff_t>(offset);
    const auto end = begin + static_cast<std::ptrdiff_t>(chunkLength);
    if (chunk == 0) {
      if (type != kChunkJson) ctx.fail(chunkElement, "the first chunk must be JSON");
      json->assign(begin, end);
      haveJson = true;
    } else if (type == kChunkJson) {
      ctx.fail(chunkElement, "a GLB file has exactly one JSON chunk");
    } else if (type == kChunkBin) {
      if (chunk != 1) ctx.fail(chunkElement, "the BIN chunk must directly follow the JSON chunk");
      bin->emplace(begin, end);
    }
    // Chunks of other types are skipped, as the GLB specification asks.
    offset += chunkLength;
  }
  if (!haveJson) ctx.fail(element, "the file has no JSON chunk");
}

std::string percentDecode(const std::string& s) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && hex(s[i + 1]) >= 0 && hex(s[i + 2]) >= 0) {
      out += static_cast<char>(hex(s[i + 1]) * 16 + hex(s[i + 2]));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

}  // namespace

GltfSource readGltfSource(Context& ctx, const std::string& path) {
  std::string reason;
  std::optional<std::vector<uint8_t>> bytes = readWholeFile(path, &reason);
  if (!bytes) ctx.fail("", "cannot read the file: " + reason);
  if (bytes->empty()) ctx.fail("", "the file is empty");

  GltfSource src;
  src.dir = std::filesystem::path(path).parent_path();
  const bool glbMagic = bytes->size() >= 4 && readU32(*bytes, 0) == kGlbMagic;
  src.glb = lowerExtension(path) == ".glb" || glbMagic;

  std::string text;
  if (src.glb) {
    splitGlb(ctx, *bytes, &text, &src.bin);
  } else {
    text.assign(bytes->begin(), bytes->end());
  }
  bytes.reset();

  try {
    src.doc = Json::parse(text);
  } catch (const Json::exception& e) {
    // nlohmann prefixes "[json.exception.parse_error.101] "; the rest is already one line.
    std::string what = e.what();
    const size_t cut = what.find("] ");
    if (cut != std::string::npos) what = what.substr(cut + 2);
    ctx.fail("", "invalid JSON: " + printable(what, 200));
  }
  if (!src.doc.is_object()) ctx.fail("", "the top level of a glTF file must be a JSON object, got " + brief(src.doc));
  return src;
}

std::optional<std::vector<uint8_t>> decodeBase64(std::string_view text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  size_t n = text.size();
  size_t padding = 0;
  while (n > 0 && text[n - 1] == '=' && padding < 2) {
    --n;
    ++padding;
  }
  if (padding > 0 && (n + padding) % 4 != 0) return std::nullopt;
  if (n % 4 == 1) return std::nullopt;  // a lone sextet cannot encode a byte
  std::vector<uint8_t> out;
  out.reserve(n / 4 * 3 + 2);
  uint32_t acc = 0;
  int bits = 0;
  for (size_t i = 0; i < n; ++i) {
    const int v = value(text[i]);
    if (v < 0) return std::nullopt;
    acc = (acc << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<uint8_t>((acc >> bits) & 0xFF));
    }
  }
  return out;
}

std::vector<uint8_t> loadBufferBytes(const Context& ctx, GltfSource& src, size_t index,
                                     const std::optional<std::string>& uri, uint64_t byteLength) {
  const std::string element = indexed("buffers", index);
  std::vector<uint8_t> data;
  std::string origin;
  if (!uri) {
    if (!src.glb || index != 0) return data;  // no data; an accessor that reads it fails
    if (!src.bin) ctx.fail(element, "refers to the GLB BIN chunk, but the file has none");
    data = std::move(*src.bin);  // only buffers[0] can use it, so it can be moved
    src.bin.reset();
    origin = "the GLB BIN chunk";
  } else if (uri->rfind("data:", 0) == 0) {
    const size_t comma = uri->find(',');
    const std::string header = comma == std::string::npos ? std::string() : uri->substr(5, comma - 5);
    const std::string suffix = ";base64";
    const bool base64 =
        header.size() >= suffix.size() && header.compare(header.size() - suffix.size(), suffix.size(), suffix) == 0;
    const std::string mime = base64 ? header.substr(0, header.size() - suffix.size()) : header;
    if (comma == std::string::npos || !base64 ||
        (mime != "application/octet-stream" && mime != "application/gltf-buffer"))
      ctx.fail(element, "malformed data URI " + brief(Json(uri->substr(0, std::min<size_t>(uri->size(), 48)))) +
                            " (expected data:application/octet-stream;base64,...)");
    std::optional<std::vector<uint8_t>> decoded = decodeBase64(std::string_view(*uri).substr(comma + 1));
    if (!decoded) ctx.fail(element, "the data URI is not valid base64");
    data = std::move(*decoded);
    origin = "its data URI";
  } else {
    if (uri->find("://") != std::string::npos)
      ctx.fail(element,
               "uri " + brief(Json(*uri)) + " is remote; only relative file paths and data URIs are supported");
    const std::filesystem::path file = src.dir / percentDecode(*uri);
    std::string reason;
    std::optional<std::vector<uint8_t>> bytes = readWholeFile(file, &reason);
    if (!bytes) ctx.fail(element, "cannot read " + brief(Json(*uri)) + ": " + reason);
    data = std::move(*bytes);
    origin = "file " + brief(Json(*uri));
  }
  if (data.size() < byteLength)
    ctx.fail(element, "byteLength " + std::to_string(byteLength) + " is larger than the " +
                          std::to_string(data.size()) + " bytes of " + origin);
  return data;
}

}  // namespace relt::gltf
