#pragma once
// The project's library folders, bottom to top (README's layout; tests/include_layers_test.cpp
// holds what each may include): the one list the tests that read the source tree scan.

#include <array>
#include <string_view>

namespace fl::test {

inline constexpr std::array<std::string_view, 11> kLibraryFolders = {
    "base", "io",     "jfa",         "geometry", "scene", "raytrace",
    "gpu",  "jfa_gl", "geometry_gl", "renderer", "app"};

} // namespace fl::test
