// Step G1 (thesis §6.3.2): continuous sites into the texture.
#include <geometry/DiscreteVoronoi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fl::geom {

glm::ivec2 TextureMapping::pixelOf(glm::dvec2 world) const {
    const glm::dvec2 t = toTexture(world);
    // floor(v + 0.5) as jfa::pixelOf; the clamp only absorbs rounding at the box's far side.
    // Written so that NaN lands on 0 too (std::clamp passes NaN through, and casting NaN or a
    // value past INT_MAX to int is undefined: that was an out-of-bounds write in snapSites).
    auto snap = [&](double v) {
        const double p = std::floor(v + 0.5);
        if (!(p > 0.0)) return 0;
        return p < double(size - 1) ? static_cast<int>(p) : size - 1;
    };
    return {snap(t.x), snap(t.y)};
}

TextureMapping fitTextureMapping(const std::vector<glm::dvec2>& sites, int size) {
    if (size < 2 || size > kMaxDiscreteSize) {
        throw std::invalid_argument("discrete Delaunay: texture size " + std::to_string(size) +
                                    " must be in [2, " + std::to_string(kMaxDiscreteSize) + "]");
    }
    glm::dvec2 lo(std::numeric_limits<double>::infinity());
    glm::dvec2 hi(-std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const glm::dvec2 p = sites[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            throw std::invalid_argument("discrete Delaunay: site " + std::to_string(i) +
                                        " has a non-finite coordinate");
        }
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    TextureMapping m;
    m.size = size;
    const double span = double(size - 1);
    if (sites.empty()) {
        m.offset = glm::dvec2(span / 2.0);
        return m;
    }
    const glm::dvec2 extent = hi - lo;
    const double longer = std::max(extent.x, extent.y);
    if (!std::isfinite(longer)) {
        throw std::invalid_argument("discrete Delaunay: the sites' bounding box is too large for "
                                    "double arithmetic");
    }
    m.origin = lo;
    // One site (or all equal): any scale maps them to the centre; 1 keeps toWorld finite.
    // Otherwise the longer side is first brought to [1, 2) by an exact power of two, so the
    // scale is in (span / 2, span] whatever the extent: subnormal boxes (1e-309) included,
    // where span / longer overflowed and every site became NaN in texture space.
    m.exponent = longer > 0.0 ? -std::ilogb(longer) : 0;
    const glm::dvec2 unit(std::ldexp(extent.x, m.exponent), std::ldexp(extent.y, m.exponent));
    m.scale = longer > 0.0 ? span / std::max(unit.x, unit.y) : 1.0;
    // The longer side spans [0, N-1] exactly; the shorter one is centred so that the sites keep
    // the same margin to the texture border on both of its sides.
    m.offset = (glm::dvec2(span) - unit * m.scale) * 0.5;
    return m;
}

SnappedSites snapSites(const std::vector<glm::dvec2>& sites, int size) {
    if (sites.size() > kMaxDiscreteSites) {
        throw std::invalid_argument("discrete Delaunay: " + std::to_string(sites.size()) +
                                    " sites, at most " + std::to_string(kMaxDiscreteSites) +
                                    " fit (ids are stored in floats)");
    }
    SnappedSites out;
    out.mapping = fitTextureMapping(sites, size);
    out.pixels.resize(sites.size());
    // Owner per pixel; visiting sites in index order makes the lowest index the keeper.
    std::vector<std::uint32_t> owner(std::size_t(size) * std::size_t(size), kNoSite);
    out.kept.reserve(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const glm::ivec2 p = out.mapping.pixelOf(sites[i]);
        out.pixels[i] = p;
        std::uint32_t& slot = owner[std::size_t(p.y) * std::size_t(size) + std::size_t(p.x)];
        if (slot == kNoSite) {
            slot = static_cast<std::uint32_t>(i);
            out.kept.push_back(slot);
        } else {
            out.missing.push_back({static_cast<std::uint32_t>(i), slot});
        }
    }
    return out;
}

} // namespace fl::geom
