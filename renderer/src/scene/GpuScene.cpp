#include <renderer/scene/GpuScene.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fl {

namespace {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec4 color; // COLOR_0, white where the mesh has none
};

/// JOINTS_0 and WEIGHTS_0 of a vertex (attribute locations 4 and 5).
struct SkinVertex {
    std::uint16_t joints[4];
    glm::vec4 weights;
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

    uploadPoseData(scene);
    for (const Image& img : scene.images) textures_.push_back(uploadImage(img));
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes.at(static_cast<size_t>(inst.mesh));
        const MeshRange& r = ranges.at(static_cast<size_t>(inst.mesh));
        Material mat;
        if (mesh.material >= 0) mat = scene.materials.at(static_cast<size_t>(mesh.material));
        const std::optional<float> cutoff = shadowCutoff(mat);
        const bool skinned = isSkinned(inst, mesh);
        const std::size_t targets = std::min(mesh.targets.size(), kMaxMorphTargets);
        std::vector<float> weights(
            mesh.morphWeights.begin(),
            mesh.morphWeights.begin() +
                static_cast<std::ptrdiff_t>(std::min(targets, mesh.morphWeights.size())));
        weights.resize(targets, 0.0f);
        draws_.push_back({inst.world, glm::transpose(glm::inverse(glm::mat3(inst.world))),
                          r.indexCount, r.firstIndex, r.baseVertex, mat.baseColorFactor,
                          mat.baseColorTexture, inst.objectId, cutoff.value_or(-1.0f),
                          mat.alphaMode == AlphaMode::Blend, inst.world, skinned ? inst.skin : -1,
                          morphBase_.empty() ? 0 : morphBase_[static_cast<size_t>(inst.mesh)],
                          static_cast<GLint>(targets), static_cast<GLint>(mesh.positions.size()),
                          weights, weights});
        blended_ = blended_ || mat.alphaMode == AlphaMode::Blend;
        triangles_ += mesh.triangleCount();
    }
}

void GpuScene::uploadPoseData(const Scene& scene) {
    const bool skinned = std::any_of(scene.meshes.begin(), scene.meshes.end(),
                                     [](const Mesh& m) { return !m.joints.empty(); });
    if (skinned) {
        // Parallel to the vertex buffer, zeros for unskinned meshes (their draws skip skinning).
        std::vector<SkinVertex> skin;
        for (const Mesh& m : scene.meshes)
            for (std::size_t i = 0; i < m.positions.size(); ++i) {
                SkinVertex v{{0, 0, 0, 0}, glm::vec4(0.0f)};
                if (i < m.joints.size() && i < m.weights.size()) {
                    for (int k = 0; k < 4; ++k)
                        v.joints[k] = static_cast<std::uint16_t>(std::min(m.joints[i][k], 65535u));
                    v.weights = m.weights[i];
                }
                skin.push_back(v);
            }
        skinVertices_ =
            gl::Buffer(static_cast<GLsizeiptr>(skin.size() * sizeof(SkinVertex)), skin.data());
        glVertexArrayVertexBuffer(vao_.id(), 1, skinVertices_.id(), 0, sizeof(SkinVertex));
        glEnableVertexArrayAttrib(vao_.id(), 4);
        glVertexArrayAttribIFormat(vao_.id(), 4, 4, GL_UNSIGNED_SHORT,
                                   offsetof(SkinVertex, joints));
        glVertexArrayAttribBinding(vao_.id(), 4, 1);
        glEnableVertexArrayAttrib(vao_.id(), 5);
        glVertexArrayAttribFormat(vao_.id(), 5, 4, GL_FLOAT, GL_FALSE,
                                  offsetof(SkinVertex, weights));
        glVertexArrayAttribBinding(vao_.id(), 5, 1);
    }
    std::vector<glm::vec4> deltas;
    for (const Mesh& m : scene.meshes) {
        morphBase_.push_back(static_cast<GLint>(deltas.size()));
        const std::size_t targets = std::min(m.targets.size(), kMaxMorphTargets);
        for (std::size_t t = 0; t < targets; ++t)
            for (const std::vector<glm::vec3>* part :
                 {&m.targets[t].positions, &m.targets[t].normals})
                for (std::size_t v = 0; v < m.positions.size(); ++v)
                    deltas.emplace_back(v < part->size() ? (*part)[v] : glm::vec3(0.0f), 0.0f);
    }
    if (!deltas.empty())
        morphs_ =
            gl::Buffer(static_cast<GLsizeiptr>(deltas.size() * sizeof(glm::vec4)), deltas.data());
    for (const Skin& s : scene.skins) {
        skinBase_.push_back(jointCount_);
        jointCount_ += static_cast<GLint>(s.joints.size());
    }
    if (jointCount_ > 0) {
        const Pose rest = evaluatePose(scene, {}, 0.0);
        std::vector<glm::mat4> joints;
        for (int pass = 0; pass < 2; ++pass) // this frame's and the previous frame's
            for (const std::vector<glm::mat4>& skinJoints : rest.joints)
                joints.insert(joints.end(), skinJoints.begin(), skinJoints.end());
        joints_ = gl::Buffer(static_cast<GLsizeiptr>(joints.size() * sizeof(glm::mat4)),
                             joints.data(), GL_DYNAMIC_STORAGE_BIT);
    }
}

