#include <scene/ClosedForm.h>

#include <scene/DiskLight.h>

#include <base/Text.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace fl {

double straightEdgeVisibility(double x, double h, double H, double r) {
    const double t = (-x * (H - h) / h) / r;
    if (t >= 1.0) return 0.0;
    if (t <= -1.0) return 1.0;
    return t >= 0.0 ? segmentFraction(static_cast<float>(t))
                    : 1.0 - segmentFraction(static_cast<float>(-t));
}

double diskOccluderVisibility(double rho, double a, double h, double H, double r) {
    const double R = a * H / h, d = rho * (H - h) / h;
    double lens = 0.0;
    if (d >= r + R) {
        lens = 0.0;
    } else if (d <= std::abs(R - r)) {
        lens = std::numbers::pi * std::min(r, R) * std::min(r, R);
    } else {
        const double k = std::sqrt((-d + r + R) * (d + r - R) * (d - r + R) * (d + r + R));
        lens = r * r * std::acos((d * d + r * r - R * R) / (2 * d * r)) +
               R * R * std::acos((d * d + R * R - r * r) / (2 * d * R)) - 0.5 * k;
    }
    return 1.0 - lens / (std::numbers::pi * r * r);
}

namespace {

// A flat horizontal polygon: the fan of `ring` around `centre`, facing up, and with `twoSided`
// also facing down (a zero-thickness occluder that every pass sees from either side).
Mesh fan(const std::string& name, glm::vec3 centre, const std::vector<glm::vec3>& ring,
         bool twoSided) {
    Mesh m;
    m.name = name;
    const auto add = [&](glm::vec3 p, glm::vec3 n) {
        m.positions.push_back(p);
        m.normals.push_back(n);
        m.texcoords.emplace_back(0.0f);
        return static_cast<std::uint32_t>(m.positions.size() - 1);
    };
    for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)}) {
        if (n.y < 0 && !twoSided) break;
        const std::uint32_t c = add(centre, n);
        const auto first = static_cast<std::uint32_t>(m.positions.size());
        for (const glm::vec3& p : ring) add(p, n);
        const auto count = static_cast<std::uint32_t>(ring.size());
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t a = first + i, b = first + (i + 1) % count;
            // Counter-clockwise seen from the side the normal points to, whichever way the
            // ring runs.
            const glm::vec3 e =
                glm::cross(m.positions[a] - m.positions[c], m.positions[b] - m.positions[c]);
            if ((e.y > 0) == (n.y > 0))
                m.indices.insert(m.indices.end(), {c, a, b});
            else
                m.indices.insert(m.indices.end(), {c, b, a});
        }
    }
    m.material = 1;
    return m;
}

// Ground, occluder and the spot light above the origin; the camera low on the side `toward`
// points to, looking back past the origin.
ClosedFormCase makeCase(std::string name, Mesh occluder, float H, float r, glm::vec2 toward) {
    ClosedFormCase c;
    c.name = std::move(name);
    Scene& s = c.scene;
    s.source = "closed form: " + c.name;
    const float half = 4.0f;
    std::vector<glm::vec3> groundRing = {
        {half, 0, half}, {half, 0, -half}, {-half, 0, -half}, {-half, 0, half}};
    Mesh ground = fan("ground", glm::vec3(0.0f), groundRing, false);
    ground.material = 0;
    s.meshes = {std::move(ground), std::move(occluder)};
    s.materials = {{"ground", glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), -1, true},
                   {"occluder", glm::vec4(0.8f, 0.3f, 0.2f, 1.0f), -1, true}};
    s.instances = {{0, glm::mat4(1.0f), 1, "ground"}, {1, glm::mat4(1.0f), 2, "occluder"}};
    Light l;
    l.type = Light::Type::Spot;
    l.position = {0.0f, H, 0.0f};
    l.direction = {0.0f, -1.0f, 0.0f};
    l.radius = r;
    l.outerConeAngle = 1.2f;
    s.light = l;
    s.computeBounds();
    const glm::vec2 t = glm::normalize(toward), side(-t.y, t.x);
    c.camera.kind = CameraSpec::Kind::LookAt;
    c.camera.eye = glm::vec3(2.5f * t.x + 0.3f * side.x, 0.6f, 2.5f * t.y + 0.3f * side.y);
    c.camera.target = glm::vec3(-0.3f * t.x, 0.0f, -0.3f * t.y);
    return c;
}

} // namespace

