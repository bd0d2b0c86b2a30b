#pragma once
// Whether every component of a vector or matrix is finite: the check every reader of user
// geometry (glTF, scene files, scripts) makes before it trusts a value.

#include <glm/glm.hpp>

#include <cmath>

namespace fl::geom {

/// True when no component of `v` is NaN or infinite.
template <glm::length_t N, typename T, glm::qualifier Q>
bool allFinite(const glm::vec<N, T, Q>& v) {
    for (glm::length_t i = 0; i < N; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

/// True when no entry of `m` is NaN or infinite.
template <glm::length_t C, glm::length_t R, typename T, glm::qualifier Q>
bool allFinite(const glm::mat<C, R, T, Q>& m) {
    for (glm::length_t c = 0; c < C; ++c)
        if (!allFinite(m[c])) return false;
    return true;
}

} // namespace fl::geom
