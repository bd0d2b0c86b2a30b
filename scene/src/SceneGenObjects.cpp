// The objects of the generated scene, after the thesis' fantasy scene (section 5.5): a tree, a
// pergola, mushrooms, a rock, a flower and simple characters. Every random choice is drawn
// before tessellation in a fixed order, so an object looks the same at every detail level.

#include "SceneGenObjects.h"
#include "SceneGenRig.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace fl::gen {

namespace {

glm::mat4 translate(const glm::vec3& t) {
    glm::mat4 m(1.0f);
    m[3] = glm::vec4(t, 1.0f);
    return m;
}

glm::mat4 scaleMat(const glm::vec3& s) {
    return glm::mat4(glm::vec4(s.x, 0, 0, 0), glm::vec4(0, s.y, 0, 0), glm::vec4(0, 0, s.z, 0),
                     glm::vec4(0, 0, 0, 1));
}

/// Ellipsoid frame: local x along `xAxis` (unit), local y as close to `upHint` as possible.
glm::mat4 orientedEllipsoid(const glm::vec3& centre, const glm::vec3& xAxis,
                            const glm::vec3& upHint, const glm::vec3& radii) {
    const glm::vec3 zRaw = glm::cross(xAxis, upHint);
    const glm::vec3 z = zRaw / std::sqrt(glm::dot(zRaw, zRaw));
    const glm::vec3 y = glm::cross(z, xAxis);
    return glm::mat4(glm::vec4(xAxis * radii.x, 0.0f), glm::vec4(y * radii.y, 0.0f),
                     glm::vec4(z * radii.z, 0.0f), glm::vec4(centre, 1.0f));
}

glm::vec3 normalized(const glm::vec3& v) {
    return v / std::sqrt(glm::dot(v, v));
}

/// Closed, tapering column along +Y from y0 to y1 with a flat, creased bottom and a pole at
/// the top `tipHeight` above y1; `radius(t)` for t in [0, 1] gives its shape.
template <typename Radius>
std::vector<ProfilePoint> columnProfile(float y0, float y1, int rings, float tipHeight,
                                        Radius radius) {
    std::vector<ProfilePoint> profile;
    profile.push_back({0.0f, y0});
    profile.push_back({radius(0.0f), y0});
    for (int i = 0; i < rings; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(rings - 1);
        profile.push_back({radius(t), y0 + t * (y1 - y0), i == 0});
    }
    profile.push_back({0.0f, y1 + tipHeight});
    return profile;
}

// ---- tree -------------------------------------------------------------------------------------

struct Branch {
    float height, azimuth, elevation, length;
    glm::vec3 tip;
};

struct LeafCluster {
    glm::vec3 centre;
    float radius;
    Bumps bumps;
};

/// Everything random about a tree. The first clusters are the crown top and the branch tips,
/// so the coarsest trees still have leaves where their branches end.
struct TreeDesign {
    float trunkH, r0, r1;
    std::array<Branch, 5> branches;
    std::vector<LeafCluster> clusters; // 24
};

TreeDesign designTree(const ObjectDesign& d) {
    Rng rng(d.seed);
    const float s = d.scale;
    TreeDesign t{3.0f * s, 0.2f * s, 0.09f * s, {}, {}};
    for (std::size_t i = 0; i < t.branches.size(); ++i) {
        Branch& br = t.branches[i];
        br.height = t.trunkH * rng.uniform(0.55f, 0.9f);
        br.azimuth = 2.0f * kPi * (static_cast<float>(i) + rng.uniform(0.0f, 0.6f)) / 5.0f;
        br.elevation = rng.uniform(0.5f, 0.95f);
        br.length = s * rng.uniform(1.0f, 1.6f);
        const glm::vec3 dir(std::cos(br.elevation) * std::cos(br.azimuth), std::sin(br.elevation),
                            -std::cos(br.elevation) * std::sin(br.azimuth));
        br.tip = glm::vec3(0.0f, br.height, 0.0f) + br.length * dir;
    }
    t.clusters.push_back({{0.0f, t.trunkH + 0.6f * s, 0.0f}, 1.3f * s, Bumps::random(rng, 0.15f)});
    for (const Branch& br : t.branches)
        t.clusters.push_back({br.tip + glm::vec3(0, 0.2f * s, 0), s * rng.uniform(0.8f, 1.0f),
                              Bumps::random(rng, 0.15f)});
    while (t.clusters.size() < 24) { // the rest fill an ellipsoid around the crown
        const glm::vec3 offset(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f),
                               rng.uniform(-1.0f, 1.0f));
        if (glm::dot(offset, offset) > 1.0f) continue;
        t.clusters.push_back(
            {glm::vec3(0.0f, t.trunkH + 0.3f * s, 0.0f) + offset * glm::vec3(1.7f, 0.9f, 1.7f) * s,
             s * rng.uniform(0.55f, 0.85f), Bumps::random(rng, 0.15f)});
    }
    return t;
}

