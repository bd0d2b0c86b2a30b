#pragma once
// Internals shared by the overlay implementations (renderer/src/overlays/*.cpp).

#include <renderer/overlays/Overlay.h>
#include <renderer/overlays/OverlayCanvas.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <geometry/Delaunay.h>
#include <jfa/NearestSite.h>
#include <jfa_gl/GlKernel.h>

#include <optional>
#include <string>
#include <vector>

namespace fl::overlay {

/// One draw() call's inputs; `framebuffer` is the draw framebuffer the overlay goes into (the
/// kernels bind their own, so it is re-bound before drawing).
struct Frame {
    const Renderer& renderer;
    const CameraView& camera;
    OverlayControls& controls;
    int width, height;
    GLint framebuffer;
    void bindTarget() const { glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(framebuffer)); }
};

/// The Delaunay visualiser's input and the pipeline's result, kept until new points come.
struct DelaunayCache {
    bool valid = false;
    std::uint32_t seed = 0;
    int points = 0;
    std::vector<glm::dvec2> input;
    geom::DelaunayResult result;
    std::string error; // why the pipeline refused the input
};

/// JfaVsFlood's reference flood, reused while its inputs are unchanged (a standard flood of a
/// 1024^2 map takes tens of seconds on llvmpipe; a still window must not redo it every frame).
struct ReferenceCache {
    std::vector<float> key; // matrices, light, plan and method the flood depended on
    jfa::Grid seeds;        // and the seeds
    jfa::Grid reference;
    gl::Texture texture;
    double ms = 0.0; // what computing it took
};

struct State {
    explicit State(const gl::ShaderLibrary& shaders);
    OverlayCanvas canvas;
    jfa::GlFloodKernel<jfa::NearestSite> siteKernel; // Voronoi, distance transform, playground
    OverlayResult result;
    DelaunayCache delaunay;
    ReferenceCache reference;
};

using Lines = std::vector<std::string>;

// FrameOverlays.cpp
Lines drawShadowMap(State& s, const Frame& f);
Lines drawSeeds(State& s, const Frame& f);
Lines drawPenumbraMap(State& s, const Frame& f);
Lines drawFloodPasses(State& s, const Frame& f);
Lines drawSiteDiagram(State& s, const Frame& f, bool distance);
Lines drawJfaVsFlood(State& s, const Frame& f);
// TrapezoidOverlay.cpp
Lines drawTrapezoid(State& s, const Frame& f);
// PlaygroundOverlay.cpp
Lines drawPlayground(State& s, const Frame& f);
// DelaunayOverlay.cpp
Lines drawDelaunay(State& s, const Frame& f);

/// Viewport NDC of a point given in texels of a size x size grid drawn over the whole viewport.
inline glm::vec2 texelToNdc(glm::dvec2 t, int size) {
    return glm::vec2((t + 0.5) / double(size) * 2.0 - 1.0);
}

} // namespace fl::overlay
