#pragma once
// Step 2 of a frame: the one geometry pass from the eye. Every shadow method, the shading pass
// and the metrics read its targets, so a frame draws the scene from the eye exactly once (plus
// the light's shadow map(s)). Its targets are packed (16 bytes a pixel and the receiver flag):
// world positions come back from the depth, normals are octahedral, the base colour is 8-bit
// sRGB; shaders/surface_decode.glsl and SurfaceDecode.h read them.

#include <gpu/BindScope.h>
#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/io/TextureImage.h>
#include <renderer/scene/GpuScene.h>
#include <scene/Camera.h>
#include <scene/Scene.h>

#include <functional>

namespace fl {

/// The frame's world positions as the surfaces pass stores them: its reversed-Z depth and the
/// inverse of the matrix that wrote it.
struct SurfacePositions {
    const gl::Texture& depth;
    glm::mat4 inverseViewProj;
    [[nodiscard]] int width() const { return depth.width(); }
    [[nodiscard]] int height() const { return depth.height(); }
    /// For shaders/surface_decode.glsl's surfacePosition(): the depth on texture `unit` (the
    /// shader's sampler binding) in `scope` and uSurfaceInverseViewProj of `program`.
    void bind(gl::BindScope& scope, const gl::Program& program, gl::TextureUnit unit) const;
    /// Binds the uniform bind() sets on `program`, built with surface_decode.glsl.
    static void bindUniforms(gl::Program& program);
    /// Every pixel's position as RGBA floats, row 0 at the top (readTexture's layout): world xyz
    /// and w = 1, or all 0 for background. The CPU twin of surfacePosition().
    [[nodiscard]] FloatImage read() const;
};

/// Runs `draw` with clip-space depth in [0, 1] (glClipControl GL_ZERO_TO_ONE), as the reversed-Z
/// matrices of SurfaceDecode.h need, and restores GL's [-1, 1] after: every draw into the
/// surfaces' depth goes through here (with glDepthFunc GL_GREATER).
void withReversedDepth(const std::function<void()>& draw);

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
    /// The visible surface of each pixel. Only depth and receivers are cleared: where the depth
    /// says background (surface::kBackgroundDepth) the other targets hold stale values.
    struct Outputs {
        /// DEPTH32F, reversed Z (near 1, far and background 0): positions() decodes it.
        const gl::Texture& depth;
        /// RGBA16_SNORM, octahedral: xy the shading normal facing the eye, zw the geometric
        /// (triangle) normal for receiver planes (surfaceNormal(), surfacePlane()).
        const gl::Texture& normals;
        /// RGBA8: material base colour with its texture, sRGB-encoded (surfaceBaseColor()).
        const gl::Texture& baseColor;
        const gl::Texture& receivers; // R8: 1 where the surface faces the light (N.L > 0)
        /// R32F: how far every shadow-map lookup moves the point along its shading normal
        /// (world units; 0 but where a smooth-shaded triangle is grazed by the light):
        /// shaders/terminator.glsl, surfaceLookupPoint().
        const gl::Texture& lift;
        /// RGBA32F: xy = the surface point's pixel position in the previous frame (GL window
        /// coordinates), z = its depth (clip w) there, w = its depth (clip w) in this frame; what
        /// flicker on the same surface point needs (Metrics.h, Reprojection). nullptr when the
        /// frame was drawn without a previous camera.
        const gl::Texture* motion;
        glm::mat4 viewProj;        // world -> clip, reversed Z (what drew the depth)
        glm::mat4 inverseViewProj; // its inverse, computed in double
        int width, height;
        /// The world positions (decoded from depth and inverseViewProj).
        [[nodiscard]] SurfacePositions positions() const { return {depth, inverseViewProj}; }
        enum class Normal { Shading, Plane };
        /// One of the two normals of every pixel, decoded, as RGBA floats (xyz, w = 0), row 0 at
        /// the top (readTexture's layout); stale values where positions() says background.
        [[nodiscard]] FloatImage readNormals(Normal which) const;
        /// The lift and the shading normals on the units surface_lookup.glsl reads them from.
        void bindLookup(gl::BindScope& scope) const;
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
    gl::Texture normals_, baseColor_, receivers_, lift_, motion_, depth_;
    gl::Framebuffer fbos_[2];
    bool motionWritten_ = false;
    glm::mat4 viewProj_{1.0f}, inverseViewProj_{1.0f};
};

} // namespace fl
