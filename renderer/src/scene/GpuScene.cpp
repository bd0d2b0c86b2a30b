#include <renderer/scene/GpuScene.h>

#include <algorithm>
#include <cmath>

namespace fl {

namespace {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec4 color; // COLOR_0, white where the mesh has none
};

struct MeshRange {
    std::size_t firstIndex;
    GLsizei indexCount;
    GLint baseVertex;
};

gl::Texture uploadImage(const Image& image) {
    const int levels =
        1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height))));
    gl::Texture t(GL_SRGB8_ALPHA8, image.width, image.height, levels);
    // glTF images have row 0 at the top and glTF UVs have v=0 at the top, so the image goes in
    // unflipped and the shader samples (u, v) directly.
    glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());
    glGenerateTextureMipmap(t.id());
    t.setSampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    return t;
}

} // namespace

GpuScene::GpuScene(const Scene& scene) : source_(&scene) {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<MeshRange> ranges;
    for (const Mesh& m : scene.meshes) {
        ranges.push_back({indices.size(), static_cast<GLsizei>(m.indices.size()),
                          static_cast<GLint>(vertices.size())});
        for (size_t i = 0; i < m.positions.size(); ++i) {
            const glm::vec2 uv = i < m.texcoords.size() ? m.texcoords[i] : glm::vec2(0.0f);
            const glm::vec4 color = i < m.colors.size() ? m.colors[i] : glm::vec4(1.0f);
            vertices.push_back({m.positions[i], m.normals.at(i), uv, color});
        }
        indices.insert(indices.end(), m.indices.begin(), m.indices.end());
    }
    // Zero-sized buffers are invalid in GL; a scene always has triangles (the loader rejects
    // empty ones), but keep a valid object regardless.
    vertices_ =
        gl::Buffer(static_cast<GLsizeiptr>(std::max<size_t>(1, vertices.size()) * sizeof(Vertex)),
                   vertices.empty() ? nullptr : vertices.data());
    indices_ = gl::Buffer(
        static_cast<GLsizeiptr>(std::max<size_t>(1, indices.size()) * sizeof(std::uint32_t)),
        indices.empty() ? nullptr : indices.data());
    vao_ = gl::VertexArray::create();
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    // Attribute locations 0..3, as the vertex stages declare them.
    const GLuint offsets[4] = {offsetof(Vertex, position), offsetof(Vertex, normal),
                               offsetof(Vertex, uv), offsetof(Vertex, color)};
    const GLint sizes[4] = {3, 3, 2, 4};
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(vao_.id(), a);
        glVertexArrayAttribFormat(vao_.id(), a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao_.id(), a, 0);
    }

    for (const Image& img : scene.images) textures_.push_back(uploadImage(img));
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes.at(static_cast<size_t>(inst.mesh));
        const MeshRange& r = ranges.at(static_cast<size_t>(inst.mesh));
        Material mat;
        if (mesh.material >= 0) mat = scene.materials.at(static_cast<size_t>(mesh.material));
        const std::optional<float> cutoff = shadowCutoff(mat);
        draws_.push_back({inst.world, glm::transpose(glm::inverse(glm::mat3(inst.world))),
                          r.indexCount, r.firstIndex, r.baseVertex, mat.baseColorFactor,
                          mat.baseColorTexture, inst.objectId, cutoff.value_or(-1.0f),
                          mat.alphaMode == AlphaMode::Blend});
        blended_ = blended_ || mat.alphaMode == AlphaMode::Blend;
        triangles_ += mesh.triangleCount();
    }
}

void GpuScene::draw(const gl::Program& program, Uniforms what, Surfaces which) const {
    if (program.location("uViewProj") >= 0) ++eyeDrawCalls_;
    glUseProgram(program.id());
    glBindVertexArray(vao_.id());
    // Uniform locations are looked up once per draw call, not once per instance.
    const GLuint id = program.id();
    const GLint model = program.location("uModel");
    const bool material = what == Uniforms::Material;
    const GLint normalMatrix = material ? program.location("uNormalMatrix") : -1;
    const GLint objectId = material ? program.location("uObjectId") : -1;
    // Every pass that draws the scene decides visibility, so all take the alpha cut-out
    // (shaders/alpha_coverage.glsl): its uniforms are set whether or not `what` asks for the
    // material's colour.
    const GLint cutoff = program.location("uAlphaCutoff");
    const GLint baseColor = program.location("uBaseColor");
    const GLint hasTexture = program.location("uHasTexture");
    for (const Draw& d : draws_) {
        if (d.indexCount == 0) continue;
        if ((which == Surfaces::Solid && d.blended) || (which == Surfaces::Blended && !d.blended))
            continue;
        glProgramUniformMatrix4fv(id, model, 1, GL_FALSE, &d.model[0][0]);
        if (material) {
            glProgramUniformMatrix3fv(id, normalMatrix, 1, GL_FALSE, &d.normalMatrix[0][0]);
            glProgramUniform1i(id, objectId, static_cast<int>(d.objectId));
        }
        glProgramUniform1f(id, cutoff, d.cutoff);
        glProgramUniform4fv(id, baseColor, 1, &d.baseColor[0]);
        const bool textured = d.texture >= 0 && d.texture < static_cast<int>(textures_.size());
        glProgramUniform1i(id, hasTexture, textured ? 1 : 0);
        if (textured && (material || d.cutoff >= 0.0f))
            glBindTextureUnit(0, textures_[static_cast<size_t>(d.texture)].id());
        glDrawElementsBaseVertex(
            GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(d.firstIndex * sizeof(std::uint32_t)), d.baseVertex);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glBindTextureUnit(0, 0); // the textures bound above are this draw's, not the caller's
}

} // namespace fl
