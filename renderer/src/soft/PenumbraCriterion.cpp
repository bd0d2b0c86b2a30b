#include <renderer/soft/PenumbraCriterion.h>

namespace fl {

void setDiskLightUniforms(const gl::Program& program, const DiskLight& light) {
    program.set("uDiskCenter", light.center);
    program.set("uDiskNormal", light.normal);
    program.set("uDiskRadius", light.radius);
}

void setCriterionUniforms(gl::BindScope& scope, const gl::Program& program,
                          const PenumbraCriterion& criterion) {
    setDiskLightUniforms(program, criterion.light);
    setPenumbraReachUniforms(scope, program, criterion.reachBound);
    program.set("uUmbraDepth", criterion.umbraDepth);
    criterion.map.bind(scope, program, gl::bind::PenumbraPositions);
}

} // namespace fl
