#include <jfa_gl/GlExactRepair.h>

#include <jfa_gl/GlKernel.h>

#include <gpu/BindScope.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace fl::jfa {

namespace {

// A storage buffer holding `values` (at least one element's bytes: GL rejects empty storage).
template <class T>
gl::Buffer storageOf(const std::vector<T>& values) {
    const std::vector<T> one(1);
    const std::vector<T>& data = values.empty() ? one : values;
    return gl::Buffer(GLsizeiptr(data.size() * sizeof(T)), data.data(), 0);
}

// jfa_exact_repair.comp.glsl's own uniforms (NearestSite's apart).
constexpr struct {
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<int> vertexCount{"uVertexCount"};
} kRepair;

} // namespace

GlExactRepair::GlExactRepair(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "jfa_exact_repair.comp.glsl"},
                                            {GL_COMPUTE_SHADER, NearestSite::glslFile}})) {
    program_.bindUniforms({&kRepair.size, &kRepair.vertexCount});
    bindCriterionUniforms(program_, static_cast<const NearestSite*>(nullptr));
}

void GlExactRepair::setGraph(const SiteGraph& graph) {
    if (graph.offsets.size() != graph.vertices.size() + 1)
        throw std::invalid_argument("GlExactRepair: the graph's offsets do not match its " +
                                    std::to_string(graph.vertices.size()) + " vertices");
    vertices_ = storageOf(graph.vertices);
    offsets_ = storageOf(graph.offsets);
    neighbours_ = storageOf(graph.neighbours);
    vertexCount_ = std::uint32_t(graph.vertices.size());
}

const gl::Texture& GlExactRepair::run(const gl::Texture& flooded) {
    if (!offsets_.id()) throw std::logic_error("GlExactRepair::run before setGraph");
    if (out_.width() != flooded.width() || out_.height() != flooded.height())
        out_ = gl::Texture(GL_RGBA32F, flooded.width(), flooded.height());
    glUseProgram(program_.id());
    gl::BindScope scope;
    setCriterionUniforms(scope, program_, NearestSite{true});
    program_.set(kRepair.size, glm::ivec2(flooded.width(), flooded.height()));
    program_.set(kRepair.vertexCount, int(vertexCount_));
    scope.texture(gl::bind::Flooded, flooded.id())
        .image(gl::bind::RepairOut, out_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .storage(gl::bind::RepairVertices, vertices_.id())
        .storage(gl::bind::RepairOffsets, offsets_.id())
        .storage(gl::bind::RepairNeighbours, neighbours_.id());
    glDispatchCompute(GLuint((flooded.width() + 7) / 8), GLuint((flooded.height() + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    scope.release(); // before the error check, so that it covers the unbinding too
    glUseProgram(0);
    gl::throwIfErrors("jfa exact repair");
    return out_;
}

} // namespace fl::jfa
