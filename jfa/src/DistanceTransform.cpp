#include <jfa/DistanceTransform.h>
#include <jfa/NearestSite.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fl::jfa {

namespace {

void checkPlan(const Plan& plan, int width, int height, const char* what) {
    if (plan.width() != width || plan.height() != height) {
        throw std::invalid_argument(std::string(what) + ": plan \"" + plan.name() +
                                    "\" is built for " + std::to_string(plan.width()) + "x" +
                                    std::to_string(plan.height()) + ", the mask is " +
                                    std::to_string(width) + "x" + std::to_string(height));
    }
}

// Distances of a flooded (or exact nearest) grid: from each texel to the site it holds.
DistanceField distancesOf(const Grid& nearest) {
    DistanceField field{nearest.width, nearest.height, {}};
    field.values.resize(nearest.cells.size());
    const NearestSite criterion{true};
    const float none = noFeatureDistance(nearest.width, nearest.height);
    for (int y = 0; y < nearest.height; ++y) {
        for (int x = 0; x < nearest.width; ++x) {
            const Cell& c = nearest.at(x, y);
            field.values[std::size_t(y) * std::size_t(nearest.width) + std::size_t(x)] =
                criterion.empty(c) ? none : distanceFromSquared(NearestSite::squaredInt(x, y, c));
        }
    }
    return field;
}

DistanceField floodDistances(const std::vector<std::uint8_t>& mask, int width, int height,
                             const Plan& plan, const FloodOptions& options) {
    const Grid seeds = seedMask(mask, width, height);
    return distancesOf(flood(plan, seeds, NearestSite{true}, options));
}

DistanceField exactDistances(const std::vector<std::uint8_t>& mask, int width, int height) {
    const ExactField exact = exactIntegerEdt(seedMask(mask, width, height));
    DistanceField field{width, height, std::vector<float>(exact.distSq.size())};
    const float none = noFeatureDistance(width, height);
    for (std::size_t i = 0; i < exact.distSq.size(); ++i) {
        const double d2 = exact.distSq[i];
        field.values[i] = std::isinf(d2) ? none : distanceFromSquared(std::int64_t(d2));
    }
    return field;
}

// inside < 0 (distance to the outside), outside > 0 (distance to the inside).
DistanceField combineSigned(const std::vector<std::uint8_t>& mask, const DistanceField& toInside,
                            const DistanceField& toOutside) {
    DistanceField field{toInside.width, toInside.height, std::vector<float>(mask.size())};
    for (std::size_t i = 0; i < mask.size(); ++i)
        field.values[i] = mask[i] != 0 ? -toOutside.values[i] : toInside.values[i];
    return field;
}

} // namespace

std::vector<std::uint8_t> invertedMask(const std::vector<std::uint8_t>& mask) {
    std::vector<std::uint8_t> out(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i) out[i] = mask[i] == 0 ? 1 : 0;
    return out;
}

float distanceFromSquared(std::int64_t d2) {
    return static_cast<float>(std::sqrt(static_cast<double>(d2)));
}

float noFeatureDistance(int width, int height) {
    return static_cast<float>(std::hypot(double(width), double(height)));
}

DistanceField distanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                const Plan& plan, const FloodOptions& options) {
    checkPlan(plan, width, height, "distanceTransform");
    return floodDistances(mask, width, height, plan, options);
}

DistanceField distanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                std::string_view planSpec, const FloodOptions& options) {
    return distanceTransform(mask, width, height, parsePlan(planSpec, width, height), options);
}

DistanceField exactDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height) {
    return exactDistances(mask, width, height);
}

DistanceField signedDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                      const Plan& plan, const FloodOptions& options) {
    checkPlan(plan, width, height, "signedDistanceTransform");
    const DistanceField toInside = floodDistances(mask, width, height, plan, options);
    const DistanceField toOutside =
        floodDistances(invertedMask(mask), width, height, plan, options);
    return combineSigned(mask, toInside, toOutside);
}

DistanceField signedDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                      std::string_view planSpec, const FloodOptions& options) {
    return signedDistanceTransform(mask, width, height, parsePlan(planSpec, width, height),
                                   options);
}

DistanceField exactSignedDistanceTransform(const std::vector<std::uint8_t>& mask, int width,
                                           int height) {
    const DistanceField toInside = exactDistances(mask, width, height);
    const DistanceField toOutside = exactDistances(invertedMask(mask), width, height);
    return combineSigned(mask, toInside, toOutside);
}

DistanceField signedDistanceFromNearest(const std::vector<std::uint8_t>& mask,
                                        const Grid& nearestInside, const Grid& nearestOutside) {
    if (nearestInside.cells.size() != mask.size() || nearestOutside.cells.size() != mask.size() ||
        nearestInside.width != nearestOutside.width)
        throw std::invalid_argument("signedDistanceFromNearest: the grids and the mask differ in "
                                    "size");
    return combineSigned(mask, distancesOf(nearestInside), distancesOf(nearestOutside));
}

std::int64_t countDifferences(const DistanceField& a, const DistanceField& b) {
    if (a.width != b.width || a.height != b.height || a.values.size() != b.values.size()) {
        throw std::invalid_argument("countDifferences: fields differ in size");
    }
    std::int64_t count = 0;
    for (std::size_t i = 0; i < a.values.size(); ++i) count += a.values[i] != b.values[i];
    return count;
}

} // namespace fl::jfa
