#include <renderer/passes/Phases.h>
#include <renderer/soft/EyeSoftShadow.h>

#include <renderer/passes/ShadowMapDecode.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>
#include <renderer/soft/EyeFloodReach.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <jfa/CpuKernel.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace fl {

namespace {

// jfae_criterion.glsl's own uniforms (the disk light's, the reach's and the eye cells' apart).
constexpr struct {
    gl::Uniform<int> objectIdFix{"uObjectIdFix"};
    gl::Uniform<int> midpointFix{"uMidpointFix"};
} kEyeCriterion;

// The JFA-E passes' own uniforms: the occluder ids drawn from the light (shadow_depth.vert.glsl),
// the eye pass, the boundary seeds and the composite.
const ShadowDepthUniforms& kEyeLightIds = kShadowDepthUniforms;
constexpr struct {
    gl::Uniform<int> occluderEdges{"uOccluderEdges"};
    gl::Uniform<float> silhouetteThreshold{"uSilhouetteThreshold"};
} kEyePass;
constexpr struct {
    gl::Uniform<glm::vec3> eye{"uEye"};
    gl::Uniform<float> absolute2{"uAbsolute2"};
    gl::Uniform<float> relative2{"uRelative2"};
    gl::Uniform<int> listSeeds{"uListSeeds"};
    gl::Uniform<int> seedWalk{"uSeedWalk"};
    gl::Uniform<float> silhouetteThreshold{"uSilhouetteThreshold"};
} kEyeBoundary;
constexpr gl::Uniform<int> kCompositeOccluderEdges{"uOccluderEdges"};

} // namespace

BoundaryThreshold boundaryThreshold(const EyeSoftSettings& settings, const glm::mat4& proj,
                                    int height) {
    BoundaryThreshold t;
    if (settings.boundaryThreshold > 0.0f) {
        t.absolute2 = settings.boundaryThreshold * settings.boundaryThreshold;
        return t;
    }
    // A pixel's footprint at distance d (facing the eye) is d * 2 / (proj[1][1] * height) for a
    // perspective projection; the distance to the eye stands in for the view depth (a little
    // larger off-axis, so the threshold errs towards finding boundaries).
    const float perUnit = 2.0f / (std::abs(proj[1][1]) * static_cast<float>(std::max(height, 1)));
    const float rel = kBoundaryFootprints * perUnit;
    t.relative2 = rel * rel;
    return t;
}

int eyeSoftMaxPasses(int width, int height) {
    return jfa::jfaMaxPasses(std::max(width, height));
}

jfa::Plan eyeSoftPlan(int passes, bool standardFlooding, int width, int height) {
    const int maxPasses = eyeSoftMaxPasses(width, height);
    if (passes < 1 || passes > maxPasses)
        throw std::invalid_argument("JFA-E pass count " + std::to_string(passes) +
                                    " is outside [1, " + std::to_string(maxPasses) + "] for a " +
                                    std::to_string(width) + "x" + std::to_string(height) +
                                    " frame");
    if (static_cast<long long>(width) * height >= (1LL << 24))
        throw std::invalid_argument("JFA-E frames must have fewer than 2^24 pixels");
    const int reach = (1 << passes) - 1;
    if (standardFlooding) return jfa::Plan::flood(reach, width, height);
    jfa::Stage stage;
    stage.width = width;
    stage.height = height;
    for (int s = 1 << (passes - 1); s >= 1; s /= 2) stage.steps.push_back(s);
    return jfa::Plan("JFA-E " + std::to_string(passes) + " passes", {stage});
}

glm::vec3 boundaryOccluderPoint(const BoundaryWalk& w, int width, int x, int y, int qx, int qy) {
    // Same operations as boundaryOccluder() in shaders/jfae_boundary.frag.glsl.
    const auto texelOf = [&](int px, int py) {
        return eyecell::texel(w.cells[static_cast<std::size_t>(py) * width + px]);
    };
    const glm::ivec2 a = texelOf(x, y), d = texelOf(qx, qy) - a;
    constexpr int kMaxWalk = 16;
    const int n = std::min(std::max(std::abs(d.x), std::abs(d.y)), kMaxWalk);
    glm::ivec2 k = a;
    glm::vec4 last = w.receivers.at(a.x, a.y);
    for (int i = 1; i <= n; ++i) {
        const glm::ivec2 c = a + glm::sign(d) * ((2 * glm::abs(d) * i + n) / (2 * n));
        const glm::vec4 next = w.receivers.at(c.x, c.y);
        if (acrossSilhouette(w.light, last, next, w.threshold)) break;
        k = c;
        last = next;
    }
    return occluderEdgePoint(w.receivers, w.light, k.x, k.y, w.threshold);
}

