#include <raytrace/ShadowRays.h>

#include <base/Parallel.h>
#include <base/Text.h>
#include <geometry/DiskSampling.h>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fl::rt {

namespace {

// Embree reports errors through a callback; the first one is kept and thrown after the call.
void onError(void* user, RTCError code, const char* text) {
    auto* message = static_cast<std::string*>(user);
    if (message->empty()) message->assign(cat("Embree error ", static_cast<int>(code), ": ", text));
}

void checkNormals(std::span<const glm::vec3> normals, std::size_t vertices) {
    if (!normals.empty() && normals.size() != vertices)
        throw std::invalid_argument(
            cat("raytrace: ", normals.size(), " normals for ", vertices, " vertices"));
}

void checkVertices(std::span<const glm::vec3> vertices) {
    for (std::size_t i = 0; i < vertices.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            const float c = vertices[i][a];
            if (!std::isfinite(c))
                throw std::invalid_argument(cat("raytrace: vertex ", i, " is not finite"));
            if (std::abs(c) > kMaxCoordinate)
                throw std::invalid_argument(cat("raytrace: vertex ", i, " lies beyond +-",
                                                kMaxCoordinate, " (Embree works in float)"));
        }
}

// A deterministic hash of (receiver, sample) -> 32 bits (PCG's output permutation over a
// mixed seed): the jitter is the same for any thread count and any run.
std::uint32_t hash(std::uint64_t receiver, std::uint32_t sample) {
    std::uint64_t x = receiver * 0x9E3779B97F4A7C15ull + sample * 0xBF58476D1CE4E5B9ull + 1;
    x ^= x >> 31;
    x *= 0x94D049BB133111EBull;
    x ^= x >> 29;
    const auto state = static_cast<std::uint32_t>(x);
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word ^ static_cast<std::uint32_t>(x >> 32);
}

// [0, 1) from 24 bits (exact in float and double).
double unit(std::uint32_t bits) {
    return static_cast<double>(bits >> 8) * (1.0 / 16777216.0);
}

/// What the occlusion filter reads (Embree's geometry user data): Triangles' cut-out flags and
/// test (empty: none).
struct AlphaTest {
    std::vector<std::uint8_t> cutOut;
    std::function<bool(std::uint32_t, float, float)> transmits;
};

constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();
// The least barycentric weight of a ray's start on its triangle (RayScene::surface).
constexpr float kInside = 1e-4f;

/// An occlusion ray's context: Embree's, then the triangle the ray skips (its receiver's).
/// Embree hands the filter the pointer it was given, so the filter reads `skip` through it.
struct SkipContext {
    RTCIntersectContext embree;
    std::uint32_t skip = kNoTriangle;
};

/// Embree's filter (every occlusion ray; intersection rays where there are cut-outs): a hit on
/// the ray's own triangle is no hit (Cycles' intersection_skip_self_shadow), nor one on a cut-out
/// triangle where the surface transmits; traversal goes on behind either. Every ray is cast with
/// a SkipContext.
void occlusionFilter(const RTCFilterFunctionNArguments* args) {
    const auto* alpha = static_cast<const AlphaTest*>(args->geometryUserPtr);
    const std::uint32_t skip = reinterpret_cast<const SkipContext*>(args->context)->skip;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        if (prim == skip)
            args->valid[i] = 0;
        else if (!alpha->cutOut.empty() && alpha->cutOut[prim] != 0 &&
                 alpha->transmits(prim, RTCHitN_u(args->hit, args->N, i),
                                  RTCHitN_v(args->hit, args->N, i)))
            args->valid[i] = 0;
    }
}

} // namespace

struct RayScene::Embree {
    std::string error;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    RTCGeometry geometry = nullptr;
    glm::vec3* vertices = nullptr;          // Embree's vertex buffer (padded by one float)
    const std::uint32_t* indices = nullptr; // Embree's index buffer
    std::size_t vertexCount = 0;
    std::vector<glm::vec3> normals; // empty or one per vertex (the terminator offset's)
    AlphaTest alpha;                // the filter's user data: lives as long as the geometry

    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        if (geometry) rtcReleaseGeometry(geometry);
        if (device) rtcReleaseDevice(device);
    }
    void check() {
        if (!error.empty()) throw std::runtime_error("raytrace: " + error);
    }
};

