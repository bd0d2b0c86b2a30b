#pragma once
// Triangle lists compared as sets, whatever order the triangulators emit them in.

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace fl::test {

/// Triangles rotated to start at their smallest index (orientation kept), sorted: equal for equal
/// triangle sets.
inline std::vector<std::array<std::uint32_t, 3>>
triangleSet(const std::vector<std::uint32_t>& tris) {
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::size_t i = 0; i + 2 < tris.size(); i += 3) {
        std::array<std::uint32_t, 3> t{tris[i], tris[i + 1], tris[i + 2]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace fl::test
