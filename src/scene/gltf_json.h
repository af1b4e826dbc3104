#pragma once
// Typed, checked access to the glTF JSON document. Every getter either returns a value that is
// valid for its field or throws one InputError naming the file, the element and the reason, so the
// loader never indexes anything the file did not prove to exist.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace relt::gltf {

using Json = nlohmann::json;

// The file being loaded and the warnings gathered while loading it.
class Context {
 public:
  explicit Context(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& element, const std::string& reason) const;
  void warn(const std::string& line);  // keeps the first occurrence of each line only
  std::vector<std::string> takeWarnings() { return std::move(warnings_); }

 private:
  std::string file_;
  std::vector<std::string> warnings_;
};

// "accessors[3]"
std::string indexed(const std::string& array, size_t i);
// A JSON value shortened for a message.
std::string brief(const Json& v);
// A string from the file made safe for a one-line message (control characters replaced, shortened).
std::string printable(const std::string& s, size_t maxLength = 64);

// Integers above 2^53 cannot round-trip through JSON numbers; rejecting them also keeps every
// byte-range computation below far from uint64 overflow.
inline constexpr uint64_t kMaxJsonInteger = uint64_t(1) << 53;

// `obj` is the JSON value of `element`; it must be an object (checked by every getter).
// A missing key gives the default or nullopt; a present key of the wrong type or range fails.
const Json* getMember(const Context& ctx, const Json& obj, const char* key, const std::string& element);
const Json* getObject(const Context& ctx, const Json& obj, const char* key, const std::string& element);
const Json* getArray(const Context& ctx, const Json& obj, const char* key, const std::string& element);
std::optional<uint64_t> getUInt(const Context& ctx, const Json& obj, const char* key, const std::string& element);
uint64_t requireUInt(const Context& ctx, const Json& obj, const char* key, const std::string& element);
std::optional<std::string> getString(const Context& ctx, const Json& obj, const char* key, const std::string& element);
bool getBool(const Context& ctx, const Json& obj, const char* key, const std::string& element, bool def);
// A finite number in [lo, hi].
double getNumber(const Context& ctx, const Json& obj, const char* key, const std::string& element, double def,
                 double lo, double hi);
// An array of exactly n finite numbers in [lo, hi]; `def` when absent.
std::vector<double> getNumbers(const Context& ctx, const Json& obj, const char* key, const std::string& element,
                               size_t n, std::vector<double> def, double lo = -INFINITY, double hi = INFINITY);

// An index into the top-level array `target` (e.g. "accessors") of `count` entries.
std::optional<uint32_t> getIndex(const Context& ctx, const Json& obj, const char* key, const std::string& element,
                                 const char* target, size_t count);
uint32_t requireIndex(const Context& ctx, const Json& obj, const char* key, const std::string& element,
                      const char* target, size_t count);
// An index value; `what` names the field in messages ("" when `element` already names the value,
// as for "nodes[2].children[0]").
uint32_t indexValue(const Context& ctx, const Json& v, const std::string& element, const std::string& what,
                    const char* target, size_t count);

// Size of a top-level array (0 when absent); fails if present but not an array.
size_t arraySize(const Context& ctx, const Json& doc, const char* key);
// Entry i of a top-level array, which must be an object.
const Json& arrayObject(const Context& ctx, const Json& doc, const char* key, size_t i);

}  // namespace relt::gltf
