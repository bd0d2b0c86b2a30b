#include <geometry/MeshIO.h>

#include "PointIODetail.h"

#include <stdexcept>
#include <string>

namespace fl::geom {

void writeEleFile(const std::filesystem::path& path, const std::vector<glm::dvec2>& points,
                  const std::vector<std::uint32_t>& triangles, int indexBase) {
    if (indexBase != 0 && indexBase != 1)
        throw std::invalid_argument("writeEleFile: index base must be 0 or 1");
    detail::requireTriangles(points, triangles, "writeEleFile");
    const auto base = static_cast<std::uint64_t>(indexBase);
    std::string out;
    out.reserve(triangles.size() / 3 * 40 + 32);
    detail::appendUint(out, triangles.size() / 3);
    out += " 3 0\n";
    for (std::size_t t = 0; t < triangles.size() / 3; ++t) {
        detail::appendUint(out, t + base);
        for (int k = 0; k < 3; ++k) {
            out += ' ';
            detail::appendUint(out, triangles[3 * t + k] + base);
        }
        out += '\n';
    }
    detail::writeFileAtomically(path, out);
}

void writeObjFile(const std::filesystem::path& path, const std::vector<glm::dvec2>& points,
                  const std::vector<std::uint32_t>& triangles) {
    detail::requireFinite(points, "writeObjFile");
    detail::requireTriangles(points, triangles, "writeObjFile");
    std::string out;
    out.reserve(points.size() * 48 + triangles.size() * 8 + 64);
    out += "# floodlight: ";
    detail::appendUint(out, points.size());
    out += " vertices, ";
    detail::appendUint(out, triangles.size() / 3);
    out += " triangles in the z = 0 plane\n";
    for (const glm::dvec2& p : points) {
        out += "v ";
        detail::appendDouble(out, p.x);
        out += ' ';
        detail::appendDouble(out, p.y);
        out += " 0\n";
    }
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        out += 'f';
        for (std::size_t k = 0; k < 3; ++k) {
            out += ' ';
            detail::appendUint(out, std::uint64_t{triangles[t + k]} + 1); // OBJ counts from 1
        }
        out += '\n';
    }
    detail::writeFileAtomically(path, out);
}

} // namespace fl::geom
