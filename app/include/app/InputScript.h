#pragma once
// `floodlight view --script FILE`: a text list of input events replayed frame by frame, so that
// tests (and benchmarks) drive the window exactly as a user would, deterministically. One event
// per line, '#' starts a comment:
//   key NAME               press and release a key; "key shift+M" holds Shift (names: ViewerInput)
//   hold NAME FRAMES       hold a key while FRAMES frames render (fly movement)
//   drag left|right X0 Y0 X1 Y1 [STEPS]   mouse drag in window pixels, STEPS moves (default 8)
//   click X Y              left click (the playground overlay adds a site there)
//   scroll DY              mouse wheel
//   resize W H             window size; W or H = 0 minimises, a later resize restores
//   screenshot NAME        PNG + EXR of the frame and NAME.window.png of the window; {method},
//                          {overlay} and {provider} in NAME are replaced by the current ones
//   drop PATH              as if PATH (the rest of the line) were dropped on the window
//   wait FRAMES            render FRAMES frames
//   stats [LABEL]          print the frame number, resident memory and the live GL objects
//                          ("stats LABEL: frame F, resident K KiB, GL objects N (...)"): soaks
//   quit                   close the window (also implied at the end of the script)
// Events up to the next hold/wait run before the same frame renders. Numbers are finite and at
// most 1000000 in magnitude; counts (FRAMES, STEPS, W, H) are whole and at most 1000000.

#include <glm/glm.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fl::app {

struct ScriptEvent {
    enum class Kind { Key, Hold, Drag, Click, Scroll, Resize, Screenshot, Drop, Wait, Quit, Stats };
    Kind kind = Kind::Wait;
    int key = 0;                    // Key, Hold: GLFW key
    int mods = 0;                   // Key: GLFW modifier bits
    int frames = 0;                 // Hold, Wait
    bool rightButton = false;       // Drag
    glm::vec2 from{0.0f}, to{0.0f}; // Drag (from, to), Click (from)
    int steps = 8;                  // Drag
    double scroll = 0.0;            // Scroll
    glm::ivec2 size{0};             // Resize
    std::string text;               // Screenshot name, Drop path, Stats label
    int line = 0;                   // source line, for messages
};

/// Parses a script; throws std::runtime_error "SOURCE:LINE: problem" for the first bad line.
std::vector<ScriptEvent> parseInputScript(std::string_view text, const std::string& source);
/// Reads and parses FILE; throws std::runtime_error naming the file if it cannot be read (not a
/// regular file, over kTextInputLimitMiB: base/InputFile.h).
std::vector<ScriptEvent> readInputScript(const std::filesystem::path& file);

/// Hands out a script's events frame by frame.
class ScriptPlayer {
  public:
    explicit ScriptPlayer(std::vector<ScriptEvent> events) : events_(std::move(events)) {}
    /// The events to apply before frame `frame` renders (frames are asked in increasing order).
    /// Hold and Wait events are returned too (the viewer holds the key) and pause the script; a
    /// Screenshot ends the frame's events (it shows the frame drawn next, before what follows).
    std::vector<ScriptEvent> due(int frame);
    /// Keys that an active Hold keeps pressed at `frame`.
    [[nodiscard]] bool held(int key, int frame) const;
    /// True once every event has been handed out and the last hold/wait has elapsed.
    [[nodiscard]] bool finished(int frame) const;

  private:
    std::vector<ScriptEvent> events_;
    std::size_t next_ = 0;
    int resumeFrame_ = 0;
    int heldKey_ = -1, heldUntil_ = 0;
};

} // namespace fl::app