/// Trunk with a flared foot, and tapering branches.
void addBark(const TreeDesign& t, float s, int detail, MeshBuilder& b) {
    const auto trunk = columnProfile(-kSink, t.trunkH, 2 + detail / 2, t.r1, [&](float u) {
        const float foot = (1.0f - u) * (1.0f - u) * (1.0f - u);
        return t.r1 + (t.r0 - t.r1) * (1.0f - u) + 0.12f * s * foot * foot;
    });
    addLathe(b, glm::mat4(1.0f), trunk, 4 + detail);

    const int branchCount = std::min(5, 2 + detail / 2);
    for (int i = 0; i < branchCount; ++i) {
        const Branch& br = t.branches[static_cast<std::size_t>(i)];
        const glm::vec3 base(0.0f, br.height, 0.0f);
        const float rb = 0.07f * s;
        const float rt = 0.025f * s;
        const auto profile = columnProfile(0.0f, br.length, 2 + detail / 4, rt,
                                           [&](float u) { return rb + (rt - rb) * u; });
        addLathe(b, frameAlong(base, normalized(br.tip - base)), profile, 3 + detail / 3);
    }
}

void buildTree(const ObjectDesign& d, int detail, MeshBuilder& bark, MeshBuilder& leaves) {
    const TreeDesign t = designTree(d);
    addBark(t, d.scale, detail, bark);
    // Overlapping bumpy leaf clusters: the many casters the thesis' tree provides.
    const int clusterCount = std::min(24, 3 + detail);
    for (int i = 0; i < clusterCount; ++i) {
        const LeafCluster& c = t.clusters[static_cast<std::size_t>(i)];
        const glm::mat4 xf =
            translate(c.centre) * scaleMat(glm::vec3(c.radius, 0.8f * c.radius, c.radius));
        addBlob(leaves, xf, 5 + detail / 2, 3 + detail / 4, c.bumps);
    }
}

// ---- pergola ----------------------------------------------------------------------------------

/// Pergola proportions, metres before scaling.
struct PergolaSize {
    float postTop, halfX, halfZ, postR;
    explicit PergolaSize(float s)
        : postTop(2.3f * s), halfX(1.5f * s), halfZ(1.0f * s), postR(0.08f * s) {}
};

/// A post from `bottom` (below the ground) to the beams: a square box at detail 0, else a round
/// column with a wider foot and capital.
void addPost(MeshBuilder& b, const glm::vec3& at, float bottom, const PergolaSize& p, float s,
             int detail) {
    if (detail == 0) {
        const float h = 0.5f * (p.postTop - bottom);
        addBox(b, translate(at + glm::vec3(0, bottom + h, 0)), glm::vec3(p.postR, h, p.postR));
        return;
    }
    const float footR = 1.35f * p.postR;
    const float capitalR = 1.4f * p.postR;
    const float shaftTop = p.postTop - 0.2f * s;
    const float capitalBottom = p.postTop - 0.08f * s;
    // Creases duplicate a point with `hard` set; each pair below is one smooth patch.
    // clang-format off
    const std::vector<ProfilePoint> profile = {
        {0.0f, bottom},                   {footR, bottom},            // bottom disk
        {footR, bottom, true},            {footR, 0.15f * s},         // foot
        {footR, 0.15f * s, true},         {p.postR, 0.25f * s},       // chamfer
        {p.postR, 0.25f * s, true},       {p.postR, shaftTop},        // shaft
        {p.postR, shaftTop, true},        {capitalR, capitalBottom},  // capital flare
        {capitalR, capitalBottom, true},  {capitalR, p.postTop},      // capital
        {capitalR, p.postTop, true},      {0.0f, p.postTop},          // top disk
    };
    // clang-format on
    // Past 48 segments a post looks no rounder; the budget goes to slats and battens.
    addLathe(b, translate(at), profile, std::min(4 + 2 * detail, 48));
}

