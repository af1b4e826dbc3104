#include "scene/gltf_json.h"

#include <algorithm>

#include "core/error.h"

namespace relt::gltf {

void Context::fail(const std::string& element, const std::string& reason) const {
  throw InputError(file_, element, reason);
}

void Context::warn(const std::string& line) {
  if (std::find(warnings_.begin(), warnings_.end(), line) == warnings_.end()) warnings_.push_back(line);
}

std::string indexed(const std::string& array, size_t i) { return array + "[" + std::to_string(i) + "]"; }

std::string brief(const Json& v) {
  // replace: a string with invalid UTF-8 must still print rather than throw.
  std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';  // messages are one line
  if (s.size() > 48) s = s.substr(0, 45) + "...";
  return s;
}

std::string printable(const std::string& s, size_t maxLength) {
  std::string out = s.size() > maxLength ? s.substr(0, maxLength - 3) + "..." : s;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return out;
}

namespace {

const Json& requireObjectValue(const Context& ctx, const Json& obj, const std::string& element) {
  if (!obj.is_object()) ctx.fail(element, "must be a JSON object, got " + brief(obj));
  return obj;
}

std::optional<uint64_t> asUInt(const Json& v) {
  if (v.is_number_unsigned()) return v.get<uint64_t>();
  if (v.is_number_integer() && v.get<int64_t>() >= 0) return static_cast<uint64_t>(v.get<int64_t>());
  // JSON Schema 2020-12, which glTF 2.0's schema follows, counts 14.0 as an integer (and so does
  // the validator). Beyond 2^53 a double no longer holds every integer: left to the callers' limit.
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (d >= 0.0 && d <= double(kMaxJsonInteger) && d == std::floor(d)) return static_cast<uint64_t>(d);
  }
  return std::nullopt;
}

}  // namespace

const Json* getMember(const Context& ctx, const Json& obj, const char* key, const std::string& element) {
  requireObjectValue(ctx, obj, element);
  auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const Json* getObject(const Context& ctx, const Json& obj, const char* key, const std::string& element) {
  const Json* v = getMember(ctx, obj, key, element);
  if (v && !v->is_object()) ctx.fail(element, std::string(key) + " must be a JSON object, got " + brief(*v));
  return v;
}

const Json* getArray(const Context& ctx, const Json& obj, const char* key, const std::string& element) {
  const Json* v = getMember(ctx, obj, key, element);
  if (v && !v->is_array()) ctx.fail(element, std::string(key) + " must be an array, got " + brief(*v));
  return v;
}

std::optional<uint64_t> getUInt(const Context& ctx, const Json& obj, const char* key, const std::string& element) {
  const Json* v = getMember(ctx, obj, key, element);
  if (!v) return std::nullopt;
  std::optional<uint64_t> u = asUInt(*v);
  if (!u) ctx.fail(element, std::string(key) + " must be a non-negative integer, got " + brief(*v));
  if (*u > kMaxJsonInteger) ctx.fail(element, std::string(key) + " " + brief(*v) + " is too large");
  return u;
}

uint64_t requireUInt(const Context& ctx, const Json& obj, const char* key, const std::string& element) {
  std::optional<uint64_t> u = getUInt(ctx, obj, key, element);
  if (!u) ctx.fail(element, std::string(key) + " is missing");
  return *u;
}

std::optional<std::string> getString(const Context& ctx, const Json& obj, const char* key, const std::string& element) {
  const Json* v = getMember(ctx, obj, key, element);
  if (!v) return std::nullopt;
  if (!v->is_string()) ctx.fail(element, std::string(key) + " must be a string, got " + brief(*v));
  return v->get<std::string>();
}

bool getBool(const Context& ctx, const Json& obj, const char* key, const std::string& element, bool def) {
  const Json* v = getMember(ctx, obj, key, element);
  if (!v) return def;
  if (!v->is_boolean()) ctx.fail(element, std::string(key) + " must be true or false, got " + brief(*v));
  return v->get<bool>();
}

namespace {

double checkedNumber(const Context& ctx, const Json& v, const std::string& element, const std::string& what, double lo,
                     double hi) {
  if (!v.is_number()) ctx.fail(element, what + " must be a number, got " + brief(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) ctx.fail(element, what + " must be finite");
  if (d < lo || d > hi) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
    std::string range;
    if (hi == INFINITY) {
      range.append(">= ").append(brief(Json(lo)));
    } else {
      range.append("[").append(brief(Json(lo))).append(", ").append(brief(Json(hi))).append("]");
    }
    ctx.fail(element, what + " " + brief(v) + " is out of range (expected " + range + ")");
  }
  return d;
}

}  // namespace

double getNumber(const Context& ctx, const Json& obj, const char* key, const std::string& element, double def,
                 double lo, double hi) {
  const Json* v = getMember(ctx, obj, key, element);
  if (!v) return def;
  return checkedNumber(ctx, *v, element, key, lo, hi);
}

std::vector<double> getNumbers(const Context& ctx, const Json& obj, const char* key, const std::string& element,
                               size_t n, std::vector<double> def, double lo, double hi) {
  const Json* v = getMember(ctx, obj, key, element);
  if (!v) return def;
  if (!v->is_array() || v->size() != n)
    ctx.fail(element, std::string(key) + " must be an array of " + std::to_string(n) + " numbers, got " + brief(*v));
  std::vector<double> out;
  out.reserve(n);
  for (size_t i = 0; i < n; ++i) out.push_back(checkedNumber(ctx, (*v)[i], element, indexed(key, i), lo, hi));
  return out;
}

uint32_t indexValue(const Context& ctx, const Json& v, const std::string& element, const std::string& what,
                    const char* target, size_t count) {
  const std::string subject = what.empty() ? std::string() : what + " ";
  std::optional<uint64_t> u = asUInt(v);
  if (!u) ctx.fail(element, subject + "must be an index (a non-negative integer), got " + brief(v));
  if (*u >= count)
    ctx.fail(element, subject + "refers to " + indexed(target, *u) + ", which does not exist (the file has " +
                          std::to_string(count) + (count == 1 ? " entry" : " entries") + " in " + target + ")");
  return static_cast<uint32_t>(*u);
}

std::optional<uint32_t> getIndex(const Context& ctx, const Json& obj, const char* key, const std::string& element,
                                 const char* target, size_t count) {
  const Json* v = getMember(ctx, obj, key, element);
  if (!v) return std::nullopt;
  return indexValue(ctx, *v, element, key, target, count);
}

uint32_t requireIndex(const Context& ctx, const Json& obj, const char* key, const std::string& element,
                      const char* target, size_t count) {
  std::optional<uint32_t> i = getIndex(ctx, obj, key, element, target, count);
  if (!i) ctx.fail(element, std::string(key) + " is missing");
  return *i;
}

size_t arraySize(const Context& ctx, const Json& doc, const char* key) {
  const Json* a = getArray(ctx, doc, key, "");
  if (a && a->size() >= (size_t(1) << 32)) ctx.fail(key, "has too many entries");
  return a ? a->size() : 0;
}

const Json& arrayObject(const Context& ctx, const Json& doc, const char* key, size_t i) {
  const Json& v = doc.at(key).at(i);
  return requireObjectValue(ctx, v, indexed(key, i));
}

}  // namespace relt::gltf
