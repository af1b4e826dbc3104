#pragma once
// A render's checkpoint (--checkpoint DIR): what it takes to continue the render (--resume DIR)
// as if it had never stopped. One file, DIR/checkpoint.relt: a magic line, a JSON header (format,
// what is rendered, how far it got, the settings) and binary words (films, every rank's state),
// then a checksum of all that. Written atomically (temporary file, fsync, rename, directory
// fsync): the previous checkpoint stays valid until the new one is complete.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/settings.h"

namespace relt {

struct Checkpoint {
  nlohmann::json header;
  std::vector<uint64_t> words;
};

std::string checkpointFile(const std::string& dir);
// Throws InputError naming the file on any write failure (a full disk included).
void writeCheckpoint(const std::string& dir, const Checkpoint& checkpoint);
// Throws InputError naming the file when it is missing, truncated, corrupt or of another format.
Checkpoint readCheckpoint(const std::string& dir);

// What decides the image apart from how long it runs: every setting except outputs, budgets,
// snapshots and placement (the image does not depend on it), and a digest of the scene.
nlohmann::json imageIdentity(const RenderSettings& settings, const std::string& sceneDigest);
// Throws InputError(file, ...) naming the first thing that differs between a checkpoint's
// identity and this render's.
void checkSameRender(const nlohmann::json& stored, const nlohmann::json& now, const std::string& file);

// Whether to write a checkpoint after a round or pass, from the elapsed time every rank agreed on:
// at the end of a render (finished or stopped by a signal: `more` false) and every `every`
// seconds (0: only at the end) since the last one.
inline bool checkpointDue(double every, double elapsed, double lastCheckpoint, bool more) {
  return !more || (every > 0.0 && elapsed - lastCheckpoint >= every);
}

// 64-bit FNV-1a of bytes, continuing from `hash`.
uint64_t fnv1a(const void* data, size_t bytes, uint64_t hash = 0xcbf29ce484222325ull);
// FNV-1a's step taken a 64-bit word at a time (8 times faster on a film of megabytes), continuing
// from `hash`; every step is a bijection of the hash, so any one changed word changes the result.
uint64_t fnv1aWords(const void* data, size_t words, uint64_t hash);
// The digest of a scene file's bytes and of what was loaded from it (its summary), as hex.
std::string sceneDigest(const std::string& path, const std::string& summary);

}  // namespace relt
