// libFuzzer target: voronoi3d's point reader (app/src/Voronoi3dInput.cpp) on any bytes, the grid
// side from the first byte. A bad file must throw std::invalid_argument (file, line, problem);
// what parses must be distinct sites inside the grid with ids in file order.
#include <app/Voronoi3dInput.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string_view>
#include <tuple>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const int side = 1 + data[0];
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        const std::vector<fl::jfa::Site3> sites = fl::app::parseSites3d(text, "fuzz.txt", side);
        std::set<std::tuple<int, int, int>> seen;
        for (std::size_t i = 0; i < sites.size(); ++i) {
            const fl::jfa::Site3& s = sites[i];
            if (s.x < 0 || s.y < 0 || s.z < 0 || s.x >= side || s.y >= side || s.z >= side ||
                s.id != int(i) || !seen.insert({s.x, s.y, s.z}).second)
                std::abort();
        }
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