/// Beams, slats across them, battens across the slats and knee braces: the crossing bars whose
/// shadows the thesis' pergola is there for.
void addRoof(MeshBuilder& b, const PergolaSize& p, float s, int detail) {
    for (float z : {-p.halfZ, p.halfZ})
        addBox(b, translate({0.0f, p.postTop + 0.1f * s, z}),
               glm::vec3(p.halfX + 0.4f * s, 0.1f * s, 0.07f * s));

    const int slats = 3 + 2 * std::min(detail, 8);
    const float slatY = p.postTop + 0.24f * s;
    for (int i = 0; i < slats; ++i) {
        const float u = 2.0f * static_cast<float>(i) / static_cast<float>(slats - 1) - 1.0f;
        addBox(b, translate({(p.halfX + 0.3f * s) * u, slatY, 0.0f}),
               glm::vec3(0.04f * s, 0.04f * s, p.halfZ + 0.35f * s));
    }
    const int battens = detail < 4 ? 0 : std::min(2 + (detail - 4) / 2, 7);
    for (int i = 0; i < battens; ++i) {
        const float u = 2.0f * static_cast<float>(i + 1) / static_cast<float>(battens + 1) - 1.0f;
        addBox(b, translate({0.0f, slatY + 0.065f * s, (p.halfZ + 0.2f * s) * u}),
               glm::vec3(p.halfX + 0.35f * s, 0.025f * s, 0.025f * s));
    }
    if (detail < 2) return;
    for (int k = 0; k < 4; ++k) { // 45-degree braces from each post up to its beam
        const float sx = (k & 1) ? 1.0f : -1.0f;
        const float sz = (k & 2) ? 1.0f : -1.0f;
        const glm::vec3 centre(sx * (p.halfX - 0.25f * s), p.postTop - 0.25f * s, sz * p.halfZ);
        addBox(b, frameAlong(centre, normalized(glm::vec3(sx, -1.0f, 0.0f))),
               glm::vec3(0.035f * s, 0.36f * s, 0.035f * s));
    }
}

void buildPergola(const ObjectDesign& d, const Terrain& terrain, int detail, MeshBuilder& b) {
    const PergolaSize p(d.scale);
    const glm::mat4 world = placeYaw(d.origin, d.yaw);
    for (int k = 0; k < 4; ++k) {
        const glm::vec3 local((k & 1) ? p.halfX : -p.halfX, 0.0f, (k & 2) ? p.halfZ : -p.halfZ);
        const glm::vec3 w(world * glm::vec4(local, 1.0f));
        // Each post reaches below the ground at its own foot, so none floats on a slope.
        const float bottom = terrain.groundUnder({w.x, w.z}, p.postR) - d.origin.y - kSink;
        addPost(b, local, bottom, p, d.scale, detail);
    }
    addRoof(b, p, d.scale, detail);
}

// ---- mushroom ---------------------------------------------------------------------------------

