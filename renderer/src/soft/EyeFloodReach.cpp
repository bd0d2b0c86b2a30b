#include <renderer/soft/EyeFloodReach.h>

#include <jfa/CpuKernel.h>

#include <algorithm>
#include <cstdlib>

namespace fl {

glm::ivec2 coarseSize(int width, int height, int factor) {
    return {(width + factor - 1) / factor, (height + factor - 1) / factor};
}

EyeImage coarseEyeImage(const EyeImage& image, int factor) {
    const glm::ivec2 size = coarseSize(image.width, image.height, factor);
    EyeImage out{size.x, size.y, {}, {}};
    out.points.reserve(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y));
    out.occluders.reserve(out.points.capacity());
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const int sx = std::min(x * factor + factor / 2, image.width - 1);
            const int sy = std::min(y * factor + factor / 2, image.height - 1);
            out.points.push_back(image.points[image.index(sx, sy)]);
            out.occluders.push_back(image.occluders[image.index(sx, sy)]);
        }
    return out;
}

BoundaryThreshold coarseThreshold(BoundaryThreshold frame, int factor) {
    // Both terms are squared distances: a neighbour one coarse pixel away lies `factor` frame
    // pixels away, so the footprint (relative) and a fixed distance (absolute) both scale.
    const float f2 = static_cast<float>(factor * factor);
    return {frame.absolute2 * f2, frame.relative2 * f2};
}

std::vector<std::uint32_t> floodTravel(const jfa::Grid& flooded) {
    std::vector<std::uint32_t> bins(kTravelBins, 0u);
    for (int y = 0; y < flooded.height; ++y)
        for (int x = 0; x < flooded.width; ++x) {
            const jfa::Cell& c = flooded.at(x, y);
            if (c.w == 0.0f) continue;
            // Same operations as shaders/jfae_travel.comp.glsl.
            const int index = static_cast<int>(c.w) - 1;
            const int dx = std::abs(x - index % flooded.width);
            const int dy = std::abs(y - index / flooded.width);
            ++bins[static_cast<std::size_t>(std::min(std::max(dx, dy), kTravelBins - 1))];
        }
    return bins;
}

int maxTravel(const std::vector<std::uint32_t>& histogram) {
    for (int d = static_cast<int>(histogram.size()) - 1; d >= 0; --d)
        if (histogram[static_cast<std::size_t>(d)] != 0u) return d;
    return -1;
}

int passesForTravel(int travel, int factor, int maxPasses) {
    if (travel < 0) return jfa::passesForReach(-1, maxPasses);
    return jfa::passesForReach(static_cast<long long>(factor) * (travel + 1) - 1, maxPasses);
}

std::vector<std::uint32_t> coarseFloodTravel(const EyeImage& image, const CoarseFloodSettings& s) {
    const EyeImage coarse = coarseEyeImage(image, s.factor);
    const int passes = eyeSoftMaxPasses(coarse.width, coarse.height);
    if (passes < 1) return {};
    const jfa::Grid seeds = eyeBoundarySeeds(coarse, s.eye, coarseThreshold(s.threshold, s.factor));
    EyeSoftCriterion criterion;
    criterion.light = s.light;
    criterion.objectIdFix = s.objectIdFix;
    criterion.midpointFix = s.midpointFix;
    criterion.image = &coarse;
    const jfa::Plan plan = eyeSoftPlan(passes, false, coarse.width, coarse.height);
    return floodTravel(jfa::flood(plan, seeds, criterion));
}

EyeFloodEstimator::EyeFloodEstimator(const gl::ShaderLibrary& shaders)
    : boundary_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "jfae_boundary.frag.glsl"}})),
      travel_(gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "jfae_travel.comp.glsl"}})),
      emptyVao_(gl::VertexArray::create()),
      bins_(static_cast<GLsizeiptr>(kTravelBins * sizeof(std::uint32_t)), nullptr),
      kernel_(shaders, jfa::GlKernelKind::Fragment) {
    bindBoundaryUniforms(boundary_);
}

void EyeFloodEstimator::resize(glm::ivec2 size) {
    if (seeds_ && seeds_.width() == size.x && seeds_.height() == size.y) return;
    seeds_ = gl::Texture(GL_R32F, size.x, size.y);            // packed cells (EyeSoftCriterion)
    seedOccluders_ = gl::Texture(GL_RGBA32F, size.x, size.y); // eyeSeedOccluder
    seedsFbo_ =
        gl::Framebuffer::withTargets({&seeds_, &seedOccluders_}, nullptr, "JFA-E coarse seeds");
}

std::vector<std::uint32_t> EyeFloodEstimator::travel(const EyeCells& eye,
                                                     const CoarseFloodSettings& s) {
    const glm::ivec2 size = coarseSize(eye.width(), eye.height(), s.factor);
    const int passes = eyeSoftMaxPasses(size.x, size.y);
    if (passes < 1) return {};
    resize(size);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, size.x, size.y);

    // The coarse phase 3 on the frame's phase 2, one pixel in factor² (read in place through
    // EyeCells::bind's factor, no coarse copy): the same boundary rule.
    const BoundaryThreshold th = coarseThreshold(s.threshold, s.factor);
    glBindFramebuffer(GL_FRAMEBUFFER, seedsFbo_.id());
    setBoundaryUniforms(boundary_, s.eye, th, false);
    {
        gl::BindScope scope;
        eye.bind(scope, boundary_, s.factor);
        gl::drawFullscreenTriangle(boundary_, emptyVao_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    // The coarse phase 4: full JFA on the whole coarse grid (no band: it is small).
    EyeSoftCriterion criterion;
    criterion.light = s.light;
    criterion.objectIdFix = s.objectIdFix;
    criterion.midpointFix = s.midpointFix;
    EyeCells coarse = eye; // the coarse grid's seeds, with their own occluders
    coarse.seedOccluders = &seedOccluders_;
    criterion.cells = &coarse;
    criterion.cellsFactor = s.factor;
    const jfa::Plan plan = eyeSoftPlan(passes, false, size.x, size.y);
    const gl::Texture& flooded = kernel_.run(plan, seeds_, criterion);

    // How far each cell travelled, one histogram for the frame.
    const std::uint32_t zero = 0;
    glClearNamedBufferData(bins_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glUseProgram(travel_.id());
    gl::BindScope scope;
    scope.texture(gl::bind::Flooded, flooded.id()).storage(gl::bind::TravelBins, bins_.id());
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glDispatchCompute(GLuint((size.x + 7) / 8), GLuint((size.y + 7) / 8), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    scope.release();
    glUseProgram(0);
    std::vector<std::uint32_t> bins(kTravelBins, 0u);
    bytes_ = gl::textureBytes(seeds_) + gl::textureBytes(seedOccluders_) +
             std::int64_t(plan.passCount()) * gl::textureBytes(flooded) +
             std::int64_t(bins.size() * sizeof(bins[0]));
    glGetNamedBufferSubData(bins_.id(), 0, static_cast<GLsizeiptr>(bins.size() * sizeof(bins[0])),
                            bins.data());
    return bins;
}

} // namespace fl
