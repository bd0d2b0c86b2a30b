#include <gpu/LiveObjects.h>

#include <algorithm>
#include <atomic>
#include <numeric>

namespace fl::gl {

namespace {

// The highest name each kind has issued. A driver may reuse freed names or not (Mesa hands out
// the next unused number), so the range to ask is bounded by what was issued, not by a guess.
std::array<std::atomic<GLuint>, kObjectKinds.size()> g_highest{};

} // namespace

int ObjectCounts::total() const {
    return std::accumulate(live.begin(), live.end(), 0);
}

std::string ObjectCounts::text() const {
    std::string s;
    for (std::size_t k = 0; k < live.size(); ++k) {
        if (live[k] == 0) continue;
        if (!s.empty()) s += ", ";
        s += std::string(kObjectKinds[k].name) + " " + std::to_string(live[k]);
    }
    return s.empty() ? "none" : s;
}

ObjectCounts countLiveObjects() {
    ObjectCounts c;
    for (std::size_t k = 0; k < kObjectKinds.size(); ++k) {
        const GLuint highest = g_highest[k].load();
        for (GLuint name = 1; name <= highest; ++name)
            c.live[k] += kObjectKinds[k].isLive(name) ? 1 : 0;
    }
    return c;
}

void noteCreated(ObjectKind kind, GLuint name) {
    std::atomic<GLuint>& h = g_highest[static_cast<std::size_t>(kind)];
    for (GLuint now = h.load(); name > now && !h.compare_exchange_weak(now, name);) {
    }
}

} // namespace fl::gl