void buildMushroom(const ObjectDesign& d, int detail, MeshBuilder& stem, MeshBuilder& cap) {
    Rng rng(d.seed);
    const float s = d.scale;
    const float stemR = 0.09f * s * rng.uniform(0.9f, 1.1f);
    const float stemH = 0.7f * s;
    const float capR = 0.45f * s * rng.uniform(0.9f, 1.15f);
    const float capH = 0.35f * s * rng.uniform(0.85f, 1.1f);
    const float rimY = 0.6f * s;
    const float tilt = rng.uniform(-0.12f, 0.12f);

    const auto stemProfile = columnProfile(-kSink, stemH, 2 + detail / 3, 0.0f, [&](float t) {
        return stemR * (1.3f - 0.45f * t + 0.1f * std::sin(kPi * t));
    });
    addLathe(stem, glm::mat4(1.0f), stemProfile, 4 + detail / 2);

    // Cap: underside from the centre out to the rim, then the dome up to the top pole.
    std::vector<ProfilePoint> profile;
    profile.push_back({0.0f, rimY + 0.06f * s});
    const int underRings = detail / 3;
    for (int i = 1; i <= underRings; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(underRings + 1);
        profile.push_back({t * capR, rimY + 0.06f * s * (1.0f - t * t)});
    }
    profile.push_back({capR, rimY});
    const int domeRings = 1 + detail / 2;
    if (detail > 0) profile.push_back({capR, rimY, true}); // crease along the rim
    for (int i = 1; i < domeRings; ++i) {
        const float a = 0.5f * kPi * static_cast<float>(i) / static_cast<float>(domeRings);
        profile.push_back({capR * std::cos(a), rimY + capH * std::sin(a)});
    }
    profile.push_back({0.0f, rimY + capH});
    // A slight tilt about the top of the stem so the three caps do not look stamped out.
    const glm::mat4 tiltX(glm::vec4(1, 0, 0, 0), glm::vec4(0, std::cos(tilt), std::sin(tilt), 0),
                          glm::vec4(0, -std::sin(tilt), std::cos(tilt), 0), glm::vec4(0, 0, 0, 1));
    const glm::mat4 capXf = translate({0, stemH, 0}) * tiltX * translate({0, -stemH, 0});
    addLathe(cap, capXf, profile, 4 + detail);
}

// ---- rock -------------------------------------------------------------------------------------

void buildRock(const ObjectDesign& d, int detail, MeshBuilder& b) {
    Rng rng(d.seed);
    const float s = d.scale;
    const glm::vec3 radii = s * glm::vec3(0.9f, 0.55f, 0.7f);
    const Bumps bumps = Bumps::random(rng, 0.2f);
    addBlob(b, translate({0.0f, 0.3f * s, 0.0f}) * scaleMat(radii), 5 + detail, 3 + detail / 2,
            bumps);
}

// ---- flower -----------------------------------------------------------------------------------

void buildFlower(const ObjectDesign& d, int detail, MeshBuilder& green, MeshBuilder& bloom) {
    Rng rng(d.seed);
    const float s = d.scale;
    const float stemLen = 0.75f * s;
    const float lean = rng.uniform(0.03f, 0.08f);
    const glm::vec3 axis = normalized({lean, 1.0f, 0.0f});
    const glm::vec3 top = glm::vec3(0.0f, -kSink, 0.0f) + (stemLen + kSink) * axis;

    const int thinSegs = 3 + detail / 4;
    addCapsule(green, frameAlong({0.0f, -kSink, 0.0f}, axis), 0.018f * s, stemLen + kSink, thinSegs,
               detail < 2 ? 0 : 1 + detail / 6);

    const int leafSegs = 4 + detail / 3;
    const int leafStacks = 2 + detail / 4;
    const int leaves = detail == 0 ? 1 : 2;
    for (int i = 0; i < leaves; ++i) {
        const float h = (0.2f + 0.15f * static_cast<float>(i)) * s;
        const float az = kPi * static_cast<float>(i) + rng.uniform(-0.4f, 0.4f);
        const glm::vec3 out(std::cos(az), 0.45f, -std::sin(az));
        const glm::vec3 dir = normalized(out);
        const glm::vec3 centre =
            glm::vec3(0.0f, h, 0.0f) + h * lean * glm::vec3(1, 0, 0) + 0.13f * s * dir;
        addSphere(green,
                  orientedEllipsoid(centre, dir, {0, 1, 0}, s * glm::vec3(0.14f, 0.012f, 0.05f)),
                  leafSegs, leafStacks);
    }

    addSphere(bloom, translate(top) * scaleMat(glm::vec3(0.05f * s)), leafSegs, leafStacks);
    const int petals = detail == 0 ? 3 : 6;
    for (int i = 0; i < petals; ++i) {
        const float az = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(petals);
        const glm::vec3 dir = normalized({std::cos(az), 0.35f, -std::sin(az)});
        addSphere(bloom,
                  orientedEllipsoid(top + 0.1f * s * dir, dir, {0, 1, 0},
                                    s * glm::vec3(0.1f, 0.012f, 0.045f)),
                  leafSegs, leafStacks);
    }
}

