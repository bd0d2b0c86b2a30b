// raytrace: the ray-traced ground truth. Per pixel of the frame's surfaces (step 2), N shadow
// rays to stratified points of the disk light, cast on the CPU by Embree over the same
// triangles the GPU draws (raytrace/ShadowRays.h); visibility is the share nothing blocks. It
// uses no shadow map, so it carries none of the errors of the methods it judges. Each pixel's
// rays start on the triangle the eye sees there and skip it; with --terminator-offset on (the
// default) the smooth surface the vertex normals describe decides what the pixel faces, and rays
// that graze start on it (raytrace/ShadowRays.h, raytrace/Terminator.h), as Cycles does.

#include <renderer/methods/OptionStructs.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/passes/Phases.h>

#include <renderer/soft/ShadowRayInputs.h>

#include <optional>

namespace fl {

namespace {

class RayTrace final : public ShadowMethod {
  public:
    void resize(int width, int height) override {
        visibility_ = gl::Texture(GL_R32F, width, height);
    }

    const gl::Texture& execute(const FrameInputs& in) override {
        const int w = in.width(), h = in.height();
        if (visibility_.width() != w || visibility_.height() != h) resize(w, h);
        // The BVH once per scene, and again (refit: the same triangles, moved) whenever the
        // scene's pose changes.
        if (!bvh_ || posedVersion_ != in.scene.poseVersion()) {
            gl::TimedPass timedRaytraceBvh(in.timer, phase::kRaytraceBvh);
            if (!bvh_) bvh_.emplace(worldTriangles(in.scene.source()));
            if (const auto& pose = in.scene.pose()) {
                std::vector<glm::vec3> normals;
                const std::vector<glm::vec3> vertices =
                    worldVertices(in.scene.source(), *pose, &normals);
                bvh_->refit(vertices, normals);
            }
            posedVersion_ = in.scene.poseVersion();
            timedRaytraceBvh.end();
        }
        gl::TimedPass timedRaytraceRays(in.timer, phase::kRaytraceRays);
        // Receivers and visibility both in GL's row order.
        const std::vector<rt::Receiver> receivers = surfaceReceivers(in.surfaces);
        rt::VisibilitySettings s;
        const RayTraceOptions& o = in.options<RayTraceOptions>();
        s.samples = o.samples;
        s.jitter = !o.grid;
        s.terminatorOffset = o.terminatorOffset;
        s.eye = in.camera.eye;
        if (in.progress) s.progress = *in.progress;
        const rt::Disk disk{in.disk.center, in.disk.normal, in.disk.radius};
        const std::vector<float> v = rt::diskVisibility(*bvh_, disk, receivers, s);
        glTextureSubImage2D(visibility_.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, v.data());
        gl::throwIfErrors("raytrace: visibility upload");
        timedRaytraceRays.wrote(gl::textureBytes(visibility_)); // the upload
        timedRaytraceRays.end();
        return visibility_;
    }

  private:
    std::optional<rt::RayScene> bvh_;
    std::uint64_t posedVersion_ = 0; // the GpuScene pose the BVH holds
    gl::Texture visibility_;
};

} // namespace

std::unique_ptr<ShadowMethod> makeRayTrace(const gl::ShaderLibrary&) {
    return std::make_unique<RayTrace>();
}

} // namespace fl