jfa::Grid eyeBoundarySeeds(const EyeImage& im, glm::vec3 eye, BoundaryThreshold th,
                           const BoundaryWalk* walk) {
    jfa::Grid out(im.width, im.height, jfa::kEmptyCell);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const glm::vec4& self = im.points[im.index(x, y)];
            if (self.w != 1.0f) continue;
            // Same operations as shaders/jfae_boundary.frag.glsl.
            const float ex = self.x - eye.x, ey = self.y - eye.y, ez = self.z - eye.z;
            const float e2 = ex * ex + ey * ey + ez * ez;
            const float limit2 = th.absolute2 + th.relative2 * e2;
            bool boundary = false;
            glm::ivec2 nearest(x, y); // the nearest lit neighbour within the limit
            float nearest2 = 0.0f;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    const int qx = x + i, qy = y + j;
                    if (qx < 0 || qy < 0 || qx >= im.width || qy >= im.height) continue;
                    const glm::vec4& n = im.points[im.index(qx, qy)];
                    if (n.w != 0.0f) continue;
                    const float dx = n.x - self.x, dy = n.y - self.y, dz = n.z - self.z;
                    const float d2 = dx * dx + dy * dy + dz * dz;
                    if (d2 < limit2 && (!boundary || d2 < nearest2)) {
                        nearest = {qx, qy};
                        nearest2 = d2;
                    }
                    boundary = boundary || d2 < limit2;
                }
            if (!boundary) continue;
            glm::vec3 o(im.occluders[im.index(x, y)]);
            if (walk) o = boundaryOccluderPoint(*walk, im.width, x, y, nearest.x, nearest.y);
            out.at(x, y) = {o.x, o.y, o.z, static_cast<float>(y * im.width + x + 1)};
        }
    return out;
}

bool EyeSoftCriterion::accepts(int px, int py, const jfa::Cell& c) const {
    // Same rule and operations as jfaAccept() in shaders/jfae_criterion.glsl.
    const glm::vec4& r = image->points[image->index(px, py)];
    const int index = static_cast<int>(c.w) - 1;
    const int sx = index % image->width, sy = index / image->width;
    const glm::vec3 o(c.x, c.y, c.z);
    if (!(r.w >= 0.0f) || occluderHitDistance2(light, glm::vec3(r), o) < 0.0f) return false;
    if (objectIdFix && r.w == 1.0f &&
        image->occluders[image->index(px, py)].w != image->occluders[image->index(sx, sy)].w)
        return false;
    if (midpointFix) {
        const glm::vec4& m = image->points[image->index((px + sx) / 2, (py + sy) / 2)];
        if (!(m.w >= 0.0f) || occluderHitDistance2(light, glm::vec3(m), o) < 0.0f) return false;
    }
    return true;
}

bool EyeSoftCriterion::better(int px, int py, const jfa::Cell& a, const jfa::Cell& b) const {
    const glm::vec3 r(image->points[image->index(px, py)]);
    const float da = occluderHitDistance2(light, r, {a.x, a.y, a.z});
    const float db = occluderHitDistance2(light, r, {b.x, b.y, b.z});
    const bool tieWins =
        a.x < b.x ||
        (a.x == b.x && (a.y < b.y || (a.y == b.y && (a.z < b.z || (a.z == b.z && a.w < b.w)))));
    return da < db || (da == db && tieWins);
}

