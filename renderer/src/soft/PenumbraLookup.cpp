#include <renderer/soft/PenumbraLookup.h>

#include <renderer/io/TextureImage.h>
#include <renderer/passes/ShadowMapDecode.h>
#include <renderer/passes/SurfaceDecode.h>
#include <renderer/passes/TerminatorLift.h>
#include <renderer/soft/OccluderEdge.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace fl {

namespace {

glm::vec3 pixel3(const FloatImage& im, int x, int y) {
    return {im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2)};
}

// What one pixel's lookup reads of the map: the map, its receivers decoded (occluderEdgePoint's
// grid), the penumbra map's tags and the silhouette threshold.
struct LookupMap {
    const LineMap& m;
    ReceiverGrid receivers;
    const std::vector<float>& tags;
    float threshold;
    [[nodiscard]] float tag(glm::ivec2 t) const {
        return tags[std::size_t(t.y) * std::size_t(m.size) + std::size_t(t.x)];
    }
};

// shadow_lookup.glsl's shadowToLight: from `world` towards the map's light.
glm::vec3 toLight(const LineMap& m, glm::vec3 world) {
    const glm::vec4 l = shadowLight(m.lightViewProj);
    return std::abs(l.w) > 1e-30f ? glm::normalize(glm::vec3(l) / l.w - world)
                                  : -glm::normalize(glm::vec3(l));
}

