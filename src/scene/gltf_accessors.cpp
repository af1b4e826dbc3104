#include "scene/gltf_accessors.h"

#include <cstring>

namespace relt::gltf {

namespace {

constexpr uint32_t kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
                   kFloat = 5126;

uint32_t componentSize(uint32_t type) {
  switch (type) {
    case kByte:
    case kUnsignedByte:
      return 1;
    case kShort:
    case kUnsignedShort:
      return 2;
    default:
      return 4;
  }
}

uint32_t componentsOf(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

// Accessors without a bufferView are materialised as zeros: cap them so a count in the file
// cannot make us allocate without bound.
constexpr uint64_t kMaxSyntheticBytes = uint64_t(1) << 28;

std::string byteRange(uint64_t begin, uint64_t end) {
  return "bytes [" + std::to_string(begin) + ", " + std::to_string(end) + ")";
}

std::vector<BufferDecl> parseBuffers(const Context& ctx, const Json& doc) {
  std::vector<BufferDecl> buffers(arraySize(ctx, doc, "buffers"));
  for (size_t i = 0; i < buffers.size(); ++i) {
    const std::string element = indexed("buffers", i);
    const Json& o = arrayObject(ctx, doc, "buffers", i);
    buffers[i].byteLength = requireUInt(ctx, o, "byteLength", element);
    if (buffers[i].byteLength == 0) ctx.fail(element, "byteLength must be at least 1");
    buffers[i].uri = getString(ctx, o, "uri", element);
  }
  return buffers;
}

std::vector<BufferView> parseViews(const Context& ctx, const Json& doc, size_t bufferCount) {
  std::vector<BufferView> views(arraySize(ctx, doc, "bufferViews"));
  for (size_t i = 0; i < views.size(); ++i) {
    const std::string element = indexed("bufferViews", i);
    const Json& o = arrayObject(ctx, doc, "bufferViews", i);
    BufferView& v = views[i];
    v.buffer = requireIndex(ctx, o, "buffer", element, "buffers", bufferCount);
    v.byteOffset = getUInt(ctx, o, "byteOffset", element).value_or(0);
    v.byteLength = requireUInt(ctx, o, "byteLength", element);
    if (v.byteLength == 0) ctx.fail(element, "byteLength must be at least 1");
    const uint64_t stride = getUInt(ctx, o, "byteStride", element).value_or(0);
    if (stride != 0 && (stride < 4 || stride > 252 || stride % 4 != 0))
      ctx.fail(element, "byteStride " + std::to_string(stride) + " must be a multiple of 4 between 4 and 252");
    v.byteStride = static_cast<uint32_t>(stride);
  }
  return views;
}

std::vector<Accessor> parseAccessors(const Context& ctx, const Json& doc, size_t viewCount) {
  std::vector<Accessor> accessors(arraySize(ctx, doc, "accessors"));
  for (size_t i = 0; i < accessors.size(); ++i) {
    const std::string element = indexed("accessors", i);
    const Json& o = arrayObject(ctx, doc, "accessors", i);
    Accessor& a = accessors[i];
    a.bufferView = getIndex(ctx, o, "bufferView", element, "bufferViews", viewCount);
    a.byteOffset = getUInt(ctx, o, "byteOffset", element).value_or(0);
    if (a.byteOffset != 0 && !a.bufferView) ctx.fail(element, "byteOffset is set but bufferView is not");
    a.componentType =
        static_cast<uint32_t>(std::min<uint64_t>(requireUInt(ctx, o, "componentType", element), 0xFFFFFFFF));
    if (std::string(componentTypeName(a.componentType)).empty())
      ctx.fail(element, "componentType " + std::to_string(a.componentType) + " is not a valid glTF 2.0 component type");
    a.type = getString(ctx, o, "type", element).value_or("");
    a.components = componentsOf(a.type);
    if (a.components == 0)
      ctx.fail(element, "type " + brief(o.value("type", Json())) + " is not a valid accessor type");
    a.count = requireUInt(ctx, o, "count", element);
    if (a.count == 0) ctx.fail(element, "count must be at least 1");
    if (!a.bufferView && a.count * a.elementSize() > kMaxSyntheticBytes)
      ctx.fail(element, "count " + std::to_string(a.count) + " is too large for an accessor without a bufferView");

    if (const Json* sparse = getObject(ctx, o, "sparse", element)) {
      const std::string se = element + ".sparse";
      SparseAccessor s;
      s.count = requireUInt(ctx, *sparse, "count", se);
      if (s.count == 0) ctx.fail(se, "count must be at least 1");
      if (s.count > a.count)
        ctx.fail(
            se, "count " + std::to_string(s.count) + " is larger than the accessor's count " + std::to_string(a.count));
      const Json* indices = getObject(ctx, *sparse, "indices", se);
      const Json* values = getObject(ctx, *sparse, "values", se);
      if (!indices) ctx.fail(se, "indices is missing");
      if (!values) ctx.fail(se, "values is missing");
      s.indicesView = requireIndex(ctx, *indices, "bufferView", se + ".indices", "bufferViews", viewCount);
      s.indicesOffset = getUInt(ctx, *indices, "byteOffset", se + ".indices").value_or(0);
      s.indexType = static_cast<uint32_t>(
          std::min<uint64_t>(requireUInt(ctx, *indices, "componentType", se + ".indices"), 0xFFFFFFFF));
      if (s.indexType != kUnsignedByte && s.indexType != kUnsignedShort && s.indexType != kUnsignedInt)
        ctx.fail(se + ".indices", "componentType must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
      s.valuesView = requireIndex(ctx, *values, "bufferView", se + ".values", "bufferViews", viewCount);
      s.valuesOffset = getUInt(ctx, *values, "byteOffset", se + ".values").value_or(0);
      a.sparse = s;
    }
  }
  return accessors;
}

void checkViewRanges(const Context& ctx, const std::vector<BufferView>& views, const std::vector<BufferDecl>& buffers) {
  for (size_t i = 0; i < views.size(); ++i) {
    const BufferView& v = views[i];
    const uint64_t end = v.byteOffset + v.byteLength;  // both <= 2^53: no overflow
    if (end > buffers[v.buffer].byteLength)
      ctx.fail(indexed("bufferViews", i), byteRange(v.byteOffset, end) + " lie outside " +
                                              indexed("buffers", v.buffer) + " (byteLength " +
                                              std::to_string(buffers[v.buffer].byteLength) + ")");
  }
}

void checkAccessorRanges(const Context& ctx, const std::vector<Accessor>& accessors,
                         const std::vector<BufferView>& views) {
  for (size_t i = 0; i < accessors.size(); ++i) {
    const std::string element = indexed("accessors", i);
    const Accessor& a = accessors[i];
    const uint64_t elem = a.elementSize();
    if (a.bufferView) {
      const BufferView& v = views[*a.bufferView];
      const uint64_t stride = v.byteStride ? v.byteStride : elem;
      if (stride < elem)
        ctx.fail(element, "elements of " + std::to_string(elem) + " bytes do not fit the byteStride " +
                              std::to_string(stride) + " of " + indexed("bufferViews", *a.bufferView));
      // count <= 2^53 and stride <= 252 would overflow only past 2^61; bound count first.
      if (a.count > v.byteLength || a.byteOffset > v.byteLength)
        ctx.fail(element, "count " + std::to_string(a.count) + " and byteOffset " + std::to_string(a.byteOffset) +
                              " do not fit in " + indexed("bufferViews", *a.bufferView) + " (byteLength " +
                              std::to_string(v.byteLength) + ")");
      const uint64_t end = a.byteOffset + stride * (a.count - 1) + elem;
      if (end > v.byteLength)
        ctx.fail(element, "its elements occupy " + byteRange(a.byteOffset, end) + " of " +
                              indexed("bufferViews", *a.bufferView) + ", which has only " +
                              std::to_string(v.byteLength) + " bytes");
    }
    if (a.sparse) {
      const SparseAccessor& s = *a.sparse;
      auto checkPacked = [&](uint32_t view, uint64_t offset, uint64_t bytes, const std::string& part) {
        const BufferView& v = views[view];
        if (v.byteStride != 0)
          ctx.fail(element + ".sparse." + part, indexed("bufferViews", view) + " must not have a byteStride");
        if (offset > v.byteLength || bytes > v.byteLength - offset)
          ctx.fail(element + ".sparse." + part, byteRange(offset, offset + bytes) + " lie outside " +
                                                    indexed("bufferViews", view) + " (byteLength " +
                                                    std::to_string(v.byteLength) + ")");
      };
      checkPacked(s.indicesView, s.indicesOffset, s.count * componentSize(s.indexType), "indices");
      checkPacked(s.valuesView, s.valuesOffset, s.count * elem, "values");
    }
  }
}

}  // namespace

uint64_t Accessor::elementSize() const { return uint64_t(componentSize(componentType)) * components; }

const char* componentTypeName(uint32_t componentType) {
  switch (componentType) {
    case kByte:
      return "BYTE";
    case kUnsignedByte:
      return "UNSIGNED_BYTE";
    case kShort:
      return "SHORT";
    case kUnsignedShort:
      return "UNSIGNED_SHORT";
    case kUnsignedInt:
      return "UNSIGNED_INT";
    case kFloat:
      return "FLOAT";
    default:
      return "";
  }
}

BufferLayout parseBufferLayout(const Context& ctx, const Json& doc) {
  // Sizes first so that references can be checked in the order a reader follows them
  // (accessor -> view -> buffer), which gives the most useful first error.
  const size_t viewCount = arraySize(ctx, doc, "bufferViews");
  const size_t bufferCount = arraySize(ctx, doc, "buffers");
  BufferLayout layout;
  layout.accessors = parseAccessors(ctx, doc, viewCount);
  layout.views = parseViews(ctx, doc, bufferCount);
  layout.buffers = parseBuffers(ctx, doc);
  checkViewRanges(ctx, layout.views, layout.buffers);
  checkAccessorRanges(ctx, layout.accessors, layout.views);
  return layout;
}

const uint8_t* AccessorReader::viewData(uint32_t view, uint64_t offset, uint64_t bytes,
                                        const std::string& element) const {
  // parseBufferLayout proved these ranges against the declared lengths and loadBufferBytes proved
  // each buffer at least that long; check again so a broken invariant cannot read out of bounds.
  const BufferView& v = layout_.views[view];
  const std::vector<uint8_t>& buffer = buffers_[v.buffer];
  if (buffer.empty())  // byteLength >= 1, so only a buffer without data is empty
    ctx_.fail(indexed("buffers", v.buffer), "has no uri (only the first buffer of a .glb file may omit it), but " +
                                                element + " reads from it");
  if (offset > v.byteLength || bytes > v.byteLength - offset || v.byteOffset + v.byteLength > buffer.size())
    ctx_.fail(element, "internal error: accessor range outside its buffer");
  return buffer.data() + v.byteOffset + offset;
}

std::vector<uint8_t> AccessorReader::gather(uint32_t index) const {
  const std::string element = indexed("accessors", index);
  const Accessor& a = layout_.accessors[index];
  const size_t elem = a.elementSize();
  std::vector<uint8_t> out(a.count * elem, 0);
  if (a.bufferView) {
    const BufferView& v = layout_.views[*a.bufferView];
    const size_t stride = v.byteStride ? v.byteStride : elem;
    const uint8_t* src = viewData(*a.bufferView, a.byteOffset, stride * (a.count - 1) + elem, element);
    if (stride == elem) {
      std::memcpy(out.data(), src, out.size());
    } else {
      for (size_t e = 0; e < a.count; ++e) std::memcpy(out.data() + e * elem, src + e * stride, elem);
    }
  }
  if (a.sparse) {
    const SparseAccessor& s = *a.sparse;
    const size_t indexSize = componentSize(s.indexType);
    const uint8_t* indices = viewData(s.indicesView, s.indicesOffset, s.count * indexSize, element);
    const uint8_t* values = viewData(s.valuesView, s.valuesOffset, s.count * elem, element);
    for (size_t k = 0; k < s.count; ++k) {
      uint32_t target = 0;
      if (indexSize == 1) {
        target = indices[k];
      } else if (indexSize == 2) {
        uint16_t t;
        std::memcpy(&t, indices + 2 * k, 2);
        target = t;
      } else {
        std::memcpy(&target, indices + 4 * k, 4);
      }
      if (target >= a.count)
        ctx_.fail(element + ".sparse",
                  "index " + std::to_string(target) + " is out of range (count " + std::to_string(a.count) + ")");
      std::memcpy(out.data() + size_t(target) * elem, values + k * elem, elem);
    }
  }
  return out;
}

std::vector<Vec3> AccessorReader::readVec3(uint32_t index, const std::string& user, const std::string& semantic) const {
  const Accessor& a = layout_.accessors[index];
  if (a.componentType != kFloat || a.type != "VEC3") {
    std::string reason = semantic + " (" + indexed("accessors", index) + ") must be FLOAT VEC3, got " +
                         componentTypeName(a.componentType) + " " + a.type;
    if (a.componentType != kFloat) reason += "; quantized attributes (KHR_mesh_quantization) are not supported";
    ctx_.fail(user, reason);
  }
  const std::vector<uint8_t> raw = gather(index);
  std::vector<Vec3> out(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    float xyz[3];
    std::memcpy(xyz, raw.data() + 12 * i, 12);
    out[i] = Vec3(xyz[0], xyz[1], xyz[2]);
  }
  return out;
}

uint32_t AccessorReader::restartValue(uint32_t index) const {
  const uint32_t t = layout_.accessors[index].componentType;
  return t == kUnsignedByte ? 0xFFu : t == kUnsignedShort ? 0xFFFFu : 0xFFFFFFFFu;
}

std::vector<uint32_t> AccessorReader::readIndices(uint32_t index, const std::string& user) const {
  const Accessor& a = layout_.accessors[index];
  const uint32_t t = a.componentType;
  if (a.type != "SCALAR" || (t != kUnsignedByte && t != kUnsignedShort && t != kUnsignedInt))
    ctx_.fail(user, "indices (" + indexed("accessors", index) +
                        ") must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT SCALAR, got " + componentTypeName(t) +
                        " " + a.type);
  const std::vector<uint8_t> raw = gather(index);
  std::vector<uint32_t> out(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    if (t == kUnsignedByte) {
      out[i] = raw[i];
    } else if (t == kUnsignedShort) {
      uint16_t v;
      std::memcpy(&v, raw.data() + 2 * i, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], raw.data() + 4 * i, 4);
    }
  }
  return out;
}

}  // namespace relt::gltf