// ---- character --------------------------------------------------------------------------------

/// The character at its rest pose; `rig` (if given) learns which vertices each joint carries.
void buildCharacter(const ObjectDesign& d, int detail, MeshBuilder& b, std::vector<RigPart>* rig) {
    const CharacterDesign c = designCharacter(d);
    const float s = c.s;
    const float hip = c.hip;
    // Records the vertices the shape just emitted as carried by `joint`.
    std::uint32_t first = b.vertexCount();
    const auto part = [&](int joint) {
        if (rig) rig->push_back({first, b.vertexCount(), joint});
        first = b.vertexCount();
    };

    const int limbSegs = 3 + detail / 2;
    const int limbRings = detail == 0 ? 0 : 1 + detail / 4;
    for (float side : {-1.0f, 1.0f}) { // legs, from the feet up to the hip
        const glm::vec3 foot(side * (0.1f * s + c.legSplay * hip), -kSink, 0.0f);
        const glm::vec3 hipJoint(side * 0.1f * s, hip, 0.0f);
        const glm::vec3 leg = hipJoint - foot;
        addCapsule(b, frameAlong(foot, normalized(leg)), 0.075f * s, std::sqrt(glm::dot(leg, leg)),
                   limbSegs, limbRings);
        part(side < 0.0f ? kLegL : kLegR);
    }

    const glm::mat4 torsoXf =
        translate({0.0f, hip - 0.08f * s, 0.0f}) * scaleMat(glm::vec3(1.0f, 1.0f, 0.7f));
    addCapsule(b, torsoXf, 0.2f * s, 0.72f * s, 4 + detail / 2, 1 + detail / 4);
    part(kSpine);
    addSphere(b, translate({0.0f, 1.6f * s, 0.0f}) * scaleMat(glm::vec3(0.12f * s)), 4 + detail,
              2 + detail / 2);
    part(kHead);

    for (int i = 0; i < 2; ++i) { // arms hang from the shoulders; one may wave
        const float side = i == 0 ? -1.0f : 1.0f;
        const glm::vec3 shoulder(side * 0.24f * s, 1.4f * s, 0.0f);
        const float swing = (c.waving && i == 1) ? 2.6f : c.armSwing[i];
        const glm::vec3 dir(side * std::sin(swing), -std::cos(swing), 0.15f);
        addCapsule(b, frameAlong(shoulder, normalized(dir)), 0.055f * s, 0.65f * s, limbSegs,
                   limbRings);
        part(i == 0 ? kArmL : kArmR);
    }
}

} // namespace

int partCount(Kind kind) {
    return kind == Kind::Tree || kind == Kind::Mushroom || kind == Kind::Flower ? 2 : 1;
}

std::string partSuffix(Kind kind, int part) {
    if (part == 0) return {};
    switch (kind) {
    case Kind::Tree:
        return ".crown";
    case Kind::Mushroom:
        return ".cap";
    case Kind::Flower:
        return ".bloom";
    default:
        return ".part" + std::to_string(part);
    }
}

