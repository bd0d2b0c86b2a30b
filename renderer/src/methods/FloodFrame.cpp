#include <renderer/methods/ShadowMethod.h>

#include <jfa_gl/GlKernel.h>

#include <stdexcept>

namespace fl {

namespace {
const FloodSpace& spaceOf(const FloodFrame& frame) {
    if (frame.space == nullptr) throw std::logic_error("FloodGridReader: a flood without a space");
    return *frame.space;
}
} // namespace

FloodGridReader::FloodGridReader(const FloodFrame& frame)
    : space_(&spaceOf(frame)), source_(jfa::readGrid(space_->unpackSource(frame))) {}

jfa::Grid FloodGridReader::read(const gl::Texture& grid) const {
    return space_->unpack(grid, source_);
}

jfa::Grid readFloodGrid(const FloodFrame& frame, const gl::Texture& grid) {
    return FloodGridReader(frame).read(grid);
}

} // namespace fl
