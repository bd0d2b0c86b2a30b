#pragma once
// Shadow acne and peter-panning, the two faces of a shadow map's depth bias, as shares of the
// pixels where each can show, measured against the ray-traced truth (pure CPU, images with row 0
// at the top as readTexture gives them).
//
// Definitions:
// - Acne candidates: receivers whose triangle's plane (its geometric normal, turned to the side
//   the eye sees) faces the light's centre, and that the truth finds fully lit (v >= 0.99).
//   Acne: the share of them the method darkens by more than 0.1 (truth - method > 0.1).
// - Contact pixels: receivers p with a surface pixel q among their 8 neighbours whose point
//   rises off p's plane by more than half a pixel footprint while lying within 3 footprints of
//   p's point: another surface meets p's there (an occluder standing on it, a wall on a floor). A
//   footprint is the world size of one pixel at p's distance from the eye. A surface floating
//   above p by more than that leaves no contact, whatever its pixels' screen distance.
// - Peter-panning candidates: receivers in the truth's umbra (v <= 0.01) within 3 pixels
//   (Chebyshev: a 7 x 7 window) of a contact pixel. Peter-panning: the share of them the method
//   lights by more than 0.1 (method - truth > 0.1).

#include <renderer/io/TextureImage.h>

#include <glm/vec3.hpp>

#include <cstddef>

namespace fl {

inline constexpr float kAcneLitAtLeast = 0.99f;          // truth's "fully lit"
inline constexpr float kPeterPanningUmbraAtMost = 0.01f; // truth's umbra
inline constexpr float kBiasArtifactChange = 0.1f;       // a method's change that counts
inline constexpr int kContactReach = 3;                  // pixels from a contact (Chebyshev)

/// What the figures need of a frame's surfaces (row 0 at the top): each pixel's world position
/// (4 channels, w = 0 for background), its triangle's plane normal turned to the seen side (4
/// channels, xyz), the receiver mask (1 channel), the eye and the world size of a pixel per unit
/// of distance from it (2 tan(fovy / 2) / height).
struct SurfaceGeometry {
    FloatImage positions, planes, receivers;
    glm::vec3 eye{0.0f};
    float pixelAngle = 0.0f;
};

/// Where each artifact can show: 1-channel masks of the acne candidates' geometry part (receivers
/// whose plane faces `lightCentre`), of the contact pixels (definitions above), and the receivers.
struct BiasMasks {
    FloatImage facingLight, contact, receivers;
};
/// Throws std::invalid_argument for images of different sizes or channel counts.
[[nodiscard]] BiasMasks biasMasks(const SurfaceGeometry& g, glm::vec3 lightCentre);

/// One frame's counts; the shares are pooled over frames by adding them.
struct BiasArtifactCounts {
    std::size_t acneCandidates = 0, acne = 0;
    std::size_t peterPanningCandidates = 0, peterPanning = 0;
    /// The shares (0 when there is no candidate).
    [[nodiscard]] double acneShare() const;
    [[nodiscard]] double peterPanningShare() const;
    BiasArtifactCounts& operator+=(const BiasArtifactCounts& o);
};

/// The method's acne and peter-panning against `truth` (1-channel visibility images of the same
/// size as the masks); throws std::invalid_argument for different sizes.
[[nodiscard]] BiasArtifactCounts biasArtifacts(const FloatImage& method, const FloatImage& truth,
                                               const BiasMasks& masks);

} // namespace fl
