#pragma once
// A capture's outputs without what changes from run to run (times, memory, the phase split): what
// a resumed or pipelined run must reproduce exactly.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace fl::test {

/// DIR/frames.csv without its time columns (frame_ms and the phases' *_ms).
std::string untimedCsv(const std::filesystem::path& dir);
/// DIR/summary.json without its times, its resources and its phase split.
nlohmann::json untimedSummary(const std::filesystem::path& dir);

} // namespace fl::test
