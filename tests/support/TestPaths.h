#pragma once
// Where tests find their data and write their output.

#include <filesystem>
#include <string>

namespace fl::test {

/// The tests/ source folder (goldens, fixtures).
std::filesystem::path dataDir();
/// assets/default.glb, the default scene that the goldens show.
std::filesystem::path defaultAsset();
/// A per-test output folder under the build tree, created on demand.
std::filesystem::path outputDir(const std::string& sub = {});
/// The whole file as bytes; empty if it cannot be read (the test's expectations then fail).
std::string fileContents(const std::filesystem::path& path);

} // namespace fl::test
