#include <renderer/overlays/OverlayCanvas.h>

#include <renderer/soft/PenumbraCriterion.h>

#include <algorithm>
#include <array>

namespace fl::overlay {

namespace {

// overlay_grid.frag.glsl's uniforms (and the disk light's, bound apart).
constexpr struct {
    gl::Uniform<int> mode{"uMode"};
    gl::Uniform<glm::ivec4> viewport{"uViewport"};
    gl::Uniform<float> scale{"uScale"};
    gl::Uniform<int> lightSpace{"uLightSpace"};
    gl::Uniform<int> eyeSpace{"uEyeSpace"};
    gl::Uniform<glm::mat4> warp{"uWarp"};
} kGridUniforms;

constexpr gl::Uniform<float> kLinesPointSize{"uPointSize"}; // overlay_lines.vert.glsl

// Saves what the overlays change (viewport, depth test, blending, point size) and restores it.
class StateGuard {
  public:
    StateGuard() {
        glGetIntegerv(GL_VIEWPORT, viewport_.data());
        depth_ = glIsEnabled(GL_DEPTH_TEST);
        blend_ = glIsEnabled(GL_BLEND);
        pointSize_ = glIsEnabled(GL_PROGRAM_POINT_SIZE);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
    }
    StateGuard(const StateGuard&) = delete;
    StateGuard& operator=(const StateGuard&) = delete;
    ~StateGuard() {
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        if (depth_) glEnable(GL_DEPTH_TEST);
        if (blend_) glEnable(GL_BLEND);
        if (pointSize_)
            glEnable(GL_PROGRAM_POINT_SIZE);
        else
            glDisable(GL_PROGRAM_POINT_SIZE);
        glUseProgram(GLuint(program_));
        glBindVertexArray(GLuint(vao_));
    }

  private:
    std::array<GLint, 4> viewport_{};
    GLboolean depth_ = GL_FALSE, blend_ = GL_FALSE, pointSize_ = GL_FALSE;
    GLint program_ = 0, vao_ = 0;
};

} // namespace

glm::ivec4 squareViewport(int w, int h) {
    const int side = std::max(1, std::min(w, h));
    return {(w - side) / 2, (h - side) / 2, side, side};
}

gl::Texture uploadMask(const std::vector<std::uint8_t>& mask, int width, int height) {
    gl::Texture t(GL_R8, width, height);
    std::vector<std::uint8_t> bytes(mask.size());
    std::transform(mask.begin(), mask.end(), bytes.begin(),
                   [](std::uint8_t v) { return std::uint8_t(v ? 255 : 0); });
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(t.id(), 0, 0, 0, width, height, GL_RED, GL_UNSIGNED_BYTE, bytes.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return t;
}

OverlayCanvas::OverlayCanvas(const gl::ShaderLibrary& shaders)
    : grid_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                         {GL_FRAGMENT_SHADER, "overlay_grid.frag.glsl"}})),
      lines_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "overlay_lines.vert.glsl"},
                                          {GL_FRAGMENT_SHADER, "overlay_lines.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()), linesVao_(gl::VertexArray::create()) {
    nearest_ = gl::makeRawTexelSampler();
    glEnableVertexArrayAttrib(linesVao_.id(), 0);
    glEnableVertexArrayAttrib(linesVao_.id(), 1);
    glVertexArrayAttribFormat(linesVao_.id(), 0, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, ndc));
    glVertexArrayAttribFormat(linesVao_.id(), 1, 4, GL_FLOAT, GL_FALSE, offsetof(Vertex, colour));
    glVertexArrayAttribBinding(linesVao_.id(), 0, 0);
    glVertexArrayAttribBinding(linesVao_.id(), 1, 0);
    const auto& u = kGridUniforms;
    grid_.bindUniforms({&u.mode, &u.viewport, &u.scale, &u.lightSpace, &u.eyeSpace, &u.warp});
    bindDiskLightUniforms(grid_);
    lines_.bindUniforms({&kLinesPointSize});
}

void OverlayCanvas::drawGrid(const GridDraw& g, glm::ivec4 viewport) const {
    if (g.a == nullptr) return;
    StateGuard guard;
    glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
    const auto& grid = kGridUniforms;
    grid_.set(grid.mode, int(g.mode));
    grid_.set(grid.viewport, viewport);
    grid_.set(grid.scale, std::max(g.scale, 1e-6f));
    grid_.set(grid.lightSpace, g.lightSpace ? 1 : 0);
    grid_.set(grid.eyeSpace, g.eyeSpace ? 1 : 0);
    grid_.set(grid.warp, g.warp);
    if (g.light != nullptr) setDiskLightUniforms(grid_, *g.light);
    const std::array<const gl::Texture*, 3> units{g.a, g.b != nullptr ? g.b : g.a,
                                                  g.c != nullptr ? g.c : nullptr};
    const std::array<gl::TextureUnit, 3> channels{gl::bind::OverlayA, gl::bind::OverlayB,
                                                  gl::bind::OverlayC};
    gl::BindScope scope;
    for (std::size_t u = 0; u < 3; ++u) {
        scope.texture(channels[u], units[u] != nullptr ? units[u]->id() : 0)
            .sampler(channels[u], nearest_.id());
    }
    glUseProgram(grid_.id());
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void OverlayCanvas::drawVertices(std::span<const Vertex> vertices, GLenum primitive,
                                 glm::ivec4 viewport, float pointSize) const {
    if (vertices.empty()) return;
    StateGuard guard;
    glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
    const gl::Buffer buffer(GLsizeiptr(vertices.size_bytes()), vertices.data());
    glVertexArrayVertexBuffer(linesVao_.id(), 0, buffer.id(), 0, sizeof(Vertex));
    glEnable(GL_PROGRAM_POINT_SIZE);
    lines_.set(kLinesPointSize, pointSize);
    glUseProgram(lines_.id());
    glBindVertexArray(linesVao_.id());
    glDrawArrays(primitive, 0, GLsizei(vertices.size()));
    glVertexArrayVertexBuffer(linesVao_.id(), 0, 0, 0, sizeof(Vertex));
}

} // namespace fl::overlay
