#pragma once
// A Scene uploaded to GL: one interleaved vertex buffer and one index buffer for all meshes,
// material textures, and the draw list. Passes draw it with their own programs.

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <scene/Pose.h>
#include <scene/Scene.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace fl {

class GpuScene {
  public:
    /// Uploads every mesh, material texture and instance; needs a current GL context. `scene`
    /// must outlive this object: CPU methods (the ray tracer) read its triangles.
    explicit GpuScene(const Scene& scene);

    /// What a draw sets per instance.
    enum class Uniforms { Geometry, Material };
    /// Which instances a draw takes: all (the light's passes: a blended surface casts the shadow
    /// of its alpha >= 0.5 part), those not blended (the eye's surfaces), or only the blended
    /// ones (drawn over the shaded image).
    enum class Surfaces { All, Solid, Blended };
    /// Draws the `which` instances with `program`, setting uModel and the alpha cut-out's
    /// uAlphaCutoff, uBaseColor, uHasTexture and base-colour texture (gl::bind::MaterialBaseColor;
    /// every pass that draws the scene decides visibility), plus uNormalMatrix and uObjectId for
    /// Uniforms::Material.
    void draw(const gl::Program& program, Uniforms what, Surfaces which = Surfaces::All) const;
    /// Poses the scene for the next draws (shaders/pose.glsl): every instance's transform, the
    /// skins' joints and the morph weights of `current`, and of `previous` for the motion target.
    /// Until the first call every draw is the rest pose, no motion.
    void setPose(const Pose& current, const Pose& previous);
    /// The pose of the last setPose (nullopt: rest), and a counter that changes with it (the
    /// ray tracer rebuilds its BVH when it does).
    [[nodiscard]] const std::optional<Pose>& pose() const { return pose_; }
    [[nodiscard]] std::uint64_t poseVersion() const { return poseVersion_; }
    /// True when some instance's material is BLEND.
    [[nodiscard]] bool hasBlended() const { return blended_; }

    [[nodiscard]] std::size_t triangleCount() const { return triangles_; }
    /// The scene this was uploaded from.
    [[nodiscard]] const Scene& source() const { return *source_; }
    /// How many draw() calls so far were from the eye: with a program whose vertex stage takes
    /// the camera's uViewProj (forward.vert.glsl), as opposed to the light's uLightViewProj.
    [[nodiscard]] std::size_t eyeDrawCalls() const { return eyeDrawCalls_; }

  private:
    struct Draw {
        glm::mat4 model;
        glm::mat3 normalMatrix;
        GLsizei indexCount;
        std::size_t firstIndex;
        GLint baseVertex;
        glm::vec4 baseColor;
        int texture; // index into textures_, -1 none
        std::uint32_t objectId;
        float cutoff; // shadowCutoff(material), -1 for none
        bool blended; // alphaMode BLEND
        // Posing (pose.glsl): the previous frame's transform, the skin (-1 none), the mesh's
        // morph deltas in morphs_ and this and the previous frame's weights.
        glm::mat4 previousModel;
        int skin;
        GLint morphBase, morphCount, vertexCount;
        std::vector<float> weights, previousWeights;
    };
    /// The skinning attributes, morph deltas and rest-pose joints (constructor).
    void uploadPoseData(const Scene& scene);
    /// Sets the posing uniforms of draw `d` on `program` (locations looked up per draw() call).
    struct PoseLocations;
    void setPoseUniforms(GLuint program, const PoseLocations& at, const Draw& d) const;
    const Scene* source_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::VertexArray vao_;
    std::vector<gl::Texture> textures_;
    gl::Buffer skinVertices_; // JOINTS_0 and WEIGHTS_0 per vertex (only when something is skinned)
    gl::Buffer morphs_;       // every mesh's morph deltas (only when some mesh has targets)
    gl::Buffer joints_;       // every skin's joint matrices: this frame's, then the previous's
    std::vector<GLint> skinBase_;  // per skin, its first joint in joints_
    std::vector<GLint> morphBase_; // per mesh, its first delta in morphs_
    GLint jointCount_ = 0;
    std::optional<Pose> pose_;
    std::uint64_t poseVersion_ = 0;
    std::vector<Draw> draws_;
    std::size_t triangles_ = 0;
    bool blended_ = false;
    mutable std::size_t eyeDrawCalls_ = 0; // counted by draw(), which is const to its callers
};

} // namespace fl
