#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/PenumbraMap.h>

#include <jfa/CpuKernel.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fl {

int penumbraMaxPasses(int size) {
    int maxPasses = 0;
    while ((2 << maxPasses) <= size) ++maxPasses; // largest k with 2^k <= size
    return maxPasses;
}

jfa::Plan penumbraPlan(const PenumbraSettings& settings, int size) {
    const int maxPasses = penumbraMaxPasses(size);
    if (settings.passes < 1 || settings.passes > maxPasses)
        throw std::invalid_argument("JFA pass count " + std::to_string(settings.passes) +
                                    " is outside [1, " + std::to_string(maxPasses) + "] for a " +
                                    std::to_string(size) + "^2 shadow map");
    const int reach = (1 << settings.passes) - 1;
    if (settings.standardFlooding) return jfa::Plan::flood(reach, size, size);
    std::vector<int> steps;
    for (int s = 1 << (settings.passes - 1); s >= 1; s /= 2) steps.push_back(s);
    jfa::Stage stage;
    stage.width = size;
    stage.height = size;
    stage.steps = steps;
    return jfa::Plan("JFA " + std::to_string(settings.passes) + " passes", {stage});
}

jfa::Grid silhouetteSeeds(const ReceiverGrid& r, const DiskLight& light, float threshold) {
    jfa::Grid out(r.width, r.height, jfa::kEmptyCell);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const glm::vec4& self = r.at(x, y);
            if (self.w == 0.0f) continue;
            bool silhouette = false;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    const int qx = x + i, qy = y + j;
                    if ((i == 0 && j == 0) || qx < 0 || qy < 0 || qx >= r.width || qy >= r.height)
                        continue;
                    silhouette =
                        silhouette || acrossSilhouette(light, self, r.at(qx, qy), threshold);
                }
            if (silhouette) out.at(x, y) = {self.x, self.y, self.z, 1.0f};
        }
    return out;
}

PenumbraMapPass::PenumbraMapPass(const gl::ShaderLibrary& shaders)
    : silhouette_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                               {GL_FRAGMENT_SHADER, "silhouette.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()), kernel_(shaders, jfa::GlKernelKind::Fragment),
      bounds_(shaders) {}

PenumbraMapPass::Outputs PenumbraMapPass::execute(const Inputs& in, gl::PassTimer* timer) {
    const int size = in.receivers.width();
    if (in.settings.passes != 0)
        (void)penumbraPlan(in.settings, size); // validates before any GL work
    if (!seeds_ || seeds_.width() != size) {
        seeds_ = gl::Texture(GL_RGBA32F, size, size);
        fbo_ = gl::Framebuffer::forColor(seeds_, "silhouette seeds");
    }
    // Phase 2 (thesis; within frame step 3): silhouettes.
    if (timer) timer->begin("silhouettes");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, size, size);
    glDisable(GL_DEPTH_TEST);
    setDiskLightUniforms(silhouette_, in.light);
    silhouette_.set("uSilhouetteThreshold", in.threshold);
    // A banded flood lists its seeds here, in the pass that finds them, rather than sweeping
    // the map for them again (GlFloodKernelBase::beginSeedList).
    const bool listSeeds = in.settings.region == jfa::FloodRegion::Band;
    silhouette_.set("uListSeeds", listSeeds ? 1 : 0);
    if (listSeeds) kernel_.beginSeedList(size, size);
    glBindTextureUnit(0, in.receivers.id());
    gl::drawFullscreenTriangle(silhouette_, emptyVao_);
    glBindTextureUnit(0, 0);
    if (listSeeds) kernel_.seedsListed(seeds_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (timer) timer->end();
    // Phase 3: flood the occluders through the penumbra region; its band (jfa/Band.h) and,
    // with auto, its pass count first, timed apart.
    if (timer) timer->begin("band");
    PenumbraCriterion criterion;
    criterion.light = in.light;
    criterion.receiverTexture = in.receivers.id();
    criterion.reachBound = in.reach;
    if (criterion.reachBound.enabled) // receivers are the texels with w = 1
        bounds_.build(in.receivers, 0.5f, in.light, criterion.reachBound);
    kernel_.setRegion(in.settings.region, in.settings.bandTile);
    PenumbraSettings settings = in.settings;
    if (settings.passes == 0) // auto: one value read back, since the plan is recorded on the CPU
        settings.passes =
            jfa::passesForReach(kernel_.maxSeedReach(seeds_, criterion), penumbraMaxPasses(size));
    const jfa::Plan plan = penumbraPlan(settings, size);
    kernel_.prepareBand(plan, seeds_, criterion);
    if (timer) timer->end();
    if (timer) timer->begin("flood");
    const gl::Texture& map = kernel_.run(plan, seeds_, criterion);
    glBindTextureUnit(2, 0);
    unbindPenumbraReach();
    if (timer) timer->end();
    return {seeds_, map, kernel_.passesRun(), settings.passes};
}

} // namespace fl
