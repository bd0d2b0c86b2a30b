#include <app/Common.h>

#include <algorithm>

namespace fl::app {

std::array<std::uint8_t, 3> regionColour(std::int64_t id) {
    std::uint32_t h = std::uint32_t(std::max<std::int64_t>(id, 0)) * 2654435761u;
    h ^= h >> 15;
    return {std::uint8_t(64 + (h & 0x7f)), std::uint8_t(64 + ((h >> 8) & 0x7f)),
            std::uint8_t(64 + ((h >> 16) & 0x7f))};
}
} // namespace fl::app
