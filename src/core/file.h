#pragma once
// Whole files into memory (scene files and their buffers, checkpoints).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace relt {

// A whole file's bytes; on failure nullopt and a reason ("no such file", "not a regular file", ...).
std::optional<std::vector<uint8_t>> readWholeFile(const std::filesystem::path& path, std::string* reason);

}  // namespace relt
