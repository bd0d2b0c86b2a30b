// libFuzzer target: the point readers on any bytes (.node, .xy text, .f64/.bin binary). A bad
// file must throw PointFileError (file, line or byte, problem); what parses must be finite.
#include <geometry/PointIO.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

namespace {
void requireFinite(const std::vector<glm::dvec2>& points) {
    for (const glm::dvec2 p : points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) std::abort();
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        switch (data[0] % 3) {
        case 0:
            requireFinite(fl::geom::parseNode(text, "fuzz.node").points);
            break;
        case 1:
            requireFinite(fl::geom::parseTextPoints(text, "fuzz.xy"));
            break;
        default:
            requireFinite(fl::geom::parseBinaryPoints(std::as_bytes(std::span(data + 1, size - 1)),
                                                      "fuzz.f64"));
            break;
        }
    } catch (const fl::geom::PointFileError&) {
    }
    return 0;
}