void GpuScene::setPose(const Pose& current, const Pose& previous) {
    if (current.instanceWorld.size() != draws_.size() ||
        previous.instanceWorld.size() != draws_.size())
        throw std::invalid_argument("GpuScene::setPose: a pose of another scene");
    for (std::size_t i = 0; i < draws_.size(); ++i) {
        Draw& d = draws_[i];
        d.model = current.instanceWorld[i];
        d.normalMatrix = glm::transpose(glm::inverse(glm::mat3(d.model)));
        d.previousModel = previous.instanceWorld[i];
        for (std::size_t t = 0; t < d.weights.size(); ++t) {
            d.weights[t] = t < current.morphWeights[i].size() ? current.morphWeights[i][t] : 0.0f;
            d.previousWeights[t] =
                t < previous.morphWeights[i].size() ? previous.morphWeights[i][t] : 0.0f;
        }
    }
    if (jointCount_ > 0) {
        std::vector<glm::mat4> joints;
        for (const Pose* p : {&current, &previous})
            for (const std::vector<glm::mat4>& skinJoints : p->joints)
                joints.insert(joints.end(), skinJoints.begin(), skinJoints.end());
        if (joints.size() != 2 * static_cast<std::size_t>(jointCount_))
            throw std::invalid_argument("GpuScene::setPose: joint count differs from the scene's");
        glNamedBufferSubData(joints_.id(), 0,
                             static_cast<GLsizeiptr>(joints.size() * sizeof(glm::mat4)),
                             joints.data());
    }
    pose_ = current;
    ++poseVersion_;
}

struct GpuScene::PoseLocations {
    GLint previousModel, jointBase, previousJointBase, morphBase, morphCount, morphVertices,
        baseVertex, weights, previousWeights;
    explicit PoseLocations(const gl::Program& p)
        : previousModel(p.location("uPreviousModel")), jointBase(p.location("uJointBase")),
          previousJointBase(p.location("uPreviousJointBase")), morphBase(p.location("uMorphBase")),
          morphCount(p.location("uMorphCount")), morphVertices(p.location("uMorphVertices")),
          baseVertex(p.location("uBaseVertex")), weights(p.location("uMorphWeights")),
          previousWeights(p.location("uPreviousMorphWeights")) {}
};

void GpuScene::setPoseUniforms(GLuint id, const PoseLocations& at, const Draw& d) const {
    glProgramUniformMatrix4fv(id, at.previousModel, 1, GL_FALSE, &d.previousModel[0][0]);
    const GLint base = d.skin >= 0 ? skinBase_[static_cast<std::size_t>(d.skin)] : -1;
    glProgramUniform1i(id, at.jointBase, base);
    glProgramUniform1i(id, at.previousJointBase, base >= 0 ? base + jointCount_ : -1);
    glProgramUniform1i(id, at.morphCount, d.morphCount);
    if (d.morphCount == 0) return;
    glProgramUniform1i(id, at.morphBase, d.morphBase);
    glProgramUniform1i(id, at.morphVertices, d.vertexCount);
    glProgramUniform1i(id, at.baseVertex, d.baseVertex);
    glProgramUniform1fv(id, at.weights, d.morphCount, d.weights.data());
    glProgramUniform1fv(id, at.previousWeights, d.morphCount, d.previousWeights.data());
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
    const PoseLocations poseAt(program);
    // The textures bound below are this draw's, not the caller's: unbound when it ends.
    gl::BindScope scope;
    if (joints_) scope.storage(gl::bind::PoseJoints, joints_.id());
    if (morphs_) scope.storage(gl::bind::PoseMorphs, morphs_.id());
    for (const Draw& d : draws_) {
        if (d.indexCount == 0) continue;
        if ((which == Surfaces::Solid && d.blended) || (which == Surfaces::Blended && !d.blended))
            continue;
        glProgramUniformMatrix4fv(id, model, 1, GL_FALSE, &d.model[0][0]);
        setPoseUniforms(id, poseAt, d);
        if (material) {
            glProgramUniformMatrix3fv(id, normalMatrix, 1, GL_FALSE, &d.normalMatrix[0][0]);
            glProgramUniform1i(id, objectId, static_cast<int>(d.objectId));
        }
        glProgramUniform1f(id, cutoff, d.cutoff);
        glProgramUniform4fv(id, baseColor, 1, &d.baseColor[0]);
        const bool textured = d.texture >= 0 && d.texture < static_cast<int>(textures_.size());
        glProgramUniform1i(id, hasTexture, textured ? 1 : 0);
        if (textured && (material || d.cutoff >= 0.0f))
            scope.texture(gl::bind::MaterialBaseColor,
                          textures_[static_cast<size_t>(d.texture)].id());
        glDrawElementsBaseVertex(
            GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(d.firstIndex * sizeof(std::uint32_t)), d.baseVertex);
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace fl
