#pragma once
// glTF buffers, buffer views and accessors: parsing, range validation against the declared buffer
// lengths (before any data is read), and reading elements with byteStride and sparse substitution.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/gltf_json.h"

namespace relt::gltf {

struct BufferDecl {
  uint64_t byteLength = 0;
  std::optional<std::string> uri;
};

struct BufferView {
  uint32_t buffer = 0;
  uint64_t byteOffset = 0, byteLength = 0;
  uint32_t byteStride = 0;  // 0: tightly packed (absent, or the legacy value 0)
};

struct SparseAccessor {
  uint64_t count = 0;
  uint32_t indicesView = 0, indexType = 0;
  uint64_t indicesOffset = 0;
  uint32_t valuesView = 0;
  uint64_t valuesOffset = 0;
};

struct Accessor {
  std::optional<uint32_t> bufferView;  // absent: all zeros (before sparse substitution)
  uint64_t byteOffset = 0;
  uint32_t componentType = 0;
  uint32_t components = 0;  // 1 (SCALAR) .. 16 (MAT4)
  std::string type;         // "SCALAR", "VEC3", ...
  uint64_t count = 0;
  std::optional<SparseAccessor> sparse;

  uint64_t elementSize() const;
};

struct BufferLayout {
  std::vector<BufferDecl> buffers;
  std::vector<BufferView> views;
  std::vector<Accessor> accessors;
};

// Parses accessors, bufferViews and buffers and checks that every byte range an accessor can touch
// lies inside its view and every view inside its buffer's declared byteLength.
BufferLayout parseBufferLayout(const Context& ctx, const Json& doc);

const char* componentTypeName(uint32_t componentType);

// Reads accessor data from loaded buffers (each at least its declared byteLength long, or empty for
// a buffer without data: reading from that one fails).
class AccessorReader {
 public:
  AccessorReader(const Context& ctx, const BufferLayout& layout, const std::vector<std::vector<uint8_t>>& buffers)
      : ctx_(ctx), layout_(layout), buffers_(buffers) {}

  // A FLOAT VEC3 attribute; `user` and `semantic` name the referencing element in messages.
  std::vector<Vec3> readVec3(uint32_t accessor, const std::string& user, const std::string& semantic) const;
  // Vertex indices: UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT scalars.
  std::vector<uint32_t> readIndices(uint32_t accessor, const std::string& user) const;
  // The largest value of an index accessor's component type: the primitive restart value.
  uint32_t restartValue(uint32_t accessor) const;
  uint64_t count(uint32_t accessor) const { return layout_.accessors[accessor].count; }

 private:
  // The accessor's elements, tightly packed, with sparse values substituted.
  std::vector<uint8_t> gather(uint32_t accessor) const;
  const uint8_t* viewData(uint32_t view, uint64_t offset, uint64_t bytes, const std::string& element) const;

  const Context& ctx_;
  const BufferLayout& layout_;
  const std::vector<std::vector<uint8_t>>& buffers_;
};

}  // namespace relt::gltf
