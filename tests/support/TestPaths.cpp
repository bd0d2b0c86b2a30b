#include "TestPaths.h"

namespace fl::test {

std::filesystem::path dataDir() {
    return FLOODLIGHT_TEST_DATA;
}

std::filesystem::path defaultAsset() {
    return std::filesystem::path(FLOODLIGHT_SOURCE_DIR) / "assets" / "default.glb";
}

std::filesystem::path outputDir(const std::string& sub) {
    std::filesystem::path p = std::filesystem::path(FLOODLIGHT_TEST_OUTPUT) / sub;
    std::filesystem::create_directories(p);
    return p;
}

} // namespace fl::test
