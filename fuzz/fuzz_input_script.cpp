// libFuzzer target: view --script parsing on any text. A bad line must throw
// std::runtime_error naming the line; events that parse must hold finite, bounded values.
#include <app/InputScript.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        for (const fl::app::ScriptEvent& e : fl::app::parseInputScript(text, "fuzz.script")) {
            if (!std::isfinite(e.from.x) || !std::isfinite(e.from.y) || !std::isfinite(e.to.x) ||
                !std::isfinite(e.to.y) || !std::isfinite(e.scroll))
                std::abort();
            if (e.frames < 0 || e.frames > 1'000'000 || e.steps < 0 || e.steps > 1'000'000)
                std::abort();
        }
    } catch (const std::runtime_error&) {
    }
    return 0;
}
