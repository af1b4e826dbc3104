#pragma once
// Shared helpers for relt's tests.
#include <string>

namespace relt::test {

// Absolute path of a file in the source tree, e.g. sourcePath("scenes/cornell-box.gltf").
std::string sourcePath(const std::string& relative);

}  // namespace relt::test