void setCriterionUniforms(gl::BindScope& scope, const gl::Program& program,
                          const EyeSoftCriterion& criterion) {
    setDiskLightUniforms(program, criterion.light);
    setPenumbraReachUniforms(scope, program, criterion.reachBound);
    program.set(kEyeCriterion.objectIdFix, criterion.objectIdFix ? 1 : 0);
    program.set(kEyeCriterion.midpointFix, criterion.midpointFix ? 1 : 0);
    if (criterion.cells != nullptr) criterion.cells->bind(scope, program, criterion.cellsFactor);
}

void setBoundaryUniforms(const gl::Program& program, glm::vec3 eye, BoundaryThreshold th,
                         bool listSeeds, const DiskLight* walkLight, float silhouetteThreshold) {
    program.set(kEyeBoundary.eye, eye);
    program.set(kEyeBoundary.absolute2, th.absolute2);
    program.set(kEyeBoundary.relative2, th.relative2);
    program.set(kEyeBoundary.listSeeds, listSeeds ? 1 : 0);
    program.set(kEyeBoundary.seedWalk, walkLight ? 1 : 0);
    if (!walkLight) return;
    program.set(kEyeBoundary.silhouetteThreshold, silhouetteThreshold);
    setDiskLightUniforms(program, *walkLight); // the walk's silhouette test (silhouetteDepth)
}

void bindBoundaryUniforms(gl::Program& program) {
    const auto& b = kEyeBoundary;
    program.bindUniforms(
        {&b.eye, &b.absolute2, &b.relative2, &b.listSeeds, &b.seedWalk, &b.silhouetteThreshold});
    bindDiskLightUniforms(program);
    EyeCells::bindUniforms(program);
}

void bindCriterionUniforms(gl::Program& program, const EyeSoftCriterion* /*criterion*/) {
    bindDiskLightUniforms(program);
    bindPenumbraReachUniforms(program);
    program.bindUniforms({&kEyeCriterion.objectIdFix, &kEyeCriterion.midpointFix});
    EyeCells::bindUniforms(program);
}

jfa::Grid readEyeGrid(const gl::Texture& packed, const jfa::Grid& occluders) {
    return jfa::readPackedGrid(packed, occluders, [](float w) -> std::size_t {
        return static_cast<std::size_t>(w) - 1; // w = the seed pixel's index + 1
    });
}

