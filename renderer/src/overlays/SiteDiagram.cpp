#include <renderer/overlays/SiteDiagram.h>

#include <jfa/NearestSite.h>
#include <jfa/Reference.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fl::overlay {

namespace {
constexpr std::array<std::string_view, 6> kSpecs{"jfa",  "jfa+1", "jfa+2",
                                                 "jfa2", "1+jfa", "half:jfa"};
} // namespace

std::span<const std::string_view> variantSpecs() {
    return kSpecs;
}

jfa::Plan variantPlan(int index, int width, int height) {
    const int n = int(kSpecs.size());
    return jfa::parsePlan(kSpecs[std::size_t(((index % n) + n) % n)], width, height);
}

jfa::Plan truncatePlan(const jfa::Plan& plan, int passes) {
    if (plan.stages().size() != 1)
        throw std::invalid_argument("flood pass by pass: plan \"" + plan.name() + "\" has " +
                                    std::to_string(plan.stages().size()) +
                                    " stages; only one-stage plans can be cut");
    jfa::Stage stage = plan.stages().front();
    if (passes < 0 || passes >= int(stage.steps.size())) return plan;
    stage.steps.resize(std::size_t(passes));
    if (stage.steps.empty()) stage.untilUnchanged = false; // an empty run is a plain stage
    return jfa::Plan(plan.name() + " (first " + std::to_string(passes) + " passes)", {stage});
}

jfa::Grid sitesFromSeeds(const jfa::Grid& seeds) {
    jfa::Grid out(seeds.width, seeds.height, jfa::Cell{0.0f, 0.0f, -1.0f, 0.0f});
    for (int y = 0; y < seeds.height; ++y)
        for (int x = 0; x < seeds.width; ++x)
            if (seeds.at(x, y).w != 0.0f)
                out.at(x, y) = {float(x), float(y), float(y * seeds.width + x), 0.0f};
    return out;
}

SiteDiagram floodSites(jfa::GlFloodKernel<jfa::NearestSite>& kernel, const jfa::Plan& plan,
                       const jfa::Grid& sites) {
    const jfa::NearestSite criterion{true};
    SiteDiagram d;
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    const auto t0 = Clock::now();
    const gl::Texture in = jfa::uploadGrid(sites);
    d.flooded = jfa::readGrid(kernel.run(plan, in, criterion));
    const auto t1 = Clock::now();
    const jfa::ExactField exact = jfa::exactNearest(sites, criterion);
    d.errors = jfa::errorMask(d.flooded, exact, criterion);
    d.errorCount = std::count(d.errors.begin(), d.errors.end(), std::uint8_t(1));
    d.sites = std::int64_t(jfa::siteCells(sites).size());
    double maxSq = 0.0;
    for (const double v : exact.distSq)
        if (std::isfinite(v)) maxSq = std::max(maxSq, v);
    d.maxDistance = float(std::sqrt(maxSq));
    d.floodMs = ms(t0, t1);
    d.exactMs = ms(t1, Clock::now());
    return d;
}

} // namespace fl::overlay
