#include "core/file.h"

#include <cerrno>
#include <cstring>
#include <fstream>

namespace relt {

std::optional<std::vector<uint8_t>> readWholeFile(const std::filesystem::path& path, std::string* reason) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    *reason = "no such file";
    return std::nullopt;
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    *reason = "not a regular file";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *reason = std::strerror(errno);
    return std::nullopt;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < 0) {
    *reason = "cannot determine its size";
    return std::nullopt;
  }
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size)) {
    *reason = "read error";
    return std::nullopt;
  }
  return bytes;
}

}  // namespace relt
