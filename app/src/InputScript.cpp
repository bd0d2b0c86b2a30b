#include <app/InputScript.h>

#include <app/ViewerInput.h>

#include <base/InputFile.h>
#include <base/Numbers.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fl::app {

namespace {

// Splits a line into words, dropping a '#' comment.
std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line.substr(0, line.find('#')));
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// The largest count a line may give (frames to wait or hold, drag steps, window sizes), and the
// largest magnitude of a position or scroll amount: beyond a float, a click at 2.7e150 became
// an infinite window position (found by fuzz/fuzz_input_script).
constexpr double kMaxCount = 1'000'000;
constexpr double kMaxMagnitude = 1'000'000;

class LineParser {
  public:
    LineParser(const std::string& source, int line, std::vector<std::string> w)
        : source_(source), line_(line), w_(std::move(w)) {}

    [[noreturn]] void fail(const std::string& problem) const {
        throw std::runtime_error(source_ + ":" + std::to_string(line_) + ": " + problem);
    }
    void expectArgs(std::size_t min, std::size_t max, const char* usage) const {
        if (w_.size() - 1 < min || w_.size() - 1 > max)
            fail(std::string("expected '") + usage + "'");
    }
    // Numbers by the rule of the command line (base/Numbers.h): finite, whole for counts.
    double read(std::size_t i, double lo, double hi, bool integer) const {
        if (std::string problem = numberProblem(w_[i], lo, hi, integer); !problem.empty())
            fail(problem);
        double v = 0.0;
        parseNumber(w_[i], v);
        return v;
    }
    double number(std::size_t i) const { return read(i, -kMaxMagnitude, kMaxMagnitude, false); }
    int count(std::size_t i, int min) const {
        return static_cast<int>(read(i, min, kMaxCount, true));
    }
    int key(std::size_t i, int* mods) const {
        std::string name = w_[i];
        if (mods && name.size() > 6 &&
            (name.rfind("shift+", 0) == 0 || name.rfind("Shift+", 0) == 0)) {
            *mods = GLFW_MOD_SHIFT;
            name = name.substr(6);
        }
        const auto k = parseKeyName(name);
        if (!k) fail("unknown key '" + w_[i] + "'");
        return *k;
    }
    const std::vector<std::string>& w() const { return w_; }

  private:
    const std::string& source_;
    int line_;
    std::vector<std::string> w_;
};

ScriptEvent parseEvent(const LineParser& p) {
    using K = ScriptEvent::Kind;
    const std::vector<std::string>& w = p.w();
    ScriptEvent e;
    const std::string& verb = w[0];
    if (verb == "key") {
        p.expectArgs(1, 1, "key NAME");
        e.kind = K::Key;
        e.key = p.key(1, &e.mods);
    } else if (verb == "hold") {
        p.expectArgs(2, 2, "hold NAME FRAMES");
        e.kind = K::Hold;
        e.key = p.key(1, nullptr);
        e.frames = p.count(2, 1);
    } else if (verb == "drag") {
        p.expectArgs(5, 6, "drag left|right X0 Y0 X1 Y1 [STEPS]");
        e.kind = K::Drag;
        if (w[1] != "left" && w[1] != "right") p.fail("drag button must be left or right");
        e.rightButton = w[1] == "right";
        e.from = {p.number(2), p.number(3)};
        e.to = {p.number(4), p.number(5)};
        if (w.size() == 7) e.steps = p.count(6, 1);
    } else if (verb == "click") {
        p.expectArgs(2, 2, "click X Y");
        e.kind = K::Click;
        e.from = {p.number(1), p.number(2)};
    } else if (verb == "scroll") {
        p.expectArgs(1, 1, "scroll DY");
        e.kind = K::Scroll;
        e.scroll = p.number(1);
    } else if (verb == "resize") {
        p.expectArgs(2, 2, "resize W H");
        e.kind = K::Resize;
        e.size = {p.count(1, 0), p.count(2, 0)};
    } else if (verb == "screenshot") {
        p.expectArgs(1, 1, "screenshot NAME");
        e.kind = K::Screenshot;
        e.text = w[1];
        if (e.text.find_first_of("/\\") != std::string::npos)
            p.fail("screenshot names are file stems, without folders");
    } else if (verb == "drop") {
        p.expectArgs(1, w.size(), "drop PATH");
        e.kind = K::Drop;
        e.text = w[1]; // the rest of the line, so that a path may contain spaces
        for (std::size_t i = 2; i < w.size(); ++i) e.text += " " + w[i];
    } else if (verb == "wait") {
        p.expectArgs(1, 1, "wait FRAMES");
        e.kind = K::Wait;
        e.frames = p.count(1, 1);
    } else if (verb == "stats") {
        p.expectArgs(0, 1, "stats [LABEL]");
        e.kind = K::Stats;
        if (w.size() == 2) e.text = w[1];
    } else if (verb == "quit") {
        p.expectArgs(0, 0, "quit");
        e.kind = K::Quit;
    } else {
        p.fail("unknown event '" + verb +
               "' (key, hold, drag, click, scroll, resize, screenshot, drop, wait, stats, quit)");
    }
    return e;
}

} // namespace

std::vector<ScriptEvent> parseInputScript(std::string_view text, const std::string& source) {
    std::vector<ScriptEvent> events;
    std::istringstream in{std::string(text)};
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        std::vector<std::string> w = words(line);
        if (w.empty()) continue;
        ScriptEvent e = parseEvent(LineParser(source, lineNo, std::move(w)));
        e.line = lineNo;
        events.push_back(std::move(e));
    }
    return events;
}

std::vector<ScriptEvent> readInputScript(const std::filesystem::path& file) {
    // Regular files within the text limit only (InputFileError is a runtime_error).
    return parseInputScript(readInputFile(file, "--script", kTextInputLimitMiB), file.string());
}

std::vector<ScriptEvent> ScriptPlayer::due(int frame) {
    std::vector<ScriptEvent> out;
    if (frame < resumeFrame_) return out;
    while (next_ < events_.size()) {
        const ScriptEvent& e = events_[next_++];
        out.push_back(e);
        // A screenshot is of the frame drawn next: what follows it waits for that frame, so that
        // "screenshot a.png" then "key M" shows the method before M.
        if (e.kind == ScriptEvent::Kind::Screenshot) break;
        if (e.kind == ScriptEvent::Kind::Hold || e.kind == ScriptEvent::Kind::Wait) {
            resumeFrame_ = frame + e.frames;
            if (e.kind == ScriptEvent::Kind::Hold) {
                heldKey_ = e.key;
                heldUntil_ = resumeFrame_;
            }
            break;
        }
    }
    return out;
}

bool ScriptPlayer::held(int key, int frame) const {
    return key == heldKey_ && frame < heldUntil_;
}

bool ScriptPlayer::finished(int frame) const {
    return next_ == events_.size() && frame >= resumeFrame_;
}

} // namespace fl::app
