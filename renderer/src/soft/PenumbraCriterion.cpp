#include <renderer/soft/PenumbraCriterion.h>

namespace fl {

namespace {
// shaders/disk_light.glsl's light.
constexpr struct {
    gl::Uniform<glm::vec3> center{"uDiskCenter"};
    gl::Uniform<glm::vec3> normal{"uDiskNormal"};
    gl::Uniform<float> radius{"uDiskRadius"};
} kDiskLight;
constexpr gl::Uniform<float> kUmbraDepth{"uUmbraDepth"}; // disk_light.glsl, the criterion's
} // namespace

void setDiskLightUniforms(const gl::Program& program, const DiskLight& light) {
    program.set(kDiskLight.center, light.center);
    program.set(kDiskLight.normal, light.normal);
    program.set(kDiskLight.radius, light.radius);
}

void bindDiskLightUniforms(gl::Program& program) {
    program.bindUniforms({&kDiskLight.center, &kDiskLight.normal, &kDiskLight.radius});
}

void setCriterionUniforms(gl::BindScope& scope, const gl::Program& program,
                          const PenumbraCriterion& criterion) {
    setDiskLightUniforms(program, criterion.light);
    setPenumbraReachUniforms(scope, program, criterion.reachBound);
    program.set(kUmbraDepth, criterion.umbraDepth);
    criterion.map.bind(scope, program, gl::bind::PenumbraPositions);
}

void bindCriterionUniforms(gl::Program& program, const PenumbraCriterion* /*criterion*/) {
    bindDiskLightUniforms(program);
    bindPenumbraReachUniforms(program);
    program.bindUniforms({&kUmbraDepth});
    MapPositions::bindUniforms(program);
}

} // namespace fl
