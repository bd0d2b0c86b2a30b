#include <renderer/metrics/BiasArtifacts.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace fl {

namespace {

glm::vec3 texelVec3(const FloatImage& image, std::size_t i) {
    const std::size_t c = static_cast<std::size_t>(image.channels) * i;
    return {image.data[c], image.data[c + 1], image.data[c + 2]};
}

bool isSurface(const FloatImage& positions, std::size_t i) {
    return positions.data[static_cast<std::size_t>(positions.channels) * i + 3] != 0.0f;
}

void checkGeometry(const SurfaceGeometry& g) {
    const auto same = [&](const FloatImage& image, int channels) {
        return image.width == g.positions.width && image.height == g.positions.height &&
               image.channels == channels;
    };
    if (!same(g.positions, 4) || !same(g.planes, 4) || !same(g.receivers, 1))
        throw std::invalid_argument("biasMasks: positions and planes (4 channels) and receivers "
                                    "(1 channel) of one size needed");
}

// Whether receiver i touches another surface among its 8 neighbours (BiasArtifacts.h).
bool touches(const SurfaceGeometry& g, int x, int y) {
    const int w = g.positions.width, h = g.positions.height;
    const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x;
    const glm::vec3 p = texelVec3(g.positions, i), n = texelVec3(g.planes, i);
    const float footprint = glm::length(p - g.eye) * g.pixelAngle;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if ((dx == 0 && dy == 0) || qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
            const std::size_t j = static_cast<std::size_t>(qy) * static_cast<std::size_t>(w) + qx;
            if (!isSurface(g.positions, j)) continue;
            const glm::vec3 d = texelVec3(g.positions, j) - p;
            if (glm::dot(d, n) > 0.5f * footprint && glm::length(d) <= 3.0f * footprint)
                return true;
        }
    return false;
}

} // namespace

BiasMasks biasMasks(const SurfaceGeometry& g, glm::vec3 lightCentre) {
    checkGeometry(g);
    const int w = g.positions.width, h = g.positions.height;
    const std::size_t n = g.receivers.data.size();
    BiasMasks m{{w, h, 1, std::vector<float>(n, 0.0f)},
                {w, h, 1, std::vector<float>(n, 0.0f)},
                g.receivers};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x;
            if (!(g.receivers.data[i] > 0.5f) || !isSurface(g.positions, i)) continue;
            const glm::vec3 p = texelVec3(g.positions, i);
            m.facingLight.data[i] = glm::dot(texelVec3(g.planes, i), lightCentre - p) > 0.0f;
            m.contact.data[i] = touches(g, x, y) ? 1.0f : 0.0f;
        }
    return m;
}

double BiasArtifactCounts::acneShare() const {
    return acneCandidates ? static_cast<double>(acne) / static_cast<double>(acneCandidates) : 0.0;
}

double BiasArtifactCounts::peterPanningShare() const {
    return peterPanningCandidates
               ? static_cast<double>(peterPanning) / static_cast<double>(peterPanningCandidates)
               : 0.0;
}

BiasArtifactCounts& BiasArtifactCounts::operator+=(const BiasArtifactCounts& o) {
    acneCandidates += o.acneCandidates;
    acne += o.acne;
    peterPanningCandidates += o.peterPanningCandidates;
    peterPanning += o.peterPanning;
    return *this;
}

BiasArtifactCounts biasArtifacts(const FloatImage& method, const FloatImage& truth,
                                 const BiasMasks& masks) {
    const FloatImage& contact = masks.contact;
    const int w = contact.width, h = contact.height;
    for (const FloatImage* image : {&method, &truth, &masks.facingLight, &masks.receivers})
        if (image->width != w || image->height != h || image->channels != 1)
            throw std::invalid_argument("biasArtifacts: 1-channel images of one size needed");
    // Distance to the nearest contact pixel, Chebyshev, capped at the reach: a box filter's
    // dilation of the contact mask by kContactReach in x, then in y.
    std::vector<std::uint8_t> nearX(contact.data.size(), 0), near(contact.data.size(), 0);
    const auto index = [w](int x, int y) {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int d = -kContactReach; d <= kContactReach && !nearX[index(x, y)]; ++d)
                if (x + d >= 0 && x + d < w && contact.data[index(x + d, y)] > 0.5f)
                    nearX[index(x, y)] = 1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int d = -kContactReach; d <= kContactReach && !near[index(x, y)]; ++d)
                if (y + d >= 0 && y + d < h && nearX[index(x, y + d)]) near[index(x, y)] = 1;
    BiasArtifactCounts c;
    for (std::size_t i = 0; i < truth.data.size(); ++i) {
        const float t = truth.data[i], m = method.data[i];
        if (masks.facingLight.data[i] > 0.5f && t >= kAcneLitAtLeast) {
            ++c.acneCandidates;
            c.acne += t - m > kBiasArtifactChange;
        }
        if (near[i] && masks.receivers.data[i] > 0.5f && t <= kPeterPanningUmbraAtMost) {
            ++c.peterPanningCandidates;
            c.peterPanning += m - t > kBiasArtifactChange;
        }
    }
    return c;
}

} // namespace fl