glm::vec4 partColor(Kind kind, int part, int variant, Rng& rng) {
    // Linear base colours; the jitter keeps duplicated objects apart.
    glm::vec3 c(0.5f);
    switch (kind) {
    case Kind::Tree:
        c = part == 0 ? glm::vec3(0.24f, 0.15f, 0.08f) : glm::vec3(0.12f, 0.32f, 0.07f);
        break;
    case Kind::Pergola:
        c = glm::vec3(0.55f, 0.42f, 0.28f);
        break;
    case Kind::Mushroom:
        c = part == 0 ? glm::vec3(0.85f, 0.8f, 0.68f) : glm::vec3(0.7f, 0.08f, 0.05f);
        break;
    case Kind::Rock:
        c = glm::vec3(0.36f, 0.35f, 0.33f);
        break;
    case Kind::Flower:
        c = part == 0 ? glm::vec3(0.15f, 0.45f, 0.1f) : glm::vec3(0.85f, 0.55f, 0.05f);
        break;
    case Kind::Character: {
        static constexpr glm::vec3 kShirts[] = {
            {0.1f, 0.25f, 0.7f}, {0.7f, 0.2f, 0.5f}, {0.2f, 0.55f, 0.5f}, {0.75f, 0.45f, 0.1f}};
        c = kShirts[variant % 4];
        break;
    }
    }
    const float jitter = rng.uniform(0.9f, 1.1f);
    return glm::vec4(glm::min(c * jitter, glm::vec3(1.0f)), 1.0f);
}

float layoutRadius(Kind kind, float scale) {
    switch (kind) {
    case Kind::Tree:
        return 2.4f * scale;
    case Kind::Pergola:
        return 2.2f * scale;
    case Kind::Mushroom:
        return 0.5f * scale;
    case Kind::Rock:
        return 1.0f * scale;
    case Kind::Flower:
        return 0.4f * scale;
    case Kind::Character:
        return 0.6f * scale;
    }
    return 1.0f;
}

float baseRadius(Kind kind, float scale) {
    switch (kind) {
    case Kind::Tree:
        return 0.35f * scale;
    case Kind::Pergola:
        return 0.0f; // each post finds its own ground
    case Kind::Mushroom:
        return 0.12f * scale;
    case Kind::Rock:
        return 0.5f * scale;
    case Kind::Flower:
        return 0.03f * scale;
    case Kind::Character:
        return 0.25f * scale;
    }
    return 0.0f;
}

void placeOnTerrain(ObjectDesign& design, const Terrain& terrain) {
    float y = terrain.groundUnder(design.at, baseRadius(design.kind, design.scale));
    if (design.kind == Kind::Pergola) {
        // The roof is level: it rests on the highest post foot, the other posts reach down.
        const PergolaSize p(design.scale);
        const glm::mat4 world = placeYaw(glm::vec3(design.at.x, 0.0f, design.at.y), design.yaw);
        y = terrain.surfaceHeight(design.at.x, design.at.y);
        for (int k = 0; k < 4; ++k) {
            const glm::vec3 local((k & 1) ? p.halfX : -p.halfX, 0.0f, (k & 2) ? p.halfZ : -p.halfZ);
            const glm::vec3 w(world * glm::vec4(local, 1.0f));
            y = std::max(y, terrain.surfaceHeight(w.x, w.z));
        }
    }
    design.origin = glm::vec3(design.at.x, y, design.at.y);
}

void buildObject(const ObjectDesign& design, const Terrain& terrain, int detail,
                 std::array<MeshBuilder, 2>& parts, std::vector<RigPart>* rig) {
    switch (design.kind) {
    case Kind::Tree:
        buildTree(design, detail, parts[0], parts[1]);
        break;
    case Kind::Pergola:
        buildPergola(design, terrain, detail, parts[0]);
        break;
    case Kind::Mushroom:
        buildMushroom(design, detail, parts[0], parts[1]);
        break;
    case Kind::Rock:
        buildRock(design, detail, parts[0]);
        break;
    case Kind::Flower:
        buildFlower(design, detail, parts[0], parts[1]);
        break;
    case Kind::Character:
        buildCharacter(design, detail, parts[0], rig);
        break;
    }
}

std::size_t objectTriangles(const ObjectDesign& design, const Terrain& terrain, int detail) {
    std::array<MeshBuilder, 2> parts{MeshBuilder(true), MeshBuilder(true)};
    buildObject(design, terrain, detail, parts);
    return parts[0].triangles() + parts[1].triangles();
}

} // namespace fl::gen
