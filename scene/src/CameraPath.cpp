#include <scene/CameraPath.h>

#include <io/ImageIO.h>
#include <io/JsonText.h>

#include <base/InputFile.h>
#include <base/Numbers.h>

#include <base/Framing.h>

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fl {

namespace {

glm::vec3 catmullRom(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, float t) {
    const float t2 = t * t, t3 = t2 * t;
    return 0.5f * ((2.0f * p1) + (-p0 + p2) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                   (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * t3);
}

} // namespace

const char* interpolationName(PathInterpolation i) {
    return i == PathInterpolation::Linear ? "linear" : "catmull-rom";
}

CameraPath::CameraPath(std::vector<CameraKey> keys, float yfovDegrees,
                       PathInterpolation interpolation)
    : keys_(std::move(keys)), yfovDegrees_(yfovDegrees), interpolation_(interpolation) {
    if (keys_.size() < 2) throw std::invalid_argument("a camera path needs at least two keys");
    for (std::size_t i = 0; i < keys_.size(); ++i)
        if (glm::length(keys_[i].target - keys_[i].eye) < 1e-6f)
            throw std::invalid_argument("keys[" + std::to_string(i) +
                                        "]: eye and target are the same point");
}

CameraKey CameraPath::keyAt(float t) const {
    const int segments = static_cast<int>(keys_.size()) - 1;
    const float u = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(segments);
    const int i = std::min(static_cast<int>(u), segments - 1);
    const float f = u - static_cast<float>(i);
    if (interpolation_ == PathInterpolation::Linear) {
        const CameraKey& a = keys_[static_cast<std::size_t>(i)];
        const CameraKey& b = keys_[static_cast<std::size_t>(i) + 1];
        return {glm::mix(a.eye, b.eye, f), glm::mix(a.target, b.target, f)};
    }
    // End keys are mirrored so the curve starts and ends at the first and last key.
    auto at = [&](int k) -> const CameraKey& {
        return keys_[static_cast<std::size_t>(std::clamp(k, 0, segments))];
    };
    return {catmullRom(at(i - 1).eye, at(i).eye, at(i + 1).eye, at(i + 2).eye, f),
            catmullRom(at(i - 1).target, at(i).target, at(i + 1).target, at(i + 2).target, f)};
}

CameraView CameraPath::viewAt(float t, const geom::Aabb& bounds, float aspect) const {
    const CameraKey k = keyAt(t);
    glm::vec3 dir = k.target - k.eye;
    if (glm::length(dir) < 1e-6f) dir = keys_.front().target - keys_.front().eye;
    CameraView v;
    v.eye = k.eye;
    v.view = glm::lookAt(k.eye, k.eye + dir, geom::stableUp(dir));
    const float r = std::max(bounds.radius(), 1e-3f);
    const float d = glm::length(bounds.center() - k.eye);
    const float znear = std::max(1e-3f * r, std::min(0.05f * r, (d - r) * 0.5f));
    v.proj = glm::perspective(glm::radians(yfovDegrees_), aspect, znear, (d + r) * 1.5f);
    return v;
}

CameraView CameraPath::frame(int i, int n, const geom::Aabb& bounds, float aspect) const {
    const float t = n <= 1 ? 0.0f : static_cast<float>(i) / static_cast<float>(n - 1);
    return viewAt(t, bounds, aspect);
}

namespace {

// What both camera paths turn about: `start`'s eye, the point on its view axis nearest the
// centre of `around` (at least a little ahead), and its vertical field of view.
struct Swing {
    glm::vec3 eye, pivot;
    float yfovDegrees;
};

Swing swingOf(const CameraView& start, const geom::Aabb& around) {
    const glm::mat4 inv = glm::inverse(start.view);
    const glm::vec3 eye = start.eye, forward = -glm::normalize(glm::vec3(inv[2]));
    const float r = std::max(around.radius(), 1e-3f);
    const float along = std::max(glm::dot(around.center() - eye, forward), 0.1f * r);
    return {eye, eye + forward * along, glm::degrees(2.0f * std::atan(1.0f / start.proj[1][1]))};
}

// `offset` turned by `angle` radians about the vertical axis.
glm::vec3 turned(glm::vec3 offset, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return {c * offset.x + s * offset.z, offset.y, -s * offset.x + c * offset.z};
}

} // namespace

CameraPath defaultWalkthrough(const CameraView& start, const geom::Aabb& bounds) {
    const Swing w = swingOf(start, bounds);
    std::vector<CameraKey> keys;
    const int n = 7;
    for (int i = 0; i < n; ++i) {
        const float u = static_cast<float>(i) / static_cast<float>(n - 1); // 0..1
        const float angle = glm::radians(-30.0f + 60.0f * u);
        const float scale = 1.0f - 0.45f * std::sin(3.14159265f * u); // 1 -> 0.55 -> 1
        keys.push_back({w.pivot + turned(w.eye - w.pivot, angle) * scale, w.pivot});
    }
    return CameraPath(std::move(keys), w.yfovDegrees);
}

CameraPath orbitPath(const CameraView& start, const geom::Aabb& focus) {
    const Swing w = swingOf(start, focus);
    std::vector<CameraKey> keys;
    constexpr int kSteps = 24;
    for (int i = 0; i <= kSteps; ++i) {
        const float angle = glm::radians(360.0f * static_cast<float>(i) / kSteps);
        keys.push_back({w.pivot + turned(w.eye - w.pivot, angle), w.pivot});
    }
    return CameraPath(std::move(keys), w.yfovDegrees);
}

namespace {

glm::vec3 readVec3(const nlohmann::json& j, const std::string& where) {
    if (!j.is_array() || j.size() != 3)
        throw std::runtime_error(where + ": expected an array of 3 numbers");
    glm::vec3 v;
    for (int k = 0; k < 3; ++k) {
        try {
            // At most the world's limit: a key at 1.7e38, within a float, made the interpolated
            // cameras infinite (found by fuzz/fuzz_camera_path).
            v[k] = static_cast<float>(jsonNumber(j[static_cast<std::size_t>(k)],
                                                 -kMaxWorldCoordinate, kMaxWorldCoordinate));
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(where + "[" + std::to_string(k) + "]: " + e.what());
        }
    }
    return v;
}

} // namespace

namespace {

CameraPath cameraPathFromJson(const nlohmann::json& j) {
    if (!j.is_object()) throw std::runtime_error("expected an object with \"keys\"");
    float fov = 50.0f;
    if (j.contains("fov")) {
        try {
            fov = static_cast<float>(jsonNumber(j["fov"], 1.0, 170.0));
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(std::string("fov (degrees): ") + e.what());
        }
    }
    PathInterpolation interpolation = PathInterpolation::CatmullRom;
    if (j.contains("interpolation")) {
        const nlohmann::json& i = j["interpolation"];
        if (i == "linear")
            interpolation = PathInterpolation::Linear;
        else if (i != "catmull-rom")
            throw std::runtime_error("interpolation: expected \"catmull-rom\" or \"linear\"");
    }
    if (!j.contains("keys") || !j["keys"].is_array())
        throw std::runtime_error("keys: missing (an array of {eye, target})");
    std::vector<CameraKey> keys;
    for (std::size_t i = 0; i < j["keys"].size(); ++i) {
        const nlohmann::json& k = j["keys"][i];
        const std::string where = "keys[" + std::to_string(i) + "]";
        if (!k.is_object() || !k.contains("eye") || !k.contains("target"))
            throw std::runtime_error(where + ": expected {\"eye\": [..], \"target\": [..]}");
        keys.push_back(
            {readVec3(k["eye"], where + ".eye"), readVec3(k["target"], where + ".target")});
    }
    if (keys.size() < 2) throw std::runtime_error("keys: at least two keys needed");
    return CameraPath(std::move(keys), fov, interpolation);
}

} // namespace

CameraPath parseCameraPath(const std::string& jsonText) {
    const nlohmann::json j = parseJsonText(jsonText);
    try {
        return cameraPathFromJson(j);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(e.what()); // the constructor's message names the key
    }
}

CameraPath readCameraPath(const std::filesystem::path& file, std::string_view role) {
    const std::string name = file.string();
    // Regular files within the text limit only (base/InputFile.h); InputFileError names them.
    const std::string text = readInputFile(file, role, kTextInputLimitMiB);
    try {
        return cameraPathFromJson(parseJsonText(text));
    } catch (const std::exception& e) {
        throw std::runtime_error(name + ": " + e.what());
    }
}

void writeCameraPath(const std::filesystem::path& file, const CameraPath& path) {
    nlohmann::json j;
    j["fov"] = path.yfovDegrees();
    j["interpolation"] = interpolationName(path.interpolation());
    j["keys"] = nlohmann::json::array();
    for (const CameraKey& k : path.keys())
        j["keys"].push_back({{"eye", {k.eye.x, k.eye.y, k.eye.z}},
                             {"target", {k.target.x, k.target.y, k.target.z}}});
    writeTextFile(file, j.dump(2) + "\n");
}

glm::vec3 lightPositionAt(const std::vector<glm::vec3>& keys, int i, int n) {
    if (keys.empty()) return glm::vec3(0.0f);
    if (keys.size() == 1 || n <= 1) return keys.front();
    const float u =
        static_cast<float>(i) / static_cast<float>(n - 1) * static_cast<float>(keys.size() - 1);
    const auto k = std::min(static_cast<std::size_t>(u), keys.size() - 2);
    return glm::mix(keys[k], keys[k + 1], u - static_cast<float>(k));
}

} // namespace fl
