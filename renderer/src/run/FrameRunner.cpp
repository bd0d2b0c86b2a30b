#include <renderer/passes/Phases.h>
#include <renderer/run/FrameRunner.h>

#include <base/Stats.h>
#include <io/ImageIO.h>
#include <renderer/metrics/BiasArtifacts.h>
#include <renderer/soft/ShadowRayInputs.h>
#include <scene/Pose.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <unistd.h>

namespace fl {

std::optional<std::string> referenceOf(const std::string& method) {
    const MethodDescriptor* m = findMethod(method);
    if (!m || m->reference.empty()) return std::nullopt;
    return std::string(m->reference);
}

std::optional<FloodSample> floodSample(const Renderer& renderer) {
    const FloodFrame* f = renderer.flood();
    if (!f) return std::nullopt;
    // The shares read 4 bytes back each: the frame is already finished and timed here.
    return FloodSample{f->passes, f->kernel ? f->kernel->activeShare() : 1.0,
                       f->kernel ? f->kernel->computedShare() : 1.0};
}

std::vector<std::pair<std::string, std::int64_t>> writtenBytes(const Renderer& renderer) {
    std::vector<std::pair<std::string, std::int64_t>> out;
    const auto add = [&out](const std::string& name, std::int64_t bytes) {
        for (auto& [n, b] : out)
            if (n == name) {
                b += bytes;
                return;
            }
        out.emplace_back(name, bytes);
    };
    for (const gl::PassTime& p : renderer.timer().passes()) add(p.name, p.bytes);
    if (const FloodFrame* f = renderer.flood(); f && f->flooded) {
        const double share = f->kernel ? f->kernel->computedShare() : 1.0;
        add(phase::kFlood, std::llround(f->passes * share * double(gl::textureBytes(*f->flooded))));
    }
    return out;
}

void PhaseTimes::record(const gl::PassTimer& timer, std::optional<FloodSample> flood) {
    Phases phases;
    for (const gl::PassTime& p : timer.passes()) phases.emplace_back(p.name, p.ms);
    append(timer.frameMs(), std::move(phases), flood);
}

void PhaseTimes::append(double frameMs, Phases phases, std::optional<FloodSample> flood) {
    phases_.push_back(std::move(phases));
    frameMs_.push_back(frameMs);
    flood_.push_back(flood);
}

std::optional<FloodSample> PhaseTimes::medianFlood() const {
    std::vector<double> passes, share, computed;
    for (const std::optional<FloodSample>& f : flood_)
        if (f) {
            passes.push_back(f->passes);
            share.push_back(f->activeShare);
            computed.push_back(f->computedShare);
        }
    if (passes.empty()) return std::nullopt;
    return FloodSample{static_cast<int>(std::lround(fl::median(std::move(passes)))),
                       fl::median(std::move(share)), fl::median(std::move(computed))};
}

double PhaseTimes::phaseMs(std::size_t i, const std::string& name) const {
    double ms = 0.0;
    for (const auto& [n, v] : phases_.at(i))
        if (n == name) ms += v;
    return ms;
}

bool PhaseTimes::ran(const std::string& name) const {
    for (const Phases& frame : phases_)
        for (const auto& p : frame)
            if (p.first == name) return true;
    return false;
}

double PhaseTimes::medianFrameMs() const {
    return fl::median(frameMs_);
}

std::vector<double> PhaseTimes::phaseSeries(const std::string& name) const {
    std::vector<double> v;
    for (std::size_t i = 0; i < frames(); ++i) v.push_back(phaseMs(i, name));
    return v;
}

double PhaseTimes::medianPhaseMs(const std::string& name) const {
    return fl::median(phaseSeries(name));
}

std::vector<std::string> phaseNames(const std::vector<const PhaseTimes*>& times) {
    std::vector<std::string> names;
    for (const PhaseTimes* t : times)
        for (std::size_t i = 0; i < t->frames(); ++i)
            for (const auto& p : t->phases(i))
                if (std::find(names.begin(), names.end(), p.first) == names.end())
                    names.push_back(p.first);
    return names;
}

namespace {

// Lane's frame i as read back, once every visibility in it is known to be finite.
FrameImages checked(FrameImages frame, const Lane& lane, int i) {
    requireFinite(frame.visibility, lane.label + " visibility, frame " + std::to_string(i));
    return frame;
}

// Moves the acne and peter-panning masks of `from` into `to` (the frame they were made with).
void moveBiasMasks(FrameImages& from, FrameImages& to) {
    to.facingLight = std::move(from.facingLight);
    to.contact = std::move(from.contact);
}

} // namespace

FrameRunner::FrameRunner(int totalFrames, int done)
    : total_(totalFrames), done_(done), doneBefore_(done), tty_(::isatty(STDOUT_FILENO) != 0) {}

FramePlan::Clip FramePlan::Clip::of(const Scene& scene, const std::string& animation, double start,
                                    double fps) {
    return {chooseAnimations(scene, animation), start, fps > 0.0 ? 1.0 / fps : 0.0};
}

void FrameRunner::run(const FramePlan& plan, std::vector<Lane>& lanes, const OnFrame& onFrame) {
    const Scene& scene = *plan.scene;
    const float aspect = static_cast<float>(plan.width) / static_cast<float>(plan.height);
    std::vector<FrameImages> images(lanes.size());
    const bool behind = plan.readBack && plan.readBehind;
    std::vector<FrameReadBack> reads(behind ? lanes.size() : 0);
    int pending = -1;                // the frame whose read-back is in flight (behind only)
    FrameImages masks, pendingMasks; // the motion lane's bias masks: this frame's, pending's
    const int end = plan.last < 0 ? plan.frames : std::min(plan.last + 1, plan.frames);
    if (plan.clip)
        for (Lane& lane : lanes)
            if (lane.renderer->animations() != plan.clip->animations)
                lane.renderer->setAnimations(plan.clip->animations);
    for (int k = plan.first - plan.warmup; k < end; ++k) {
        const int i = std::max(k, plan.first);
        if (!plan.lightKeys.empty()) {
            Light light = sceneLight(scene);
            light.position = lightPositionAt(plan.lightKeys, i, plan.frames);
            // A spot keeps its own direction; other lights aim at the scene as they move.
            if (light.type != Light::Type::Spot)
                light.direction = glm::normalize(scene.bounds.center() - light.position);
            for (Lane& lane : lanes) lane.renderer->setLight(light);
        }
        const auto* path = std::get_if<CameraPath>(&plan.camera);
        const CameraView cam = path ? path->frame(i, plan.frames, scene.bounds, aspect)
                                    : std::get<CameraView>(plan.camera);
        // The frame before's camera, for the motion target (flicker on the same surface point).
        const CameraView previous =
            path && i > 0 ? path->frame(i - 1, plan.frames, scene.bounds, aspect) : cam;
        for (std::size_t l = 0; l < lanes.size(); ++l) {
            Renderer& r = *lanes[l].renderer;
            if (plan.clip) r.setTime(plan.clip->timeOf(i), plan.clip->timeOf(std::max(i - 1, 0)));
            const Clock::time_point renderStart = Clock::now();
            if (static_cast<int>(l) == plan.motionLane)
                r.render(cam, previous);
            else
                r.render(cam);
            const Clock::time_point rendered = Clock::now();
            seconds_.render += std::chrono::duration<double>(rendered - renderStart).count();
            if (k < plan.first) continue;
            const bool withMasks = plan.biasMasks && static_cast<int>(l) == plan.motionLane;
            if (withMasks) {
                BiasMasks m = biasMasks(surfaceGeometry(r.surfaces(), cam), r.disk().center);
                masks.facingLight = std::move(m.facingLight);
                masks.contact = std::move(m.contact);
            }
            if (behind) {
                // This lane's copy of the frame before finished while this frame rendered.
                if (pending >= 0) images[l] = checked(reads[l].finish(), lanes[l], pending);
                if (withMasks && pending >= 0) moveBiasMasks(pendingMasks, images[l]);
                if (withMasks) moveBiasMasks(masks, pendingMasks);
                reads[l].start(r);
            } else if (plan.readBack) {
                images[l] = checked(readFrame(r), lanes[l], i);
                if (withMasks) moveBiasMasks(masks, images[l]);
            }
            lanes[l].times.record(r.timer(), floodSample(r));
            seconds_.readBack += std::chrono::duration<double>(Clock::now() - rendered).count();
        }
        if (k < plan.first) continue;
        if (!behind) {
            handOver(i, images, onFrame);
            continue;
        }
        if (pending >= 0) handOver(pending, images, onFrame);
        pending = i;
    }
    if (pending >= 0) {
        finishReadBack(reads, lanes, pending, images);
        if (plan.biasMasks && plan.motionLane >= 0)
            moveBiasMasks(pendingMasks, images[static_cast<std::size_t>(plan.motionLane)]);
        handOver(pending, images, onFrame);
    }
}

void FrameRunner::finishReadBack(std::vector<FrameReadBack>& reads, std::vector<Lane>& lanes, int i,
                                 std::vector<FrameImages>& images) {
    const Clock::time_point start = Clock::now();
    for (std::size_t l = 0; l < lanes.size(); ++l)
        images[l] = checked(reads[l].finish(), lanes[l], i);
    seconds_.readBack += std::chrono::duration<double>(Clock::now() - start).count();
}

void FrameRunner::handOver(int i, std::vector<FrameImages>& images, const OnFrame& onFrame) {
    if (onFrame) onFrame(i, images);
    ++done_;
    showProgress();
}

void FrameRunner::showProgress() {
    if (!tty_) return;
    const double s = std::chrono::duration<double>(Clock::now() - start_).count();
    const int width = 30, filled = total_ > 0 ? width * done_ / total_ : width;
    const int now = done_ - doneBefore_; // this run's frames give the rate
    const double eta = now > 0 ? s / now * (total_ - done_) : 0.0;
    std::cout << "\r[" << std::string(static_cast<size_t>(filled), '#')
              << std::string(static_cast<size_t>(width - filled), '.') << "] " << done_ << "/"
              << total_ << " frames, " << std::fixed << std::setprecision(0) << s << " s, ETA "
              << eta << " s " << std::defaultfloat << std::flush;
}

void FrameRunner::finish() {
    if (tty_) std::cout << "\n";
}

CsvTable::CsvTable(const std::vector<std::string>& columns) {
    for (const std::string& c : columns) *this << c;
    endRow();
}

CsvTable& CsvTable::blank() {
    separate();
    return *this;
}

void CsvTable::endRow() {
    out_ << "\n";
    rowStarted_ = false;
}

void CsvTable::separate() {
    if (rowStarted_) out_ << ",";
    rowStarted_ = true;
}

std::string csvName(std::string text) {
    std::replace(text.begin(), text.end(), ' ', '_');
    std::replace(text.begin(), text.end(), ',', ';');
    return text;
}

void writeCsv(const std::filesystem::path& path, const CsvTable& table) {
    writeTextFile(path, table.text());
}

void writeJson(const std::filesystem::path& path, const nlohmann::json& j) {
    writeTextFile(path, j.dump(2) + "\n");
}

} // namespace fl
