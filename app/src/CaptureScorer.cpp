#include <app/CaptureScorer.h>

#include <renderer/metrics/ShadowStats.h>
#include <renderer/metrics/SoftStats.h>

namespace fl::app {

namespace {

// The standard-flooding run a JFA run's |dI| buckets are measured against: the script's run of
// referenceOf(its method) at the same size and pass count; -1 if the script has none.
int counterpartOf(const std::vector<MethodRun>& runs, std::size_t k, int defaultPasses) {
    const MethodSpec& m = runs[k].spec;
    const std::optional<std::string> want = referenceOf(m.method);
    if (!want) return -1;
    const auto passes = [&](const MethodSpec& spec) {
        const MethodOption& o = floodPassesOption();
        return spec.options.has(o.flag) ? spec.options.integer(o) : defaultPasses;
    };
    for (std::size_t c = 0; c < runs.size(); ++c)
        if (runs[c].spec.method == *want && runs[c].width == runs[k].width &&
            runs[c].height == runs[k].height && passes(runs[c].spec) == passes(m))
            return static_cast<int>(c);
    return -1;
}

} // namespace

FrameScorer::FrameScorer(std::vector<MethodRun>& runs, std::size_t first, int jfaPasses)
    : runs_(runs), first_(first) {
    state_.previous.resize(runs.size() - first);
    for (std::size_t k = first; k < runs.size(); ++k) {
        const int c = counterpartOf(runs, k, jfaPasses);
        counterpart_.push_back(c);
        if (c >= 0) runs[k].counterpart = runs[static_cast<std::size_t>(c)].label;
    }
}

void FrameScorer::score(int i, std::vector<FloatImage>& visibility, const FrameImages& ref) {
    // Flicker compares with the previous frame: on the same surface points (reprojected with
    // the reference's motion; every method sees the same surfaces), and, as before, on the
    // same pixels where both frames have receivers.
    const FloatImage flickerReceivers =
        i > 0 ? bothReceivers(state_.previousReceivers, ref.receivers) : FloatImage{};
    std::optional<Reprojection> reprojection;
    if (i > 0)
        reprojection.emplace(ref.motion, state_.previousDepth, ref.receivers,
                             state_.previousReceivers);
    for (std::size_t k = 0; k < visibility.size(); ++k) {
        MethodRun& run = runs_[first_ + k];
        FrameRow row;
        row.frame = i;
        // Every method sees the same surfaces: the reference's receivers are theirs.
        row.metrics = compareWithReference(visibility[k], ref.visibility, ref.receivers);
        if (!ref.facingLight.data.empty())
            row.bias = biasArtifacts(visibility[k], ref.visibility,
                                     {ref.facingLight, ref.contact, ref.receivers});
        if (reprojection) {
            row.flicker = addedSurfaceFlicker(*reprojection, state_.previous[k], visibility[k],
                                              state_.previousReference, ref.visibility);
            row.screenFlicker =
                addedFlicker(state_.previous[k], visibility[k], state_.previousReference,
                             ref.visibility, flickerReceivers);
        }
        if (isWorse(run, row)) run.worst = {visibility[k], ref.visibility, ref.receivers};
        run.rows.push_back(std::move(row));
    }
    for (std::size_t k = 0; k < visibility.size(); ++k) {
        if (counterpart_[k] >= 0)
            runs_[first_ + k].rows.back().deltaBuckets =
                compareSoftShadows(visibility[k],
                                   visibility[static_cast<std::size_t>(counterpart_[k]) - first_])
                    .deltaBuckets;
        state_.previous[k] = std::move(visibility[k]);
    }
    state_.previousReference = ref.visibility;
    state_.previousReceivers = ref.receivers;
    state_.previousDepth = depthOf(ref.motion);
}

void FrameScorer::replay(const std::vector<const FrameRecord*>& done, bool more,
                         CaptureProgress& progress) {
    // Each run's worst pictures are in the state saved with its worst frame.
    std::vector<std::pair<std::size_t, std::pair<int, int>>> worst;
    const int size = done.empty() ? 0 : done.front()->size;
    for (std::size_t k = 0; k + first_ < runs_.size(); ++k) {
        MethodRun& run = runs_[first_ + k];
        for (const FrameRecord* r : done) {
            isWorse(run, r->runs.at(k).row);
            run.rows.push_back(r->runs.at(k).row);
        }
        if (run.worstFrame >= 0) {
            run.worst = progress.loadWorst(size, k, run.worstFrame);
            worst.push_back({first_ + k, {size, run.worstFrame}});
        }
    }
    std::optional<std::pair<int, int>> last; // (resolution, frame) of the state kept
    if (!done.empty() && more) {
        last = {done.back()->size, done.back()->frame};
        state_ = progress.loadState(last->first, last->second, state_.previous.size());
    }
    progress.adopt(last, worst);
}

// Whether `row` is the run's worst frame so far; if so, it becomes the run's worst.
bool FrameScorer::isWorse(MethodRun& run, const FrameRow& row) {
    if (row.metrics.rmse <= run.worstRmse) return false;
    run.worstRmse = row.metrics.rmse;
    run.worstFrame = row.frame;
    return true;
}

} // namespace fl::app
