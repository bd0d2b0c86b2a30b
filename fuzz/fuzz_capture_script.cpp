// libFuzzer target: capture scripts (floodlight capture SCRIPT.json) on any text, through
// readCaptureScript and a per-process temporary file, as the command reads them. A bad script
// must throw CaptureScriptError naming the field; a script that parses must hold values in the
// ranges the capture relies on: frames, resolutions and sizes within their limits, finite
// cameras along the path and finite light keys, known methods with unique labels.
#include "FuzzInput.h"
#include <app/CaptureScript.h>

#include <base/Finite.h>
#include <renderer/methods/ShadowMethod.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

namespace {

/// What parseCaptureScript promises about a script it returns (CaptureScript.h).
void checkScript(const fl::app::CaptureScript& s) {
    REQUIRE(s.frames >= 1 && s.frames <= fl::app::kMaxCaptureFrames);
    if (s.camera) {
        REQUIRE(s.camera->keys().size() >= 2 && std::isfinite(s.camera->yfovDegrees()));
        for (const float t : {0.0f, 0.37f, 1.0f}) {
            const fl::CameraKey k = s.camera->keyAt(t);
            REQUIRE(fl::geom::allFinite(k.eye) && fl::geom::allFinite(k.target));
        }
    }
    REQUIRE(!s.lightRadius || (std::isfinite(*s.lightRadius) && *s.lightRadius >= 0.0f));
    for (const glm::vec3& k : s.lightKeys) REQUIRE(fl::geom::allFinite(k));
    REQUIRE(!s.resolutions.empty());
    for (const auto& [w, h] : s.resolutions) REQUIRE(w >= 1 && w <= 8192 && h >= 1 && h <= 8192);
    REQUIRE(s.shadowMapProvider == "uniform" || s.shadowMapProvider == "tsm");
    REQUIRE(s.shadowMapSize >= 16 && s.shadowMapSize <= 8192);
    for (const fl::MethodOption* o : s.reference.method().options) // every one valid
        REQUIRE(fl::checkOptionValue(*o, s.reference.options.text(*o)).empty());
    (void)fl::app::referenceText(s.reference); // throws for an unknown kind: a bug here
    REQUIRE(!s.methods.empty());
    std::set<std::string> labels;
    for (const fl::app::MethodSpec& m : s.methods) {
        REQUIRE(fl::findMethod(m.method) != nullptr && !m.label.empty());
        REQUIRE(labels.insert(m.label).second);
        (void)fl::app::settingsFor(fl::RenderSettings{}, m);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path file = fl::fuzz::tempFile("capture_script", "json");
    fl::fuzz::writeInput(file, data, size);
    try {
        checkScript(fl::app::readCaptureScript(file));
    } catch (const fl::app::CaptureScriptError&) {
    }
    return 0;
}
