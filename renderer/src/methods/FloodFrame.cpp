#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/EyeDecode.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/PenumbraMap.h>

#include <jfa_gl/GlKernel.h>

#include <stdexcept>

namespace fl {

namespace {
const gl::Texture& unpackSource(const FloodFrame& frame) {
    if (frame.eye) return frame.eyeCells->decoded().second;
    if (frame.map == nullptr)
        throw std::logic_error("FloodGridReader: a light-space flood without its shadow map");
    return frame.map->decoded();
}
} // namespace

FloodGridReader::FloodGridReader(const FloodFrame& frame)
    : eye_(frame.eye), source_(jfa::readGrid(unpackSource(frame))) {}

jfa::Grid FloodGridReader::read(const gl::Texture& grid) const {
    return eye_ ? readEyeGrid(grid, source_) : readPenumbraGrid(grid, source_);
}

jfa::Grid readFloodGrid(const FloodFrame& frame, const gl::Texture& grid) {
    return FloodGridReader(frame).read(grid);
}

} // namespace fl
