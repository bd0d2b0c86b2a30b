#include <renderer/passes/SurfaceDecode.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/soft/EyeDecode.h>

#include <gpu/ReadBack.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/OccluderEdge.h>

#include <stdexcept>

namespace fl {

namespace eyecell {

std::uint32_t pack(State state, glm::ivec2 t, std::uint32_t edgeCode) {
    return static_cast<std::uint32_t>(state) | (edgeCode << 2u) |
           (static_cast<std::uint32_t>(t.x) << 6u) | (static_cast<std::uint32_t>(t.y) << 19u);
}

State state(std::uint32_t cell) {
    return static_cast<State>(cell & 3u);
}

glm::ivec2 texel(std::uint32_t cell) {
    return {static_cast<int>((cell >> 6u) & 8191u), static_cast<int>(cell >> 19u)};
}

std::uint32_t edgeCode(std::uint32_t cell) {
    return (cell >> 2u) & 15u;
}

glm::vec4 point(std::uint32_t cell, glm::vec4 surfacePosition) {
    const State s = state(cell);
    if (s == State::Background) return {0.0f, 0.0f, 0.0f, -1.0f};
    const float w = s == State::Shadowed ? 1.0f : (s == State::Lit ? 0.0f : 2.0f);
    return {surfacePosition.x, surfacePosition.y, surfacePosition.z, w};
}

glm::vec4 occluder(std::uint32_t cell, const ReceiverGrid& receivers,
                   const std::vector<float>* ids) {
    const State s = state(cell);
    if (s == State::Background || s == State::OutsideMap) return {0.0f, 0.0f, 0.0f, -1.0f};
    const glm::ivec2 t = texel(cell);
    const float id =
        ids ? (*ids)[static_cast<std::size_t>(t.y) * static_cast<std::size_t>(receivers.width) +
                     static_cast<std::size_t>(t.x)]
            : -1.0f;
    return glm::vec4(occluderEdgeApply(receivers, t.x, t.y, edgeCode(cell)), id);
}

} // namespace eyecell

namespace {
// shaders/eye_decode.glsl's own uniforms (EyeCells::bind; the surfaces' and the map's apart).
constexpr struct {
    gl::Uniform<int> objectIds{"uEyeObjectIds"};
    gl::Uniform<int> factor{"uEyeFactor"};
    gl::Uniform<glm::ivec2> grid{"uEyeGrid"};
} kEyeDecode;
} // namespace

void EyeCells::bind(gl::BindScope& scope, const gl::Program& program, int factor) const {
    scope.texture(gl::bind::EyeCells, cells->id());
    SurfacePositions{*depth, inverseViewProj}.bind(scope, program, gl::bind::EyeDepth);
    map.bind(scope, program, gl::bind::EyeReceivers);
    scope.texture(gl::bind::EyeIds, objectIds ? ids->id() : 0);
    program.set(kEyeDecode.objectIds, objectIds ? 1 : 0);
    scope.texture(gl::bind::SeedOccluders, seedOccluders ? seedOccluders->id() : 0);
    program.set(kEyeDecode.factor, factor);
    program.set(kEyeDecode.grid,
                glm::ivec2((width() + factor - 1) / factor, (height() + factor - 1) / factor));
}

void EyeCells::bindUniforms(gl::Program& program) {
    program.bindUniforms({&kEyeDecode.objectIds, &kEyeDecode.factor, &kEyeDecode.grid});
    SurfacePositions::bindUniforms(program);
    MapPositions::bindUniforms(program);
}

std::pair<const gl::Texture&, const gl::Texture&> EyeCells::decoded() const {
    if (pass == nullptr) throw std::logic_error("EyeCells::decoded: no JFA-E pass");
    return pass->decodedEyeImage();
}

std::vector<std::uint32_t> EyeCells::words() const {
    return gl::readTexels<std::uint32_t>(*cells, GL_RED_INTEGER, GL_UNSIGNED_INT);
}

EyeImage EyeCells::read() const {
    const std::vector<std::uint32_t> cellWords = words();
    const std::vector<float> depths = gl::readTexels<float>(*depth, GL_DEPTH_COMPONENT, GL_FLOAT);
    const ReceiverGrid receivers{map.size(), map.size(), map.read()};
    std::vector<float> idValues;
    if (objectIds) idValues = gl::readTexels<float>(*ids, GL_RED, GL_FLOAT);
    EyeImage im{width(), height(), {}, {}};
    im.points.reserve(cellWords.size());
    im.occluders.reserve(cellWords.size());
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const std::size_t i = im.index(x, y);
            const glm::vec4 surface =
                surface::position(depths[i], {x, y}, {im.width, im.height}, inverseViewProj);
            im.points.push_back(eyecell::point(cellWords[i], surface));
            im.occluders.push_back(
                eyecell::occluder(cellWords[i], receivers, objectIds ? &idValues : nullptr));
        }
    return im;
}

} // namespace fl
