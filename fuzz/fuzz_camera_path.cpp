// libFuzzer target: camera paths (capture scripts' camera files, inline keys) on any text. Bad
// JSON, a non-finite or out-of-range number, a degenerate key must throw std::runtime_error; a
// path that parses must give finite cameras along its whole length.
#include <scene/CameraPath.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const fl::CameraPath path = fl::parseCameraPath(text);
        for (float t : {0.0f, 0.37f, 1.0f}) {
            const fl::CameraKey k = path.keyAt(t);
            for (int i = 0; i < 3; ++i)
                if (!std::isfinite(k.eye[i]) || !std::isfinite(k.target[i])) std::abort();
        }
    } catch (const std::runtime_error&) {
    }
    return 0;
}
