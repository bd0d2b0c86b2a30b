// libFuzzer target: jfa::parsePlan on any text and grid size. Bad specs must throw
// std::invalid_argument, never crash, hang or allocate without bound; a parsed plan must
// describe itself and keep every step inside the grid.
#include <jfa/Plan.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    // The first two bytes choose the grid (1..256 per side): small enough to stay fast.
    const int width = 1 + data[0], height = 1 + data[1];
    const std::string spec(reinterpret_cast<const char*>(data + 2), size - 2);
    try {
        const fl::jfa::Plan plan = fl::jfa::parsePlan(spec, width, height);
        (void)plan.describe();
        if (plan.passCount() < 0) std::abort();
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
