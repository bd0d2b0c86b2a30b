#pragma once
// Smooth camera paths for walkthroughs: keyframes (eye, target) interpolated with centripetal-
// free uniform Catmull-Rom splines (or piecewise linearly), sampled at a fixed frame count.
// Measurements of temporal behaviour (TSM continuity, flicker) need a camera that moves smoothly
// over a static scene.

#include <scene/Camera.h>
#include <scene/Scene.h>

#include <filesystem>
#include <string_view>
#include <vector>

namespace fl {

struct CameraKey {
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f};
};

/// How the path runs between keys: a C1 spline, or straight segments (kinks at the keys).
enum class PathInterpolation { CatmullRom, Linear };
/// "catmull-rom" or "linear".
const char* interpolationName(PathInterpolation i);

class CameraPath {
  public:
    /// At least two keys; throws std::invalid_argument otherwise or if a key's eye equals its
    /// target.
    explicit CameraPath(std::vector<CameraKey> keys, float yfovDegrees = 50.0f,
                        PathInterpolation interpolation = PathInterpolation::CatmullRom);
    /// The camera at parameter t in [0, 1] (clamped): passes through every key, C1-continuous.
    [[nodiscard]] CameraKey keyAt(float t) const;
    /// The camera view at t for a picture of the given aspect; near/far from the scene bounds.
    [[nodiscard]] CameraView viewAt(float t, const geom::Aabb& bounds, float aspect) const;
    /// Frame i of n evenly spaced frames from the first key to the last.
    [[nodiscard]] CameraView frame(int i, int n, const geom::Aabb& bounds, float aspect) const;
    [[nodiscard]] const std::vector<CameraKey>& keys() const { return keys_; }
    [[nodiscard]] float yfovDegrees() const { return yfovDegrees_; }
    [[nodiscard]] PathInterpolation interpolation() const { return interpolation_; }

  private:
    std::vector<CameraKey> keys_;
    float yfovDegrees_;
    PathInterpolation interpolation_;
};

/// Reads a camera path from JSON: {"fov": degrees (optional, default 50), "interpolation":
/// "catmull-rom" | "linear" (optional), "keys": [{"eye": [x, y, z], "target": [x, y, z]}, ...]}
/// with at least two keys. Throws std::runtime_error "FILE: FIELD: problem" for a missing or
/// malformed field; fl::InputFileError (a runtime_error, "ROLE FILE: problem") for a file that is
/// missing, not a regular file or over kTextInputLimitMiB. `role` names the option or field.
CameraPath readCameraPath(const std::filesystem::path& file, std::string_view role = {});
/// The same from JSON text (e.g. an object inside a capture script); other members of the object
/// are ignored. Throws std::runtime_error "FIELD: problem".
CameraPath parseCameraPath(const std::string& jsonText);

/// Writes a path in the format readCameraPath reads (temporary name, then rename).
void writeCameraPath(const std::filesystem::path& file, const CameraPath& path);

/// A walkthrough that starts at `start` (e.g. the scene's camera): it swings 60 degrees around
/// the vertical axis through the point the camera looks at, closing in to 55% of the distance
/// half-way and back out, at a height that scales with the distance (so it stays above the
/// ground the start camera looks down on). Eye height relative to the ground is not known from
/// the bounds alone, which is why a path is built from a camera rather than from the bounds.
CameraPath defaultWalkthrough(const CameraView& start, const geom::Aabb& bounds);

/// A full circle around the vertical axis through the point of `start`'s view axis nearest the
/// centre of `focus` (the model's bounds), at `start`'s distance, height and field of view: the
/// auto frame (capture scripts' "path": "orbit") seen from every side, first and last frame at
/// `start`'s eye. 24 keys, 15 degrees apart, so the spline stays within 0.1% of the circle.
CameraPath orbitPath(const CameraView& start, const geom::Aabb& focus);

/// The light position at frame i of n along `keys` (piecewise linear; the origin without keys).
glm::vec3 lightPositionAt(const std::vector<glm::vec3>& keys, int i, int n);

} // namespace fl
