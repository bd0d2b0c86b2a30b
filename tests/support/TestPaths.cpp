#include "TestPaths.h"

#include <fstream>
#include <iterator>

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

std::string fileContents(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

} // namespace fl::test