RayScene::RayScene(const Triangles& t) : e_(std::make_unique<Embree>()) {
    const auto start = std::chrono::steady_clock::now();
    if (t.indices.size() % 3 != 0)
        throw std::invalid_argument(
            cat("raytrace: ", t.indices.size(), " indices is not a whole number of triangles"));
    checkVertices(t.vertices);
    checkNormals(t.normals, t.vertices.size());
    for (std::size_t i = 0; i < t.indices.size(); ++i)
        if (t.indices[i] >= t.vertices.size())
            throw std::invalid_argument(cat("raytrace: triangle ", i / 3, " uses vertex ",
                                            t.indices[i], " of ", t.vertices.size()));
    const std::size_t triangles = t.indices.size() / 3;
    if (!t.cutOut.empty() && (t.cutOut.size() != triangles || !t.transmits))
        throw std::invalid_argument(cat("raytrace: ", t.cutOut.size(), " cut-out flags for ",
                                        triangles, " triangles",
                                        t.transmits ? "" : ", and no transmits() test"));
    e_->device = rtcNewDevice(nullptr);
    if (!e_->device)
        throw std::runtime_error(
            cat("raytrace: Embree device: error ", static_cast<int>(rtcGetDeviceError(nullptr))));
    rtcSetDeviceErrorFunction(e_->device, onError, &e_->error);
    e_->scene = rtcNewScene(e_->device);
    // Robust traversal: rays that graze a shared edge or vertex do not slip between triangles.
    rtcSetSceneFlags(e_->scene, RTC_SCENE_FLAG_ROBUST);
    // High quality: the tree is built once per static scene and traced by millions of rays.
    // (A two-level scene with a refittable geometry tree was measured no faster to refit than
    // this is to rebuild on Embree 3.13, and traced 8% slower: docs/BENCHMARKS.md.)
    rtcSetSceneBuildQuality(e_->scene, RTC_BUILD_QUALITY_HIGH);
    e_->geometry = rtcNewGeometry(e_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    e_->check();
    // Embree reads vertices 16 bytes at a time: its buffers are padded.
    e_->vertexCount = t.vertices.size();
    e_->vertices = static_cast<glm::vec3*>(
        rtcSetNewGeometryBuffer(e_->geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                sizeof(glm::vec3), std::max<std::size_t>(t.vertices.size(), 1)));
    auto* indices = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(e_->geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), triangles));
    e_->check();
    std::copy(t.vertices.begin(), t.vertices.end(), e_->vertices);
    std::copy(t.indices.begin(), t.indices.end(), indices);
    e_->indices = indices;
    e_->normals = t.normals;
    rtcSetGeometryUserData(e_->geometry, &e_->alpha);
    rtcSetGeometryOccludedFilterFunction(e_->geometry, occlusionFilter);
    if (std::any_of(t.cutOut.begin(), t.cutOut.end(), [](std::uint8_t f) { return f != 0; })) {
        e_->alpha = {t.cutOut, t.transmits};
        // The receiver's lookup (surface) sees through cut-outs as the rasteriser did.
        rtcSetGeometryIntersectFilterFunction(e_->geometry, occlusionFilter);
    }
    rtcCommitGeometry(e_->geometry);
    rtcAttachGeometry(e_->scene, e_->geometry);
    rtcCommitScene(e_->scene);
    e_->check();
    triangleCount_ = triangles;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& v : t.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    diagonal_ = t.vertices.empty() ? 1.0f : std::max(glm::length(hi - lo), 1e-25f);
    buildMs_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

RayScene::~RayScene() = default;
RayScene::RayScene(RayScene&&) noexcept = default;
RayScene& RayScene::operator=(RayScene&&) noexcept = default;

