#include <jfa/NearestSite.h>
#include <jfa/Sites.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

namespace fl::jfa {

namespace {

void checkSize(int width, int height, const char* what) {
    if (width < 1 || height < 1) {
        throw std::invalid_argument(std::string(what) + ": grid " + std::to_string(width) + "x" +
                                    std::to_string(height) + " must be at least 1x1");
    }
}

std::size_t area(int width, int height) {
    return std::size_t(width) * std::size_t(height);
}

} // namespace

long long pixelOf(float v) {
    if (!std::isfinite(v)) throw std::invalid_argument("pixelOf: coordinate is not finite");
    const double p = std::floor(double(v) + 0.5);
    constexpr double kLimit = 4.0e18; // beyond any grid; keeps the conversion defined
    return static_cast<long long>(std::clamp(p, -kLimit, kLimit));
}

SeedResult seedPoints(const std::vector<Site>& sites, int width, int height, bool integer) {
    checkSize(width, height, "seedPoints");
    if (sites.size() > std::size_t(kMaxSiteId) + 1) {
        throw std::invalid_argument("seedPoints: " + std::to_string(sites.size()) +
                                    " sites, but ids must be <= " + std::to_string(kMaxSiteId));
    }
    const NearestSite criterion{integer};
    SeedResult result;
    result.grid = Grid(width, height);
    std::vector<char> lost(sites.size(), 0);
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Site& s = sites[i];
        if (!std::isfinite(s.x) || !std::isfinite(s.y)) {
            throw std::invalid_argument("seedPoints: site " + std::to_string(i) +
                                        " has a non-finite coordinate");
        }
        const long long px = pixelOf(s.x), py = pixelOf(s.y);
        if (px < 0 || py < 0 || px >= width || py >= height) {
            throw std::invalid_argument(
                "seedPoints: site " + std::to_string(i) + " at (" + std::to_string(s.x) + ", " +
                std::to_string(s.y) + ") falls in pixel (" + std::to_string(px) + ", " +
                std::to_string(py) + "), outside the " + std::to_string(width) + "x" +
                std::to_string(height) + " grid");
        }
        const int x = int(px), y = int(py);
        const Cell cell =
            integer ? Cell{float(x), float(y), float(i), 0.0f} : Cell{s.x, s.y, float(i), 0.0f};
        Cell& slot = result.grid.at(x, y);
        if (criterion.empty(slot)) {
            slot = cell;
        } else if (criterion.better(x, y, cell, slot)) {
            lost[std::size_t(slot.z)] = 1;
            slot = cell;
        } else {
            lost[i] = 1;
        }
    }
    for (std::size_t i = 0; i < lost.size(); ++i) {
        if (lost[i]) result.missing.push_back(int(i));
    }
    return result;
}

Grid seedMask(const std::vector<std::uint8_t>& mask, int width, int height,
              const std::vector<std::int32_t>* labels) {
    checkSize(width, height, "seedMask");
    const std::size_t n = area(width, height);
    if (mask.size() != n) {
        throw std::invalid_argument("seedMask: mask has " + std::to_string(mask.size()) +
                                    " values, expected " + std::to_string(width) + "x" +
                                    std::to_string(height) + " = " + std::to_string(n));
    }
    if (labels != nullptr && labels->size() != n) {
        throw std::invalid_argument("seedMask: labels have " + std::to_string(labels->size()) +
                                    " values, expected " + std::to_string(n));
    }
    Grid grid(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t index = std::size_t(y) * std::size_t(width) + std::size_t(x);
            if (mask[index] == 0) continue;
            const std::int32_t id = labels != nullptr ? (*labels)[index] : 0;
            if (id < 0 || id > kMaxSiteId) {
                throw std::invalid_argument(
                    "seedMask: label " + std::to_string(id) + " at pixel (" + std::to_string(x) +
                    ", " + std::to_string(y) + ") is outside 0.." + std::to_string(kMaxSiteId));
            }
            grid.at(x, y) = Cell{float(x), float(y), float(id), 0.0f};
        }
    }
    return grid;
}

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

std::uint64_t SplitMix64::below(std::uint64_t bound) {
    if (bound == 0) throw std::invalid_argument("SplitMix64::below: bound must be >= 1");
    // Accept only draws below the largest multiple of bound, so every residue is equally likely.
    const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    const std::uint64_t limit = max - (max % bound + 1) % bound;
    std::uint64_t r = next();
    while (r > limit) r = next();
    return r % bound;
}

double SplitMix64::unit() {
    return double(next() >> 11) * 0x1.0p-53;
}

std::vector<Site> randomIntegerSites(int count, int width, int height, std::uint64_t seed,
                                     bool distinct) {
    checkSize(width, height, "randomIntegerSites");
    const std::size_t n = area(width, height);
    if (count < 0 || (distinct && std::size_t(count) > n)) {
        throw std::invalid_argument("randomIntegerSites: cannot draw " + std::to_string(count) +
                                    (distinct ? " distinct" : "") + " sites on a " +
                                    std::to_string(width) + "x" + std::to_string(height) + " grid");
    }
    SplitMix64 rng(seed);
    std::vector<Site> sites;
    sites.reserve(std::size_t(count));
    auto site = [width](std::uint64_t index) {
        return Site{float(index % std::uint64_t(width)), float(index / std::uint64_t(width))};
    };
    if (!distinct) {
        for (int i = 0; i < count; ++i) sites.push_back(site(rng.below(n)));
    } else if (2 * std::size_t(count) <= n) {
        // Sparse: draw pixels, redrawing taken ones (expected < 2 draws per site).
        std::unordered_set<std::uint64_t> taken;
        taken.reserve(std::size_t(count));
        while (sites.size() < std::size_t(count)) {
            const std::uint64_t index = rng.below(n);
            if (taken.insert(index).second) sites.push_back(site(index));
        }
    } else {
        // Dense: the first `count` entries of a partial Fisher-Yates shuffle of all pixels.
        std::vector<std::uint32_t> pixels(n);
        for (std::size_t i = 0; i < n; ++i) pixels[i] = std::uint32_t(i);
        for (std::size_t i = 0; i < std::size_t(count); ++i) {
            const std::size_t j = i + std::size_t(rng.below(n - i));
            std::swap(pixels[i], pixels[j]);
            sites.push_back(site(pixels[i]));
        }
    }
    return sites;
}

std::vector<Site> randomFloatSites(int count, int width, int height, std::uint64_t seed) {
    checkSize(width, height, "randomFloatSites");
    if (count < 0) throw std::invalid_argument("randomFloatSites: count must be >= 0");
    SplitMix64 rng(seed);
    std::vector<Site> sites;
    sites.reserve(std::size_t(count));
    for (int i = 0; i < count; ++i) {
        const float x = float(rng.unit() * double(width - 1));
        const float y = float(rng.unit() * double(height - 1));
        sites.push_back(Site{x, y});
    }
    return sites;
}

} // namespace fl::jfa
