#include "checkpoint/checkpoint.h"

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.h"
#include "core/file.h"
#include "image/image.h"

namespace relt {
namespace {

constexpr char kMagic[] = "relt checkpoint\n";
constexpr uint64_t kFormat = 1;

std::string hex(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

void appendWord(std::string& out, uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }

uint64_t wordAt(const std::vector<uint8_t>& in, size_t at) {
  uint64_t v;
  std::memcpy(&v, in.data() + at, sizeof v);
  return v;
}

}  // namespace

std::string checkpointFile(const std::string& dir) { return (std::filesystem::path(dir) / "checkpoint.relt").string(); }

uint64_t fnv1a(const void* data, size_t bytes, uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
  return hash;
}

uint64_t fnv1aWords(const void* data, size_t words, uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < words; ++i) {
    uint64_t w;
    std::memcpy(&w, p + i * sizeof w, sizeof w);  // the words may sit unaligned in a file's bytes
    hash = (hash ^ w) * 0x100000001b3ull;
  }
  return hash;
}

std::string sceneDigest(const std::string& path, const std::string& summary) {
  std::string reason;
  const std::vector<uint8_t> bytes = readWholeFile(path, &reason).value_or(std::vector<uint8_t>());
  return hex(fnv1a(summary.data(), summary.size(), fnv1a(bytes.data(), bytes.size())));
}

void writeCheckpoint(const std::string& dir, const Checkpoint& checkpoint) {
  // Layout: magic, header length, header, word count, words, checksum of everything before it
  // (FNV-1a by bytes up to the words, then by words: a film of megabytes costs milliseconds).
  const std::string header = checkpoint.header.dump();
  std::string prefix = kMagic;
  appendWord(prefix, header.size());
  prefix += header;
  appendWord(prefix, checkpoint.words.size());
  const std::string_view words(reinterpret_cast<const char*>(checkpoint.words.data()),
                               checkpoint.words.size() * sizeof(uint64_t));
  std::string checksum;
  appendWord(checksum, fnv1aWords(words.data(), checkpoint.words.size(), fnv1a(prefix.data(), prefix.size())));
  const std::string_view pieces[] = {prefix, words, checksum};
  writeFileAtomically(checkpointFile(dir), pieces);
}

namespace {

// Whether the checksum at `body` matches: as writeCheckpoint computes it, or by bytes throughout
// (checkpoints written before the words were hashed as words).
bool checksumMatches(const std::vector<uint8_t>& bytes, size_t body, size_t wordsAt) {
  const uint64_t stored = wordAt(bytes, body);
  const size_t start = wordsAt + sizeof(uint64_t);
  if (start <= body && (body - start) % sizeof(uint64_t) == 0 &&
      stored == fnv1aWords(bytes.data() + start, (body - start) / sizeof(uint64_t), fnv1a(bytes.data(), start)))
    return true;
  return stored == fnv1a(bytes.data(), body);
}

}  // namespace

Checkpoint readCheckpoint(const std::string& dir) {
  const std::string file = checkpointFile(dir);
  std::string reason;
  const std::optional<std::vector<uint8_t>> read = readWholeFile(file, &reason);
  if (!read) throw InputError(file, "", "cannot read the checkpoint: " + reason);
  const std::vector<uint8_t>& bytes = *read;
  const size_t magic = sizeof kMagic - 1;
  if (bytes.size() < magic || std::memcmp(bytes.data(), kMagic, magic) != 0)
    throw InputError(file, "", "not a relt checkpoint");
  auto corrupt = [&](const char* what) { return InputError(file, "", std::string("checkpoint is damaged: ") + what); };
  if (bytes.size() < magic + 3 * sizeof(uint64_t)) throw corrupt("truncated");
  const size_t body = bytes.size() - sizeof(uint64_t);
  const uint64_t headerLength = wordAt(bytes, magic);
  const bool lengthFits = headerLength <= body - magic - 2 * sizeof(uint64_t);
  if (!checksumMatches(bytes, body, lengthFits ? magic + sizeof(uint64_t) + headerLength : body))
    throw corrupt("checksum mismatch (truncated or modified)");
  if (!lengthFits) throw corrupt("header length");
  Checkpoint c;
  try {
    const auto* text = bytes.data() + magic + sizeof(uint64_t);
    c.header = nlohmann::json::parse(text, text + headerLength);
  } catch (const nlohmann::json::exception&) {
    throw corrupt("header is not JSON");
  }
  const size_t wordsAt = magic + sizeof(uint64_t) + headerLength;
  const uint64_t count = wordAt(bytes, wordsAt);
  if (count != (body - wordsAt - sizeof(uint64_t)) / sizeof(uint64_t) ||
      (body - wordsAt - sizeof(uint64_t)) % sizeof(uint64_t) != 0)
    throw corrupt("word count");
  c.words.resize(count);
  std::memcpy(c.words.data(), bytes.data() + wordsAt + sizeof(uint64_t), count * sizeof(uint64_t));
  if (c.header.value("format", uint64_t(0)) != kFormat)
    throw InputError(file, "", "checkpoint format " + c.header.value("format", nlohmann::json()).dump() +
                                   " is not the one this relt reads (" + std::to_string(kFormat) + ")");
  return c;
}

nlohmann::json imageIdentity(const RenderSettings& settings, const std::string& digest) {
  nlohmann::json j = settings.toJson();
  for (const char* key : {"scene", "output", "png", "spp", "time", "mutations_per_pixel", "snapshot_every",
                          "placement", "balance_window", "exposure", "threads"})
    j.erase(key);
  j["scene_digest"] = digest;
  j["format"] = kFormat;
  return j;
}

void checkSameRender(const nlohmann::json& stored, const nlohmann::json& now, const std::string& file) {
  for (auto it = now.begin(); it != now.end(); ++it) {
    const auto s = stored.find(it.key());
    if (s == stored.end() || *s != it.value()) {
      const std::string was = s == stored.end() ? "(absent)" : s->dump();
      if (it.key() == "scene_digest")
        throw InputError(file, "", "the checkpoint is of another scene (or the scene file changed since)");
      throw InputError(file, "", "the checkpoint was rendered with " + it.key() + " " + was + ", this render has " +
                                     it.value().dump() + "; resume with the same settings");
    }
  }
  for (auto it = stored.begin(); it != stored.end(); ++it)
    if (!now.contains(it.key()))
      throw InputError(file, "", "the checkpoint was rendered with " + it.key() + " " + it.value().dump() +
                                     ", which this render does not set; resume with the same settings");
}

}  // namespace relt
