#pragma once
// The flooding criterion of JFA-L (and JFA-E's occluder propagation), thesis §5.2-5.3, for the
// jfa/ kernels: the CPU functor here and shaders/jfa_penumbra.glsl for the GL kernels, which
// agree bit for bit. See the GLSL file for the rule.

#include <renderer/passes/ShadowMapDecode.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/soft/PenumbraReach.h>
#include <scene/DiskLight.h>

#include <jfa/Grid.h>

#include <gpu/Gl.h>
#include <gpu/Program.h>

#include <glm/glm.hpp>

#include <limits>
#include <vector>

namespace fl {

/// Per texel of the flooded grid: the receiver's world position (xyz, w = 1) or w = 0 where
/// nothing is there. Row-major, the grid's size.
struct ReceiverGrid {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> points;
    [[nodiscard]] const glm::vec4& at(int x, int y) const {
        return points[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
};

struct PenumbraCriterion {
    static constexpr const char* glslFile = "jfa_penumbra.glsl";
    static constexpr bool keyed = true; // the GLSL has jfaKey (jfa_select.glsl)
    /// GL grids hold a cell as its seed's tag alone (R32F; jfaLoad rebuilds the occluder from
    /// the map's receiver target): readPenumbraGrid turns one back into cells.
    static constexpr bool packedCells = true;
    DiskLight light;
    const ReceiverGrid* receivers = nullptr; // CPU kernel
    MapPositions map; // GL kernels: the shadow map's receiver target (decoded in the shader)
    PenumbraReach reachBound; // the shadow map's: bounds the band (jfa/Band.h)
    /// --penumbra both: the deepest a receiver lies (reachBound's farDepth), where a texel whose
    /// own surface takes no occluder places the receiver it may hide (umbraSideKey); 0: the
    /// thesis' outer penumbra only.
    float umbraDepth = 0.0f;

    /// Band-limited flooding: the widest penumbra occluder c (seeded at its own texel) can cast.
    [[nodiscard]] jfa::ReachRect reach(int, int, const jfa::Cell& c) const {
        return penumbraReachRect(light, reachBound, {c.x, c.y, c.z});
    }

    /// The ranking key of occluder c at receiver r of texel (px, py): |cq|^2 if its ray reaches
    /// the light; with umbraDepth, else umbraSideKey (the receiver r may hide); the largest float
    /// if c is the seed of this very texel (its w is the texel's shadowmap::seedTag: a silhouette
    /// texel keeps its own occluder, so JFA's later passes can still pass it on) and no umbra-side
    /// key is found; -1 (rejected) otherwise.
    [[nodiscard]] float key(int px, int py, glm::vec3 r, const jfa::Cell& c) const {
        const bool own = c.w == shadowmap::seedTag(px, py, receivers->width);
        const glm::vec3 o(c.x, c.y, c.z);
        float k = own ? -1.0f : occluderHitDistance2(light, r, o);
        if (k < 0.0f && umbraDepth > 0.0f) k = umbraSideKey(light, r, o, umbraDepth);
        return own && k < 0.0f ? std::numeric_limits<float>::max() : k;
    }
    [[nodiscard]] bool empty(const jfa::Cell& c) const { return c.w == 0.0f; }
    [[nodiscard]] bool accepts(int px, int py, const jfa::Cell& c) const {
        const glm::vec4& r = receivers->at(px, py);
        return r.w != 0.0f && key(px, py, glm::vec3(r), c) >= 0.0f;
    }
    [[nodiscard]] bool better(int px, int py, const jfa::Cell& a, const jfa::Cell& b) const {
        const glm::vec3 r(receivers->at(px, py));
        const float da = key(px, py, r, a);
        const float db = key(px, py, r, b);
        const bool tieWins = a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
        return da < db || (da == db && tieWins);
    }
};

/// Sets the disk-light uniforms (shaders/disk_light.glsl) of any program that includes it.
void setDiskLightUniforms(const gl::Program& program, const DiskLight& light);
/// Binds the uniforms setDiskLightUniforms sets on `program`.
void bindDiskLightUniforms(gl::Program& program);
/// The GL kernels' hook (found by argument-dependent lookup from jfa::GlFloodKernel::run):
/// binds the map's receiver target (gl::bind::PenumbraPositions) and the reach bounds in the
/// run's `scope` and sets the light.
void setCriterionUniforms(gl::BindScope& scope, const gl::Program& program,
                          const PenumbraCriterion& criterion);
/// Binds the uniforms setCriterionUniforms sets on a kernel program (the GL kernels' other
/// hook; the pointer only chooses the overload).
void bindCriterionUniforms(gl::Program& program, const PenumbraCriterion*);

} // namespace fl