// soft_penumbra.glsl's penumbraTexel: the point's map texel t, whether the hard test at `tested`
// shadows it, and its tag; false off the map.
bool penumbraTexel(const LookupMap& L, glm::vec3 world, glm::vec3 tested, glm::ivec2& t,
                   bool& inside, float& tag) {
    const std::optional<glm::vec3> uvz = shadowmap::mapCoord(L.m.lightViewProj, L.m.warp, world);
    if (!uvz || glm::any(glm::lessThan(*uvz, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThan(*uvz, glm::vec3(1.0f))))
        return false;
    inside = lineMapHardShadow(L.m, tested) < 0.5f;
    t = glm::clamp(glm::ivec2(glm::vec2(*uvz) * float(L.m.size)), glm::ivec2(0),
                   glm::ivec2(L.m.size - 1));
    tag = L.tag(t);
    return true;
}

// soft_penumbra.glsl's neighbourTag.
float neighbourTag(const LookupMap& L, glm::ivec2 t) {
    const glm::ivec2 axis[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    float tag = 0.0f;
    for (int k = 0; k < 4 && tag == 0.0f; ++k)
        tag = L.tag(glm::clamp(t + axis[k], glm::ivec2(0), glm::ivec2(L.m.size - 1)));
    return tag;
}

// The texel a tag names (mapSeedTexel).
glm::ivec2 seedTexel(float tag, int width) {
    const std::uint32_t i = shadowmap::seedIndex(tag);
    return {int(i % std::uint32_t(width)), int(i / std::uint32_t(width))};
}

// The shared ending of both passes: a hard-shadowed point whose surface faces away from the
// light's centre or from its occluder stays 0; else the occluder point's share, -1 for a miss.
std::optional<float> selfShadowed(const DiskLight& l, glm::vec3 world, glm::vec3 plane, glm::vec3 o,
                                  bool inside) {
    if (inside && (glm::dot(plane, l.center - world) <= 0.0f || glm::dot(plane, o - world) <= 0.0f))
        return 0.0f;
    return std::nullopt;
}

// The first pass (without PENUMBRA_EDGES): the occluder's point at the silhouette's edge.
float pointPass(const LookupMap& L, glm::vec3 world, glm::vec3 plane, bool inside, float tag) {
    const float lit = inside ? 0.0f : 1.0f;
    if (tag == 0.0f) return lit;
    const glm::ivec2 ot = seedTexel(tag, L.m.size);
    const glm::vec3 o = occluderEdgePoint(L.receivers, L.m.light, ot.x, ot.y, L.threshold);
    if (const std::optional<float> zero = selfShadowed(L.m.light, world, plane, o, inside))
        return *zero;
    const std::optional<float> k = occluderIntensity(L.m.light, world, o, inside);
    return k ? *k : lit;
}

// The second pass (PENUMBRA_EDGES): the occluder's edges, a neighbour's occluder borrowed.
float edgesPass(const LookupMap& L, glm::vec3 world, glm::vec3 plane, glm::ivec2 t, bool inside,
                float tag) {
    bool borrowed = false;
    if (tag == 0.0f) {
        tag = neighbourTag(L, t);
        borrowed = tag != 0.0f;
    }
    const float lit = inside ? 0.0f : 1.0f;
    if (tag == 0.0f) return lit;
    const glm::ivec2 ot = seedTexel(tag, L.m.size);
    const OccluderLines lines = occluderLines(L.m, ot, world, plane);
    const glm::vec3 o = lines.count > 0
                            ? lines.point[0]
                            : occluderEdgePoint(L.receivers, L.m.light, ot.x, ot.y, L.threshold);
    if (const std::optional<float> zero = selfShadowed(L.m.light, world, plane, o, inside))
        return *zero;
    float intensity = -1.0f;
    if (!borrowed)
        if (const std::optional<float> k = occluderIntensity(L.m.light, world, o, inside))
            intensity = *k;
    if (intensity >= 0.0f || borrowed) {
        const float l = occluderShareFused(L.m, t, world, plane, lines, o, inside, borrowed);
        intensity = l < 0.0f ? intensity : l;
    }
    return intensity < 0.0f ? lit : intensity;
}

// One pixel (light_visibility.frag.glsl's main with SOFT_PENUMBRA_BOTH): both passes, the second
// where the first marked.
float lookupPixel(const LookupMap& L, glm::vec3 position, float lift, glm::vec3 shading,
                  glm::vec3 plane) {
    const glm::vec3 world = surface::lookupPoint(position, lift, shading);
    const glm::vec3 lookupPlane = lift > 0.0f ? shading : plane; // surfaceLookupPlane
    const glm::vec3 tested = surface::normalOffset(world, lookupPlane, toLight(L.m, world),
                                                   L.m.warp * L.m.lightViewProj, float(L.m.size));
    glm::ivec2 t(0);
    bool inside = false;
    float tag = 0.0f;
    if (!penumbraTexel(L, world, tested, t, inside, tag)) return 1.0f;
    const bool edges = L.m.light.radius > 0.0f && (tag != 0.0f || neighbourTag(L, t) != 0.0f);
    return edges ? edgesPass(L, world, plane, t, inside, tag)
                 : pointPass(L, world, plane, inside, tag);
}

} // namespace

LookupSurfaces readLookupSurfaces(const SurfacesPass::Outputs& s) {
    return {s.positions().read(), readTexture(s.lift, 1),
            s.readNormals(SurfacesPass::Outputs::Normal::Shading),
            s.readNormals(SurfacesPass::Outputs::Normal::Plane)};
}

FloatImage penumbraLookupVisibility(const LookupSurfaces& s, const LineMap& m,
                                    const std::vector<float>& tags, float threshold) {
    const std::size_t texels = std::size_t(m.size) * std::size_t(m.size);
    if (tags.size() != texels || m.receiverDepth.size() != texels)
        throw std::invalid_argument("penumbraLookupVisibility: the penumbra map and the receiver "
                                    "target must be the shadow map's size");
    LookupMap L{m, {m.size, m.size, {}}, tags, threshold};
    L.receivers.points.reserve(texels);
    for (int y = 0; y < m.size; ++y)
        for (int x = 0; x < m.size; ++x)
            L.receivers.points.push_back(shadowmap::receiverPosition(
                m.receiverDepth[std::size_t(y) * std::size_t(m.size) + std::size_t(x)], {x, y},
                m.size, m.unwarp, m.inverseLightViewProj));
    const FloatImage& p = s.points;
    FloatImage out{p.width, p.height, 1, std::vector<float>(std::size_t(p.width) * p.height, 1.0f)};
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            if (p.at(x, y, 3) == 0.0f) continue; // background: lit
            out.data[std::size_t(y) * std::size_t(p.width) + std::size_t(x)] =
                lookupPixel(L, pixel3(p, x, y), s.lift.at(x, y, 0), pixel3(s.shading, x, y),
                            pixel3(s.planes, x, y));
        }
    return out;
}

} // namespace fl
