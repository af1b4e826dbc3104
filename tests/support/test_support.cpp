#include "test_support.h"

namespace relt::test {

std::string sourcePath(const std::string& relative) { return std::string(RELT_SOURCE_DIR) + "/" + relative; }

}  // namespace relt::test
