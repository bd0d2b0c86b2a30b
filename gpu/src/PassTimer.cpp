#include <gpu/PassTimer.h>

#include <stdexcept>

namespace fl::gl {

namespace {
double msSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

PassTimer::PassTimer(TimingMode mode) : mode_(mode) {
    if (mode_ == TimingMode::Auto)
        mode_ = isSoftwareRenderer() ? TimingMode::Finish : TimingMode::Query;
}

const char* PassTimer::modeName() const {
    return mode_ == TimingMode::Query ? "GL timer queries" : "glFinish wall time";
}

void PassTimer::beginFrame() {
    results_.clear();
    glFinish(); // so the frame total does not include work queued before it
    frameStart_ = Clock::now();
}

void PassTimer::begin(const char* name) {
    results_.push_back({name, 0.0, 0});
    open_ = true;
    if (mode_ == TimingMode::Query) {
        if (queries_.size() < results_.size()) queries_.push_back(Query::create(GL_TIME_ELAPSED));
        glBeginQuery(GL_TIME_ELAPSED, queries_[results_.size() - 1].id());
    } else {
        glFinish();
        passStart_ = Clock::now();
    }
}

void PassTimer::end() {
    open_ = false;
    if (mode_ == TimingMode::Query) {
        glEndQuery(GL_TIME_ELAPSED);
    } else {
        glFinish();
        results_.back().ms = msSince(passStart_);
    }
}

void PassTimer::wrote(std::int64_t bytes) {
    if (!open_) throw std::logic_error("PassTimer::wrote outside a pass");
    results_.back().bytes += bytes;
}

std::int64_t PassTimer::frameBytes() const {
    std::int64_t sum = 0;
    for (const PassTime& p : results_) sum += p.bytes;
    return sum;
}

void PassTimer::endFrame() {
    glFinish();
    frameMs_ = msSince(frameStart_);
    if (mode_ != TimingMode::Query) return;
    for (size_t i = 0; i < results_.size(); ++i) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(queries_[i].id(), GL_QUERY_RESULT, &ns);
        results_[i].ms = static_cast<double>(ns) * 1e-6;
    }
}

} // namespace fl::gl
