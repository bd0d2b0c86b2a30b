#pragma once
// Step 2 of a frame: the one geometry pass from the eye. Every shadow method, the shading pass
// and the metrics read its targets, so a frame draws the scene from the eye exactly once (plus
// the light's shadow map(s)).

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/scene/GpuScene.h>
#include <renderer/scene/Scene.h>

namespace fl {

/// What the camera sees with: matrices and eye position.
struct CameraView {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::vec3 eye{0.0f};
};

class SurfacesPass {
  public:
    explicit SurfacesPass(const gl::ShaderLibrary& shaders);
    /// (Re)allocates the targets at width x height (both > 0).
    void resize(int width, int height);

    struct Inputs {
        const GpuScene& scene;
        const CameraView& camera;
        const Light& light; // for the receiver mask (the surface faces the light)
        /// The camera of the frame before (the same camera for a first frame): the motion
        /// target says where each pixel's surface point lay in it. nullptr: no motion target
        /// is written (what only flicker on the same surface point reads costs a sixth
        /// RGBA32F target and the previous pose of every vertex).
        const CameraView* previousCamera = nullptr;
    };
    /// The visible surface of each pixel; background keeps the clear values noted.
    struct Outputs {
        const gl::Texture& position;  // RGBA32F: world xyz, w = 1 (0 background)
        const gl::Texture& normal;    // RGBA32F: shading normal facing the eye, w = object id
        const gl::Texture& plane;     // RGBA32F: geometric (triangle) normal, for receiver planes
        const gl::Texture& baseColor; // RGBA32F: material base colour with its texture
        const gl::Texture& receivers; // R8: 1 where the surface faces the light (N.L > 0)
        const gl::Texture& depth;     // DEPTH32F: window depth (1 background)
        /// RGBA32F: xy = the surface point's pixel position in the previous frame (GL window
        /// coordinates), z = its depth (clip w) there, w = its depth (clip w) in this frame; what
        /// flicker on the same surface point needs (Metrics.h, Reprojection). nullptr when the
        /// frame was drawn without a previous camera.
        const gl::Texture* motion;
        int width, height;
        /// Bytes of every target above: what the pass writes (clear and draw together).
        [[nodiscard]] std::int64_t bytes() const;
    };
    /// Draws the scene once from the camera into the targets.
    Outputs execute(const Inputs& in);
    /// The last execute()'s targets (valid after the first execute()).
    [[nodiscard]] Outputs outputs() const;

  private:
    // [0] without the motion target, [1] with it (FL_MOTION).
    gl::Program programs_[2];
    gl::Texture position_, normal_, plane_, baseColor_, receivers_, motion_, depth_;
    gl::Framebuffer fbos_[2];
    bool motionWritten_ = false;
};

} // namespace fl
