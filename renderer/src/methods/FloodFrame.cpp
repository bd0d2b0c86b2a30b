#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/PenumbraMap.h>

#include <jfa/GlKernel.h>

#include <stdexcept>

namespace fl {

jfa::Grid readFloodGrid(const FloodFrame& frame, const gl::Texture& grid) {
    if (frame.eye) return readEyeGrid(grid, *frame.occluders);
    if (frame.map == nullptr)
        throw std::logic_error("readFloodGrid: a light-space flood without its shadow map");
    const jfa::Grid decoded = jfa::readGrid(frame.map->decoded());
    ReceiverGrid receivers{decoded.width, decoded.height, {}};
    receivers.points.reserve(decoded.cells.size());
    for (const jfa::Cell& c : decoded.cells) receivers.points.emplace_back(c.x, c.y, c.z, c.w);
    return readPenumbraGrid(grid, receivers);
}

} // namespace fl