void RayScene::refit(std::span<const glm::vec3> vertices, std::span<const glm::vec3> normals) {
    const auto start = std::chrono::steady_clock::now();
    if (vertices.size() != e_->vertexCount)
        throw std::invalid_argument(cat("raytrace: refit with ", vertices.size(),
                                        " vertices, the scene has ", e_->vertexCount));
    checkVertices(vertices);
    checkNormals(normals, vertices.size());
    std::copy(vertices.begin(), vertices.end(), e_->vertices);
    e_->normals.assign(normals.begin(), normals.end());
    rtcUpdateGeometryBuffer(e_->geometry, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(e_->geometry);
    rtcCommitScene(e_->scene);
    e_->check();
    buildMs_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool RayScene::occluded(glm::vec3 from, glm::vec3 to, std::optional<std::uint32_t> skip,
                        float shortOf) const {
    const glm::vec3 d = to - from;
    const float length = glm::length(d);
    if (!(length > shortOf)) return false;
    SkipContext context;
    rtcInitIntersectContext(&context.embree);
    context.skip = skip.value_or(kNoTriangle);
    RTCRay ray{};
    ray.org_x = from.x;
    ray.org_y = from.y;
    ray.org_z = from.z;
    ray.dir_x = d.x / length;
    ray.dir_y = d.y / length;
    ray.dir_z = d.z / length;
    ray.tnear = 0.0f;
    ray.tfar = length - shortOf; // the direction is to `to`, whatever `shortOf`
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(e_->scene, &context.embree, &ray);
    return ray.tfar < 0.0f; // Embree sets tfar to -inf on a hit
}

std::optional<SurfacePoint> RayScene::surface(glm::vec3 point, glm::vec3 side,
                                              std::optional<glm::vec3> eye) const {
    // The window around the point: its position comes from the depth buffer, a little off the
    // triangle; the first triangle inside is the one the eye sees there.
    const float window = 16.0f * kRayEpsilon * diagonal_;
    glm::vec3 from = point + window * side, d = -side;
    float distance = window, margin = window;
    if (eye && glm::length(point - *eye) > 0.0f) {
        from = *eye;
        d = point - *eye;
        distance = glm::length(d);
        margin = std::max(1e-3f * distance, window);
    }
    if (!(distance > 0.0f) || !(glm::length(d) > 0.0f)) return std::nullopt;
    SkipContext context; // skips nothing: the filter only reads its cut-outs here
    rtcInitIntersectContext(&context.embree);
    RTCRayHit hit{};
    hit.ray.org_x = from.x;
    hit.ray.org_y = from.y;
    hit.ray.org_z = from.z;
    hit.ray.dir_x = d.x / glm::length(d);
    hit.ray.dir_y = d.y / glm::length(d);
    hit.ray.dir_z = d.z / glm::length(d);
    hit.ray.tnear = std::max(distance - margin, 0.0f);
    hit.ray.tfar = distance + margin;
    hit.ray.mask = 0xFFFFFFFFu;
    hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(e_->scene, &context.embree, &hit);
    if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    SurfacePoint out;
    out.triangle = hit.hit.primID;
    const std::uint32_t* t = e_->indices + 3 * static_cast<std::size_t>(out.triangle);
    const std::array<glm::vec3, 3> corner{e_->vertices[t[0]], e_->vertices[t[1]],
                                          e_->vertices[t[2]]};
    const glm::vec3 cross = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
    if (!(glm::length(cross) > 0.0f)) return std::nullopt;
    out.normal = glm::normalize(cross);
    if (glm::dot(out.normal, side) < 0.0f) out.normal = -out.normal;
    // On an edge or a corner the neighbour sharing it passes through the ray's start, and
    // rounding decides whether a ray meets it there (Cycles, which skips only the ray's own
    // primitive, has the same case): the start moves into its own triangle, 1e-4 of the way
    // from each edge at least. Along the triangle, so it changes no ray's height over it.
    glm::vec3 w(1.0f - hit.hit.u - hit.hit.v, hit.hit.u, hit.hit.v);
    w = glm::max(w, glm::vec3(kInside));
    w /= w.x + w.y + w.z;
    const float u = w.y, v = w.z;
    out.position = w.x * corner[0] + u * corner[1] + v * corner[2];
    if (!e_->normals.empty()) {
        const std::array<glm::vec3, 3> normal{e_->normals[t[0]], e_->normals[t[1]],
                                              e_->normals[t[2]]};
        out.smooth = terminatorOffset(out.position, corner, normal, u, v, side);
    }
    return out;
}

namespace {

void checkSamples(const VisibilitySettings& s) {
    if (s.samples < kMinSamples || s.samples > kMaxSamples)
        throw std::invalid_argument(cat("raytrace: samples must be in [", kMinSamples, ", ",
                                        kMaxSamples, "], got ", s.samples));
}

// diskSamples() into `out` (cleared first): the hot loop keeps one buffer per thread.
void fillDiskSamples(const Disk& disk, const VisibilitySettings& s, std::uint64_t receiver,
                     std::vector<glm::vec3>& out) {
    const glm::ivec2 grid = geom::stratifiedGrid(s.samples);
    const geom::DiskFrame frame = geom::diskFrame(disk.normal);
    out.clear();
    std::uint32_t k = 0;
    for (int j = 0; j < grid.y; ++j)
        for (int i = 0; i < grid.x; ++i, ++k) {
            double a = 0.5, b = 0.5;
            if (s.jitter) {
                a = unit(hash(receiver, 2 * k));
                b = unit(hash(receiver, 2 * k + 1));
            }
            const glm::dvec2 p =
                geom::concentricDisk(2.0 * (i + a) / grid.x - 1.0, 2.0 * (j + b) / grid.y - 1.0);
            out.push_back(disk.center + disk.radius * (static_cast<float>(p.x) * frame.tangent +
                                                       static_cast<float>(p.y) * frame.bitangent));
        }
}

} // namespace

std::vector<glm::vec3> diskSamples(const Disk& disk, const VisibilitySettings& s,
                                   std::uint64_t receiver) {
    checkSamples(s);
    std::vector<glm::vec3> out;
    fillDiskSamples(disk, s, receiver, out);
    return out;
}

namespace {

/// Where a receiver's rays leave from, and what decides which light it faces.
struct RayStart {
    glm::vec3 point{0.0f};             // on its triangle, or epsilon off the receiver
    glm::vec3 plane{0.0f};             // Ng: its triangle's normal, seen side (zero: unknown)
    glm::vec3 shading{0.0f};           // N: the smooth normal with the offset on, else Ng
    glm::vec3 move{0.0f};              // Hanika's move onto the smooth surface (zero: none)
    std::optional<std::uint32_t> self; // its triangle, which its rays skip
};

RayStart rayStart(const RayScene& scene, const Receiver& rc, const VisibilitySettings& s,
                  float eps) {
    RayStart out;
    const glm::vec3 side =
        glm::length(rc.normal) > 0.0f ? glm::normalize(rc.normal) : glm::vec3(0.0f);
    const std::optional<SurfacePoint> surface =
        side == glm::vec3(0.0f) ? std::nullopt : scene.surface(rc.position, side, s.eye);
    if (!surface) { // no triangle here: epsilon off the point, along its normal
        out.point = rc.position + eps * side;
        out.plane = out.shading = side;
        return out;
    }
    out.point = surface->position;
    out.plane = out.shading = surface->normal;
    out.self = surface->triangle;
    if (s.terminatorOffset && surface->smooth) {
        out.shading = surface->smooth->normal;
        out.move = surface->smooth->position - surface->position;
    }
    return out;
}

/// Rays from one receiver to `samples`: the share that reaches the disk.
float receiverVisibility(const RayScene& scene, const RayStart& st, glm::vec3 facing,
                         std::span<const glm::vec3> samples, const VisibilitySettings& s, float eps,
                         RayCounts& counts) {
    int visible = 0;
    for (const glm::vec3& q : samples) {
        const glm::vec3 toLight = q - st.point;
        const float length = glm::length(toLight);
        if (!(length > eps)) {
            ++visible; // on the light itself
            continue;
        }
        const glm::vec3 l = toLight / length;
        const float shadingL = glm::dot(st.shading, l), planeL = glm::dot(st.plane, l);
        if (shadingL <= 0.0f && st.shading != glm::vec3(0.0f)) continue; // faces away
        if (glm::dot(facing, -toLight) <= 0.0f) continue;                // behind the disk
        // Cycles decides per light sample, and each of our rays is one: the amount follows the
        // direction to its own point of the disk. From the disk's centre, a receiver whose disk
        // straddles its terminator would move all of its rays or none.
        const float amount =
            st.move != glm::vec3(0.0f) ? offsetAmount(shadingL, planeL, s.geometryOffset) : 0.0f;
        const glm::vec3 origin = st.point + amount * st.move;
        // An offset ray whose triangle faces away from its light point is meant to meet it.
        const std::optional<std::uint32_t> skip =
            amount > 0.0f && !(planeL > 0.0f) ? std::nullopt : st.self;
        const float reach = glm::length(q - origin);
        if (!(reach > eps)) {
            ++visible; // moved onto the light
            continue;
        }
        ++counts.cast;
        counts.offset += amount > 0.0f;
        if (!scene.occluded(origin, q, skip, eps)) ++visible;
    }
    return static_cast<float>(visible) / static_cast<float>(s.samples);
}

} // namespace

std::vector<float> diskVisibility(const RayScene& scene, const Disk& disk,
                                  std::span<const Receiver> receivers, const VisibilitySettings& s,
                                  RayCounts* counts) {
    checkSamples(s);
    if (!(disk.radius >= 0.0f) || !(glm::length(disk.normal) > 0.0f))
        throw std::invalid_argument("raytrace: the disk needs a radius >= 0 and a normal");
    if (!(s.epsilon > 0.0f && s.epsilon < 1e-2f))
        throw std::invalid_argument(cat("raytrace: epsilon must be in (0, 0.01), got ", s.epsilon));
    const glm::vec3 facing = glm::normalize(disk.normal);
    const float eps = s.epsilon * scene.diagonal();
    std::vector<float> out(receivers.size(), 1.0f);
    std::atomic<std::uint64_t> cast{0}, offset{0}, unplaced{0};
    // Receivers in blocks of 256, taken in turn by whichever thread is free (the cores stay
    // busy whatever the image holds; each receiver's answer depends on its index only). The
    // caller's thread reports progress as it takes blocks.
    constexpr std::size_t kBlock = 256;
    const std::size_t blocks = (receivers.size() + kBlock - 1) / kBlock;
    std::atomic<std::size_t> next{0}, done{0};
    const int threads =
        std::max(1, std::min<int>(resolveThreads(s.threads),
                                  static_cast<int>(std::max<std::size_t>(blocks, 1))));
    std::size_t reported = 0;
    parallelRows(threads, threads, [&](int, int, int band) {
        RayCounts mine;
        std::vector<glm::vec3> samples; // this thread's, refilled per receiver
        samples.reserve(static_cast<std::size_t>(s.samples));
        for (std::size_t b = next++; b < blocks; b = next++) {
            const std::size_t last = std::min(receivers.size(), (b + 1) * kBlock);
            for (std::size_t r = b * kBlock; r < last; ++r) {
                if (!receivers[r].valid) continue;
                const RayStart start = rayStart(scene, receivers[r], s, eps);
                mine.unplaced += !start.self;
                fillDiskSamples(disk, s, r, samples);
                out[r] = receiverVisibility(scene, start, facing, samples, s, eps, mine);
            }
            const std::size_t finished = ++done;
            if (band == 0 && s.progress && finished * 100 >= (reported + 1) * blocks) {
                reported = finished * 100 / blocks;
                s.progress(static_cast<double>(finished) / static_cast<double>(blocks));
            }
        }
        cast += mine.cast;
        offset += mine.offset;
        unplaced += mine.unplaced;
    });
    if (s.progress) s.progress(1.0);
    if (counts) *counts = {cast, offset, unplaced};
    return out;
}

} // namespace fl::rt
