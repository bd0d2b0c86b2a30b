#pragma once
// Distance transforms of binary masks (thesis §4.1.2): the distance from every pixel to the
// nearest feature pixel, by jump flooding the feature pixels as integer sites (any Plan), or
// exactly (Reference.h) for comparison.
//
// Conventions. A mask holds W * H bytes, row-major, row 0 at y = 0; non-zero = feature / inside.
// Distances are Euclidean, between pixel centres (integer grid points), in pixels, as floats:
// float(sqrt(double(d2))) of the exact integer squared distance d2 the flood or reference found,
// so a JFA value and an exact value are equal exactly when the squared distances are.
//  * Unsigned: 0 on feature pixels, else the distance to the nearest feature pixel;
//    noFeatureDistance(W, H) everywhere if the mask has no feature pixel.
//  * Signed: negative inside, positive outside, never 0. An inside pixel holds minus the distance
//    to the nearest outside pixel; an outside pixel holds plus the distance to the nearest inside
//    pixel. The boundary runs between pixel centres, so the pixels next to it hold -1 (inside)
//    and +1 (outside) (or -sqrt(2) / +sqrt(2) across a corner): the zero level set lies between a
//    negative and a positive pixel, where a renderer interpolates. A mask with no outside pixel
//    (every pixel a site) gives -noFeatureDistance(W, H) everywhere, one with no inside pixel
//    +noFeatureDistance(W, H) everywhere.
//  * noFeatureDistance(W, H) = hypot(W, H): the nearest pixel of the other kind lies beyond the
//    grid, so farther than any two of its pixels are apart (at most hypot(W-1, H-1)). Its sign
//    still says inside or outside, every value stays finite (an EXR of the field has no inf,
//    which a renderer would turn into NaN), and no real distance in any field of that size
//    reaches it. Pixels a plan leaves without a site hold it too.

#include <jfa/CpuKernel.h>
#include <jfa/Plan.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace fl::jfa {

/// A W x H field of distances in pixels, row-major, row 0 at y = 0.
struct DistanceField {
    int width = 0;
    int height = 0;
    std::vector<float> values;

    /// Value at pixel (x, y).
    [[nodiscard]] float at(int x, int y) const {
        return values[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    friend bool operator==(const DistanceField&, const DistanceField&) = default;
};

/// The mask's complement: 1 where `mask` is 0, else 0 (the outside pixels as features).
std::vector<std::uint8_t> invertedMask(const std::vector<std::uint8_t>& mask);
/// A distance in pixels from an exact squared integer distance: float(sqrt(double(d2))).
float distanceFromSquared(std::int64_t d2);
/// The value for "no feature pixel in a W x H grid" (convention above): float(hypot(W, H)).
float noFeatureDistance(int width, int height);

/// Unsigned distance transform by flooding the feature pixels with `plan` (which must be built
/// for W x H; std::invalid_argument otherwise, or for a mask of the wrong size).
DistanceField distanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                const Plan& plan, const FloodOptions& options = {});
/// Unsigned distance transform with the plan parsePlan(planSpec, W, H), e.g. "jfa+2".
DistanceField distanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                std::string_view planSpec, const FloodOptions& options = {});
/// Exact unsigned distance transform (exactIntegerEdt), O(W * H).
DistanceField exactDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height);

/// Signed distance transform (convention above): two floods with `plan`, from the inside and
/// from the outside pixels.
DistanceField signedDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                      const Plan& plan, const FloodOptions& options = {});
/// Signed distance transform with the plan parsePlan(planSpec, W, H).
DistanceField signedDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height,
                                      std::string_view planSpec, const FloodOptions& options = {});
/// Exact signed distance transform (two exactIntegerEdt runs).
DistanceField exactSignedDistanceTransform(const std::vector<std::uint8_t>& mask, int width,
                                           int height);

/// Signed distance transform from nearest-feature grids the caller already has (such as floods
/// repaired by jfa/ExactRepair.h): `nearestInside` holds per pixel an inside pixel's cell (empty
/// where there is none), `nearestOutside` an outside pixel's; both W x H like the mask.
DistanceField signedDistanceFromNearest(const std::vector<std::uint8_t>& mask,
                                        const Grid& nearestInside, const Grid& nearestOutside);

/// Pixels where two fields of the same size hold different values (NaN-free fields).
std::int64_t countDifferences(const DistanceField& a, const DistanceField& b);

} // namespace fl::jfa