ClosedFormCase straightEdgeCase(float h, float H, float r, float angleDegrees) {
    const float a = glm::radians(angleDegrees);
    const glm::vec2 out(std::cos(a), std::sin(a)), along(-out.y, out.x);
    const auto at = [&](float o, float s) {
        const glm::vec2 p = o * out + s * along;
        return glm::vec3(p.x, h, p.y);
    };
    // 16 wide and 8 deep behind the edge: from any ground point within the extent, every ray to
    // the disk crosses the occluder's plane well inside it where the half-plane would.
    Mesh occluder =
        fan("half-plane", at(-4.0f, 0.0f), {at(0, -8), at(0, 8), at(-8, 8), at(-8, -8)}, true);
    ClosedFormCase c = makeCase(cat("edge h ", h, " H ", H, " r ", r, " at ", angleDegrees, "deg"),
                                std::move(occluder), H, r, out);
    c.exact = [=](glm::vec3 p) {
        return straightEdgeVisibility(glm::dot(glm::vec2(p.x, p.z), out), h, H, r);
    };
    return c;
}

ClosedFormCase diskOccluderCase(float a, float h, float H, float r) {
    std::vector<glm::vec3> ring;
    constexpr int kSides = 128;
    // The 128-gon's area equals the disk's (radius scaled by sqrt(2 pi / (n sin(2 pi / n)))):
    // the polygon's error against the closed form is then well under 1e-3.
    const double scale =
        std::sqrt(2.0 * std::numbers::pi / (kSides * std::sin(2.0 * std::numbers::pi / kSides)));
    for (int i = 0; i < kSides; ++i) {
        const double t = 2.0 * std::numbers::pi * i / kSides;
        ring.emplace_back(static_cast<float>(a * scale * std::cos(t)), h,
                          static_cast<float>(a * scale * std::sin(t)));
    }
    Mesh occluder = fan("disk", glm::vec3(0.0f, h, 0.0f), ring, true);
    ClosedFormCase c = makeCase(cat("disk a ", a, " h ", h, " H ", H, " r ", r),
                                std::move(occluder), H, r, glm::vec2(1.0f, 0.0f));
    c.exact = [=](glm::vec3 p) {
        return diskOccluderVisibility(glm::length(glm::vec2(p.x, p.z)), a, h, H, r);
    };
    c.extent = 1.5f;
    return c;
}

ClosedFormError closedFormError(const ClosedFormCase& c, const FloatImage& position,
                                const FloatImage& visibility) {
    ClosedFormError e;
    e.exact = visibility;
    double sum2 = 0.0, pen2 = 0.0, bias = 0.0;
    for (int y = 0; y < visibility.height; ++y)
        for (int x = 0; x < visibility.width; ++x) {
            const glm::vec3 p(position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2));
            if (position.at(x, y, 3) == 0.0f || std::abs(p.y) > 1e-4f) continue;
            if (std::abs(p.x) > c.extent || std::abs(p.z) > c.extent) continue;
            const double exact = c.exact(p);
            e.exact.data[static_cast<std::size_t>(y) * static_cast<std::size_t>(visibility.width) +
                         static_cast<std::size_t>(x)] = static_cast<float>(exact);
            const double d = visibility.at(x, y, 0) - exact;
            sum2 += d * d;
            e.maxAbs = std::max(e.maxAbs, std::abs(d));
            ++e.ground;
            if (exact > 0.02 && exact < 0.98) {
                pen2 += d * d;
                bias += d;
                ++e.penumbra;
            }
        }
    if (e.ground) e.rmse = std::sqrt(sum2 / static_cast<double>(e.ground));
    if (e.penumbra) {
        e.rmsePenumbra = std::sqrt(pen2 / static_cast<double>(e.penumbra));
        e.biasPenumbra = bias / static_cast<double>(e.penumbra);
    }
    return e;
}

std::vector<ClosedFormCase> closedFormCases() {
    std::vector<ClosedFormCase> cases;
    for (float angle : {0.0f, 30.0f, 60.0f})
        cases.push_back(straightEdgeCase(1.0f, 5.0f, 1.0f, angle));
    cases.push_back(straightEdgeCase(0.5f, 6.0f, 1.0f, 20.0f));
    cases.push_back(straightEdgeCase(2.0f, 4.0f, 0.5f, 45.0f));
    cases.push_back(diskOccluderCase(0.6f, 1.5f, 5.0f, 1.0f));
    return cases;
}

} // namespace fl
