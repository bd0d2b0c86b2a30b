#include "CaptureOutputs.h"

#include "TestPaths.h"

#include <sstream>
#include <vector>

namespace fl::test {

std::string untimedCsv(const std::filesystem::path& dir) {
    std::istringstream in(fileContents(dir / "frames.csv"));
    std::string out, line;
    std::vector<bool> keep;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream s(line);
        for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
        if (keep.empty())
            for (const std::string& c : cells) keep.push_back(!c.ends_with("_ms"));
        for (std::size_t k = 0; k < cells.size(); ++k)
            if (k < keep.size() && keep[k]) out += cells[k] + ",";
        out += "\n";
    }
    return out;
}

nlohmann::json untimedSummary(const std::filesystem::path& dir) {
    nlohmann::json j = nlohmann::json::parse(fileContents(dir / "summary.json"));
    j["reference"].erase("medianFrameMs");
    j.erase("resources");  // the process's memory and objects, after this sitting's frames
    j.erase("phaseSplit"); // where this sitting's time went
    for (auto& m : j["methods"])
        for (const char* timed : {"medianFrameMs", "frameTimeOverHard", "medianPhaseMs"})
            m.erase(timed);
    return j;
}

} // namespace fl::test
