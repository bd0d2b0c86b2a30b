#include "PointIODetail.h"

#include <geometry/PointIO.h>

#include <base/OutputFiles.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace fl::geom::detail {

void appendDouble(std::string& out, double v) {
    char buffer[32]; // the longest shortest-round-trip double is 24 characters
    const auto [p, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    if (ec != std::errc{}) throw std::logic_error("appendDouble: buffer too small");
    out.append(buffer, p);
}

void appendRounded(std::string& out, double v, int digits) {
    char buffer[48];
    const auto [p, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, digits);
    if (ec != std::errc{}) throw std::logic_error("appendRounded: buffer too small");
    out.append(buffer, p);
}

void appendUint(std::string& out, std::uint64_t v) {
    char buffer[24];
    const auto [p, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    if (ec != std::errc{}) throw std::logic_error("appendUint: buffer too small");
    out.append(buffer, p);
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    // base/OutputFiles.h writes it (and defers the rename inside a command's OutputSet); the
    // error becomes this library's, naming the file once.
    try {
        fl::writeFileAtomically(path, contents);
    } catch (const OutputFileError& e) {
        const std::string message = e.what(), prefix = path.string() + ": ";
        throw PointFileError(
            path.string(), message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message);
    }
}

void requireFinite(const std::vector<glm::dvec2>& points, const char* what) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) {
            throw std::invalid_argument(std::string(what) + ": point " + std::to_string(i) +
                                        " is not finite");
        }
    }
}

void requireTriangles(const std::vector<glm::dvec2>& points,
                      const std::vector<std::uint32_t>& triangles, const char* what) {
    if (triangles.size() % 3 != 0) {
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(triangles.size()) +
                                    " triangle indices is not a multiple of 3");
    }
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        if (triangles[i] >= points.size()) {
            throw std::invalid_argument(std::string(what) + ": triangle " + std::to_string(i / 3) +
                                        " refers to vertex " + std::to_string(triangles[i]) +
                                        " but there are " + std::to_string(points.size()) +
                                        " points");
        }
    }
}

} // namespace fl::geom::detail