namespace {

// jfae_composite.frag.glsl's borrowedCell: an axis neighbour's occluder, if it lies on the
// pixel's own surface (within 30 degrees of its plane); nullptr for none.
const jfa::Cell* borrowedCell(const EyeImage& im, const jfa::Grid& flooded, int x, int y,
                              glm::vec3 p, glm::vec3 plane) {
    const glm::ivec2 axis[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const glm::ivec2 a : axis) {
        const int qx = x + a.x, qy = y + a.y;
        if (qx < 0 || qy < 0 || qx >= im.width || qy >= im.height) continue;
        const jfa::Cell& c = flooded.cells[im.index(qx, qy)];
        if (c.w == 0.0f) continue;
        const glm::vec4& n = im.points[im.index(qx, qy)];
        const glm::vec3 d = glm::vec3(n) - p;
        if (n.w >= 0.0f && std::abs(glm::dot(d, plane)) <= 0.5f * glm::length(d)) return &c;
    }
    return nullptr;
}

// jfae_composite.frag.glsl's seedWindowTexel: where the edges' window centres when the pixel's
// own texel has none; the GLSL says why.
glm::ivec2 seedWindowTexel(const CompositeEdges& e, std::size_t seed, glm::vec3 o) {
    const glm::ivec2 own = eyecell::texel(e.cells[seed]);
    const glm::vec3 centre(lineMapReceiver(e.map, own));
    const glm::vec3 q = o + 0.25f * (centre - o);
    const std::optional<glm::vec3> uvz = shadowmap::mapCoord(e.map.lightViewProj, e.map.warp, q);
    if (!uvz || glm::any(glm::lessThan(*uvz, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThan(*uvz, glm::vec3(1.0f))))
        return own;
    return glm::clamp(glm::ivec2(glm::vec2(*uvz) * float(e.map.size)), glm::ivec2(0),
                      glm::ivec2(e.map.size - 1));
}

// One pixel of the composite with edges (the shader's main()).
float compositeWithEdges(const EyeImage& im, const jfa::Grid& flooded, const DiskLight& light,
                         const CompositeEdges& e, int x, int y) {
    const std::size_t i = im.index(x, y);
    const glm::vec4& r = im.points[i];
    const glm::vec3 plane = e.planes[i];
    const jfa::Cell* cell = &flooded.cells[i];
    const bool inside = r.w == 1.0f;
    float v = inside ? 0.0f : 1.0f;
    bool borrowed = false;
    if (cell->w == 0.0f && r.w >= 0.0f && light.radius > 0.0f) {
        const jfa::Cell* b = borrowedCell(im, flooded, x, y, glm::vec3(r), plane);
        borrowed = b != nullptr;
        if (b) cell = b;
    }
    if (r.w < 0.0f || cell->w == 0.0f) return v;
    const std::size_t seed = static_cast<std::size_t>(cell->w) - 1;
    // The seed's occluder as the flood carried it (phase 3's, eyeSeedOccluder in the shader).
    const glm::vec3 o(cell->x, cell->y, cell->z);
    float intensity = -1.0f;
    if (!borrowed)
        if (const std::optional<float> k = occluderIntensity(light, glm::vec3(r), o, inside))
            intensity = *k;
    if (intensity >= 0.0f || borrowed) {
        const glm::ivec2 own = eyecell::texel(e.cells[i]);
        OccluderLines lines = occluderLines(e.map, own, glm::vec3(r), plane);
        if (lines.count == 0)
            lines = occluderLines(e.map, seedWindowTexel(e, seed, o), glm::vec3(r), plane);
        const float l =
            occluderShareFused(e.map, own, glm::vec3(r), plane, lines, o, inside, borrowed);
        intensity = l < 0.0f ? intensity : l;
    }
    return intensity < 0.0f ? v : intensity;
}

} // namespace

FloatImage eyeSoftVisibility(const EyeImage& im, const jfa::Grid& flooded, const DiskLight& light,
                             const CompositeEdges* edges) {
    FloatImage out{im.width, im.height, 1, std::vector<float>(im.points.size(), 1.0f)};
    if (edges) {
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                out.data[im.index(x, y)] = compositeWithEdges(im, flooded, light, *edges, x, y);
        return out;
    }
    for (std::size_t i = 0; i < im.points.size(); ++i) {
        const glm::vec4& r = im.points[i];
        const jfa::Cell& c = flooded.cells[i];
        const bool inside = r.w == 1.0f;
        float v = inside ? 0.0f : 1.0f;
        if (r.w >= 0.0f && c.w != 0.0f) {
            const std::optional<float> intensity =
                occluderIntensity(light, glm::vec3(r), {c.x, c.y, c.z}, inside);
            if (intensity) v = *intensity;
        }
        out.data[i] = v;
    }
    return out;
}

EyeSoftShadowPass::EyeSoftShadowPass(const gl::ShaderLibrary& shaders)
    : lightIds_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "jfae_light_id.frag.glsl"}})),
      eyePass_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "jfae_eye.frag.glsl"}})),
      boundary_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "jfae_boundary.frag.glsl"}})),
      composite_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                              {GL_FRAGMENT_SHADER, "jfae_composite.frag.glsl"}})),
      compositeEdges_(gl::Program::build(shaders,
                                         {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                          {GL_FRAGMENT_SHADER, "jfae_composite.frag.glsl"}},
                                         {"COMPOSITE_EDGES 1"})),
      unpack_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                           {GL_FRAGMENT_SHADER, "jfae_unpack.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()), kernel_(shaders, jfa::GlKernelKind::Fragment),
      bounds_(shaders), shaders_(shaders) {
    const auto& l = kEyeLightIds;
    lightIds_.bindUniforms({&l.lightViewProj, &l.warp, &l.slopeBias, &l.constantBias});
    eyePass_.bindUniforms({&kEyePass.occluderEdges, &kEyePass.silhouetteThreshold});
    bindDiskLightUniforms(eyePass_);
    bindShadowMapUniforms(eyePass_);
    SurfacePositions::bindUniforms(eyePass_);
    MapPositions::bindUniforms(eyePass_);
    bindBoundaryUniforms(boundary_);
    for (gl::Program* composite : {&composite_, &compositeEdges_}) {
        composite->bindUniforms({&kCompositeOccluderEdges});
        bindDiskLightUniforms(*composite);
        EyeCells::bindUniforms(*composite);
        bindShadowMapUniforms(*composite);
    }
    EyeCells::bindUniforms(unpack_);
}

EyeSoftShadowPass::~EyeSoftShadowPass() = default;

void EyeSoftShadowPass::prepare(const Inputs& in) {
    const int shadowSize = in.shadow.depth.width();
    if (shadowSize > eyecell::kMaxMapSize)
        throw std::invalid_argument("JFA-E's eye cells address shadow maps up to " +
                                    std::to_string(eyecell::kMaxMapSize) + " texels per side");
    resize(in.width, in.height, shadowSize);
    eye_ = {&cells_,
            &in.positions.depth,
            in.positions.inverseViewProj,
            *in.shadow.receivers,
            &ids_,
            in.settings.objectIdFix,
            this,
            nullptr}; // seed occluders: phase 3 writes them
    decodedStale_ = true;
}

void EyeSoftShadowPass::resize(int width, int height, int shadowSize) {
    if (!ids_ || ids_.width() != shadowSize) ids_ = gl::Texture(GL_R32F, shadowSize, shadowSize);
    if (cells_ && cells_.width() == width && cells_.height() == height) return;
    cells_ = gl::Texture(GL_R32UI, width, height); // packed eye cells (EyeDecode.h)
    seeds_ = gl::Texture(GL_R32F, width, height);  // packed flood cells (EyeSoftCriterion)
    seedOccluders_ = gl::Texture(GL_RGBA32F, width, height); // eyeSeedOccluder
    visibility_ = gl::Texture(GL_R32F, width, height);
    mask_ = gl::Texture(GL_DEPTH_COMPONENT16, width, height);
    eyeFbo_ = gl::Framebuffer::forColor(cells_, "JFA-E eye pass");
    seedsFbo_ =
        gl::Framebuffer::withTargets({&seeds_, &seedOccluders_}, nullptr, "JFA-E boundary seeds");
    visibilityFbo_ = gl::Framebuffer::withTargets({&visibility_}, &mask_, "JFA-E visibility");
}

void EyeSoftShadowPass::drawOccluderIds(const Inputs& in) {
    const int shadowSize = in.shadow.depth.width();
    const gl::Framebuffer fbo =
        gl::Framebuffer::withTargets({&ids_}, &in.shadow.depth, "JFA-E occluder ids");
    const float none = -1.0f;
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, &none);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, shadowSize, shadowSize);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    lightIds_.set(kEyeLightIds.lightViewProj, in.shadow.lightViewProj);
    lightIds_.set(kEyeLightIds.warp, in.shadow.warp);
    lightIds_.set(kEyeLightIds.slopeBias, in.shadowSettings.slopeBias);
    lightIds_.set(kEyeLightIds.constantBias, in.shadowSettings.constantBias);
    in.scene.draw(lightIds_, GpuScene::Uniforms::Material);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void EyeSoftShadowPass::drawEyeHardShadows(const Inputs& in) {
    glBindFramebuffer(GL_FRAMEBUFFER, eyeFbo_.id());
    glViewport(0, 0, in.width, in.height);
    glDisable(GL_DEPTH_TEST);
    eyePass_.set(kEyePass.occluderEdges,
                 in.settings.occluderPoints == OccluderPoints::Edge ? 1 : 0);
    eyePass_.set(kEyePass.silhouetteThreshold, in.settings.silhouetteThreshold);
    setDiskLightUniforms(eyePass_, in.light);
    gl::BindScope scope;
    bindShadowMap(scope, eyePass_, in.shadow);
    in.positions.bind(scope, eyePass_, gl::bind::EyeDepth);
    in.shadow.receivers->bind(scope, eyePass_, gl::bind::EyeReceivers);
    scope.texture(gl::bind::SurfacesLift, in.lift.id())
        .texture(gl::bind::LookupNormals, in.normals.id());
    gl::drawFullscreenTriangle(eyePass_, emptyVao_);
    scope.release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void EyeSoftShadowPass::drawBoundaries(const Inputs& in, BoundaryThreshold th) {
    glBindFramebuffer(GL_FRAMEBUFFER, seedsFbo_.id());
    glViewport(0, 0, in.width, in.height);
    glDisable(GL_DEPTH_TEST);
    // A banded flood lists its seeds here rather than sweeping the frame for them again.
    const bool listSeeds = jfa::banded(in.region);
    // Edge points: a seed's occluder is walked to the silhouette (boundaryOccluderPoint).
    const bool walk = in.settings.occluderPoints == OccluderPoints::Edge;
    setBoundaryUniforms(boundary_, in.camera.eye, th, listSeeds, walk ? &in.light : nullptr,
                        in.settings.silhouetteThreshold);
    gl::BindScope scope;
    if (listSeeds) kernel_.beginSeedList(scope, in.width, in.height);
    eye_.bind(scope, boundary_);
    gl::drawFullscreenTriangle(boundary_, emptyVao_);
    if (listSeeds) kernel_.seedsListed(seeds_);
    scope.release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void EyeSoftShadowPass::drawComposite(const Inputs& in, const gl::Texture& flooded) {
    glBindFramebuffer(GL_FRAMEBUFFER, visibilityFbo_.id());
    glViewport(0, 0, in.width, in.height);
    const bool edges = in.settings.occluderPoints == OccluderPoints::Edge && in.light.radius > 0.0f;
    // The first pass marks the pixels the edges recompute; the second runs only there.
    const auto draw = [&](const gl::Program& program) {
        setDiskLightUniforms(program, in.light);
        program.set(kCompositeOccluderEdges, edges ? 1 : 0);
        gl::BindScope scope;
        eye_.bind(scope, program);
        bindShadowMap(scope, program, in.shadow);
        scope.texture(gl::bind::EyeNormals, in.normals.id());
        scope.texture(gl::bind::EyeFlooded, flooded.id());
        gl::drawFullscreenTriangle(program, emptyVao_);
        scope.release();
    };
    gl::drawMarkedThenRefined(draw, composite_, edges ? &compositeEdges_ : nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

int EyeSoftShadowPass::measurePasses(const Inputs& in, BoundaryThreshold threshold, int maxPasses) {
    if (!estimator_) estimator_ = std::make_unique<EyeFloodEstimator>(shaders_);
    CoarseFloodSettings s;
    s.eye = in.camera.eye;
    s.threshold = threshold;
    s.light = in.light;
    s.objectIdFix = in.settings.objectIdFix;
    s.midpointFix = in.settings.midpointFix;
    const std::vector<std::uint32_t> bins = estimator_->travel(eye_, s);
    return bins.empty() ? -1 : passesForTravel(maxTravel(bins), s.factor, maxPasses);
}

EyeSoftShadowPass::Outputs EyeSoftShadowPass::execute(const Inputs& in, gl::PassTimer* timer) {
    if (in.shadow.receivers == nullptr)
        throw std::invalid_argument("JFA-E needs the shadow map's receiver positions");
    // The pass count is the thesis' for a 512² frame; a smaller frame (a window being resized)
    // cannot use steps beyond its size, so the count is capped there rather than refused.
    // Validates before any GL work.
    const int maxPasses = eyeSoftMaxPasses(in.width, in.height);
    int passes = std::min(in.passes, maxPasses);
    if (passes != 0) (void)eyeSoftPlan(passes, in.standardFlooding, in.width, in.height);
    prepare(in);

    // Phases 2-5 are the thesis' (§5.4), all within frame step 3.
    // Phase 2a (object-ID fix only): which object the light's centre sees at each texel.
    if (in.settings.objectIdFix) {
        gl::TimedPass timedOccluderIds(timer, phase::kOccluderIds);
        drawOccluderIds(in);
        timedOccluderIds.wrote(gl::textureBytes(ids_));
        timedOccluderIds.end();
    }

    // Phase 2: hard shadows per pixel of the frame's surfaces, with occluders.
    gl::TimedPass timedEyeHardShadows(timer, phase::kEyeHardShadows);
    drawEyeHardShadows(in);
    timedEyeHardShadows.wrote(gl::textureBytes(cells_));
    timedEyeHardShadows.end();

    // Phase 3: boundary pixels become seeds with their occluders.
    gl::TimedPass timedBoundaries(timer, phase::kBoundaries);
    const BoundaryThreshold th = boundaryThreshold(in.settings, in.camera.proj, in.height);
    drawBoundaries(in, th);
    eye_.seedOccluders = &seedOccluders_; // the flood's and the composite's from here on
    timedBoundaries.wrote(gl::textureBytes(seeds_) + gl::textureBytes(seedOccluders_));
    timedBoundaries.end();

    // Phase 4: flood the occluders through the penumbrae, in eye space. With auto, first how
    // far they travel in a coarse flood of this frame (EyeFloodReach.h), timed apart.
    const bool autoPasses = passes == 0;
    int measured = -1, geometric = -1;
    if (autoPasses && in.settings.autoPasses == EyeAutoPasses::Measured) {
        gl::TimedPass timedPassCount(timer, phase::kPassCount);
        measured = measurePasses(in, th, maxPasses);
        if (estimator_) timedPassCount.wrote(estimator_->bytes());
        timedPassCount.end();
    }
    // Then its band (jfa/Band.h).
    gl::TimedPass timedBand(timer, phase::kBand);
    EyeSoftCriterion criterion;
    criterion.light = in.light;
    criterion.objectIdFix = in.settings.objectIdFix;
    criterion.midpointFix = in.settings.midpointFix;
    criterion.cells = &eye_;
    criterion.reachBound = in.reach;
    if (criterion.reachBound.enabled) { // receivers are the surface pixels (w >= 0)
        bounds_.build(eye_, in.light, criterion.reachBound);
        timedBand.wrote(bounds_.bytes());
    }
    kernel_.setRegion(in.region, in.bandTile);
    if (autoPasses) {
        // The geometric bound is band step A (one value read back; a banded run reuses the
        // step). It caps the measured count too: no cell is accepted beyond it.
        geometric = jfa::passesForReach(kernel_.maxSeedReach(seeds_, criterion), maxPasses);
        passes = measured < 0 ? geometric : std::min(measured, geometric);
    }
    const jfa::Plan plan = eyeSoftPlan(passes, in.standardFlooding, in.width, in.height);
    kernel_.prepareBand(plan, seeds_, criterion);
    timedBand.end();
    gl::TimedPass timedFlood(timer, phase::kFlood);
    const gl::Texture& flooded = kernel_.run(plan, seeds_, criterion);
    timedFlood.end();

    // Phase 5: visibility per pixel.
    gl::TimedPass timedComposite(timer, phase::kComposite);
    drawComposite(in, flooded);
    timedComposite.wrote(gl::textureBytes(visibility_) + gl::textureBytes(mask_));
    timedComposite.end();
    return {eye_, seeds_, flooded, visibility_, kernel_.passesRun(), passes, geometric, measured};
}

std::pair<const gl::Texture&, const gl::Texture&> EyeSoftShadowPass::decodedEyeImage() const {
    if (eye_.cells == nullptr) throw std::logic_error("JFA-E: no frame to decode");
    const int w = eye_.width(), h = eye_.height();
    if (!decodedPoints_ || decodedPoints_.width() != w || decodedPoints_.height() != h) {
        decodedPoints_ = gl::Texture(GL_RGBA32F, w, h);
        decodedOccluders_ = gl::Texture(GL_RGBA32F, w, h);
        decodedFbo_ = gl::Framebuffer::withTargets({&decodedPoints_, &decodedOccluders_}, nullptr,
                                                   "JFA-E decoded eye image");
        decodedStale_ = true;
    }
    if (decodedStale_) {
        glBindFramebuffer(GL_FRAMEBUFFER, decodedFbo_.id());
        glViewport(0, 0, w, h);
        glDisable(GL_DEPTH_TEST);
        gl::BindScope scope;
        eye_.bind(scope, unpack_);
        gl::drawFullscreenTriangle(unpack_, emptyVao_);
        scope.release();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        decodedStale_ = false;
    }
    return {decodedPoints_, decodedOccluders_};
}

} // namespace fl
