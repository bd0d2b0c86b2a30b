#include <app/Voronoi3dInput.h>

#include <base/Numbers.h>

#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace fl::app {

namespace {

// The whitespace-separated words of one line.
std::vector<std::string> lineWords(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w && words.size() < 4;) words.push_back(w);
    return words;
}

} // namespace

std::vector<jfa::Site3> parseSites3d(std::string_view text, const std::string& file, int size) {
    std::istringstream in{std::string(text)};
    std::vector<jfa::Site3> sites;
    std::map<std::tuple<int, int, int>, int> seen; // voxel -> line, to name duplicates
    std::string line;
    const auto fail = [&](int n, const std::string& problem) {
        return std::invalid_argument(file + ":" + std::to_string(n) + ": " + problem);
    };
    for (int n = 1; std::getline(in, line); ++n) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        const std::vector<std::string> words = lineWords(line);
        if (words.size() != 3) throw fail(n, "expected three integers 'x y z'");
        int xyz[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            const std::string problem = numberProblem(words[std::size_t(k)], 0, size - 1, true);
            if (!problem.empty())
                throw fail(n, std::string(1, "xyz"[k]) + " " + problem + " (the grid is " +
                                  std::to_string(size) + "^3)");
            double v = 0;
            parseNumber(words[std::size_t(k)], v);
            xyz[k] = int(v);
        }
        const auto [it, added] = seen.try_emplace({xyz[0], xyz[1], xyz[2]}, n);
        if (!added) throw fail(n, "duplicate of the site on line " + std::to_string(it->second));
        if (sites.size() >= std::size_t(kMaxSites3d))
            throw fail(n, "more than " + std::to_string(kMaxSites3d) + " sites");
        sites.push_back({xyz[0], xyz[1], xyz[2], int(sites.size())});
    }
    if (sites.empty()) throw std::invalid_argument(file + ": no sites");
    return sites;
}

} // namespace fl::app
