// raytrace: the ray-traced ground truth. Per pixel of the frame's surfaces (step 2), N shadow
// rays to stratified points of the disk light, cast on the CPU by Embree over the same
// triangles the GPU draws (raytrace/ShadowRays.h); visibility is the share nothing blocks. It
// uses no shadow map, so it carries none of the errors of the methods it judges.

#include <renderer/methods/ShadowMethod.h>

#include <raytrace/ShadowRays.h>

#include <base/Text.h>

#include <cmath>
#include <optional>
#include <stdexcept>

namespace fl {

namespace {

// Every instance's triangles in world space (as the vertex stage places them). A vertex that a
// node's transform takes beyond what Embree's floats hold is refused here, naming the node and
// the mesh (the loader has already refused non-finite input).
rt::Triangles worldTriangles(const Scene& scene) {
    rt::Triangles t;
    for (const Instance& inst : scene.instances) {
        const Mesh& m = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        const auto base = static_cast<std::uint32_t>(t.vertices.size());
        for (std::size_t v = 0; v < m.positions.size(); ++v) {
            const glm::vec3 p(inst.world * glm::vec4(m.positions[v], 1.0f));
            for (int a = 0; a < 3; ++a)
                if (!(std::abs(p[a]) <= rt::kMaxCoordinate))
                    throw std::invalid_argument(cat("raytrace: node '", inst.nodeName, "' (mesh '",
                                                    m.name, "'): vertex ", v, " lands at ", p[a],
                                                    " in the world, beyond Embree's range (+-",
                                                    rt::kMaxCoordinate, ")"));
            t.vertices.push_back(p);
        }
        for (std::uint32_t i : m.indices) t.indices.push_back(base + i);
    }
    return t;
}

class RayTrace final : public ShadowMethod {
  public:
    void resize(int width, int height) override {
        visibility_ = gl::Texture(GL_R32F, width, height);
    }

    const gl::Texture& execute(const FrameInputs& in) override {
        const int w = in.width(), h = in.height();
        if (visibility_.width() != w || visibility_.height() != h) resize(w, h);
        // The BVH once per scene (a static scene: the renderer's scene never changes).
        if (!bvh_) {
            if (in.timer) in.timer->begin("raytrace bvh");
            bvh_.emplace(worldTriangles(in.scene.source()));
            if (in.timer) in.timer->end();
        }
        if (in.timer) in.timer->begin("raytrace rays");
        // The surfaces in GL's row order (row 0 at the bottom), and visibility back in the same.
        const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        const auto read = [&](const gl::Texture& t) {
            std::vector<float> v(4 * pixels);
            glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT,
                              static_cast<GLsizei>(v.size() * sizeof(float)), v.data());
            return v;
        };
        const std::vector<float> position = read(in.surfaces.position),
                                 plane = read(in.surfaces.plane), normal = read(in.surfaces.normal);
        gl::throwIfErrors("raytrace: surfaces read-back");
        std::vector<rt::Receiver> receivers(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            const auto at = [i](const std::vector<float>& v) {
                return glm::vec3(v[4 * i], v[4 * i + 1], v[4 * i + 2]);
            };
            // The triangle's plane, turned to the seen side (the shading normal faces the eye).
            glm::vec3 n = at(plane);
            if (glm::dot(n, at(normal)) < 0.0f) n = -n;
            receivers[i] = {at(position), n, position[4 * i + 3] != 0.0f}; // w = 0: background
        }
        rt::VisibilitySettings s;
        s.samples = in.integer("samples");
        s.jitter = !in.flag("grid");
        if (in.progress) s.progress = *in.progress;
        const rt::Disk disk{in.disk.center, in.disk.normal, in.disk.radius};
        const std::vector<float> v = rt::diskVisibility(*bvh_, disk, receivers, s, &rays_);
        glTextureSubImage2D(visibility_.id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, v.data());
        gl::throwIfErrors("raytrace: visibility upload");
        if (in.timer) in.timer->end();
        return visibility_;
    }

  private:
    std::optional<rt::RayScene> bvh_;
    gl::Texture visibility_;
    std::uint64_t rays_ = 0;
};

} // namespace

std::unique_ptr<ShadowMethod> makeRayTrace(const gl::ShaderLibrary&) {
    return std::make_unique<RayTrace>();
}

} // namespace fl
