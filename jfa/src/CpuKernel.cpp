#include <jfa/CpuKernel.h>

namespace fl::jfa {

int stageScale(const Plan& plan, std::size_t stageIndex) {
    const std::size_t count = plan.stages().size();
    if (stageIndex >= count) throw std::out_of_range("stageScale: no such stage");
    const std::size_t shift = count - 1 - stageIndex;
    if (shift > 20) throw std::invalid_argument("stageScale: plan has too many stages");
    return 1 << shift;
}

Grid expand(const Grid& grid, int width, int height) {
    if (width < 1 || height < 1 || grid.width != (width + 1) / 2 ||
        grid.height != (height + 1) / 2) {
        throw std::invalid_argument("expand: a " + std::to_string(grid.width) + "x" +
                                    std::to_string(grid.height) + " grid does not expand to " +
                                    std::to_string(width) + "x" + std::to_string(height));
    }
    Grid out(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) out.at(x, y) = grid.at(x / 2, y / 2);
    }
    return out;
}

} // namespace fl::jfa
