#include <app/ViewerInput.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>

namespace fl::app {

namespace {

// clang-format off
constexpr KeyBinding kBindings[] = {
    {GLFW_KEY_H, false, Action::ToggleHelp, "H", "show / hide this help"},
    {GLFW_KEY_F1, false, Action::ToggleHud, "F1", "show / hide the whole HUD"},
    {GLFW_KEY_M, false, Action::NextMethod, "M / Shift+M", "next / previous shadow method"},
    {GLFW_KEY_M, true, Action::PrevMethod, "M / Shift+M", "next / previous shadow method"},
    {GLFW_KEY_T, false, Action::ToggleProvider, "T", "shadow map: uniform <-> TSM"},
    {GLFW_KEY_LEFT_BRACKET, false, Action::ShadowMapSmaller, "[ / ]", "shadow map size / 2, x 2 (256..4096)"},
    {GLFW_KEY_RIGHT_BRACKET, false, Action::ShadowMapLarger, "[ / ]", "shadow map size / 2, x 2 (256..4096)"},
    {GLFW_KEY_MINUS, false, Action::FewerPasses, "- / =", "fewer / more JFA passes (reach 2^n - 1 texels)"},
    {GLFW_KEY_EQUAL, false, Action::MorePasses, "- / =", "fewer / more JFA passes (reach 2^n - 1 texels)"},
    {GLFW_KEY_B, false, Action::NextFloodRegion, "B", "flooding: view -> band -> full (--flood-region; the same picture)"},
    {GLFW_KEY_G, false, Action::Stats, "G", "compare with standard flooding now (jfa-l, jfa-e; also every 30+ frames)"},
    {GLFW_KEY_O, false, Action::NextOverlay, "O / Shift+O", "next / previous overlay"},
    {GLFW_KEY_O, true, Action::PrevOverlay, "O / Shift+O", "next / previous overlay"},
    {GLFW_KEY_V, false, Action::NextVariant, "V", "overlays: next JFA variant (JFA, 1+JFA, JFA+1, ...)"},
    {GLFW_KEY_COMMA, false, Action::StepBack, ", / .", "overlays: previous / next flood pass or Delaunay step"},
    {GLFW_KEY_PERIOD, false, Action::StepForward, ", / .", "overlays: previous / next flood pass or Delaunay step"},
    {GLFW_KEY_N, false, Action::NewPoints, "N", "overlays: new random points (playground, Delaunay)"},
    {-1, false, Action::None, "click", "playground overlay: add a site"},
    {GLFW_KEY_TAB, false, Action::ToggleCameraMode, "Tab", "camera: orbit <-> fly"},
    {-1, false, Action::None, "left drag", "orbit (fly: look around)"},
    {-1, false, Action::None, "right drag", "pan"},
    {-1, false, Action::None, "wheel", "zoom (fly: movement speed)"},
    {GLFW_KEY_W, false, Action::None, "W A S D Q E", "fly: forward, left, back, right, down, up"},
    {GLFW_KEY_LEFT_SHIFT, false, Action::None, "Shift (held)", "fly: 4x faster"},
    {GLFW_KEY_R, false, Action::ResetView, "R", "reset the view"},
    {GLFW_KEY_C, false, Action::NextCamera, "C", "camera: auto frame -> the file's cameras -> auto"},
    {GLFW_KEY_LEFT, false, Action::LightLeft, "arrows", "move the light around the scene centre"},
    {GLFW_KEY_RIGHT, false, Action::LightRight, "arrows", "move the light around the scene centre"},
    {GLFW_KEY_UP, false, Action::LightUp, "arrows", "move the light around the scene centre"},
    {GLFW_KEY_DOWN, false, Action::LightDown, "arrows", "move the light around the scene centre"},
    {GLFW_KEY_Z, false, Action::LightSmaller, "Z / X", "light radius smaller / larger"},
    {GLFW_KEY_X, false, Action::LightLarger, "Z / X", "light radius smaller / larger"},
    {GLFW_KEY_SPACE, false, Action::PlayPause, "Space", "animation: play / pause"},
    {GLFW_KEY_J, false, Action::AnimationBack, "J / K", "animation: one frame (1/30 s) back / forward"},
    {GLFW_KEY_K, false, Action::AnimationForward, "J / K", "animation: one frame (1/30 s) back / forward"},
    {GLFW_KEY_9, false, Action::AnimationSlower, "9 / 0", "animation: half / double speed"},
    {GLFW_KEY_0, false, Action::AnimationFaster, "9 / 0", "animation: half / double speed"},
    {GLFW_KEY_P, false, Action::Screenshot, "P / F12", "screenshot: PNG + EXR into captures/"},
    {GLFW_KEY_F12, false, Action::Screenshot, "P / F12", "screenshot: PNG + EXR into captures/"},
    {-1, false, Action::None, "drop file", "open a .gltf / .glb scene"},
    {GLFW_KEY_ESCAPE, false, Action::Quit, "Esc", "quit"},
};
// clang-format on

struct NamedKey {
    std::string_view name;
    int key;
};
constexpr NamedKey kNamedKeys[] = {
    {"ESC", GLFW_KEY_ESCAPE},     {"TAB", GLFW_KEY_TAB},         {"SPACE", GLFW_KEY_SPACE},
    {"ENTER", GLFW_KEY_ENTER},    {"LEFT", GLFW_KEY_LEFT},       {"RIGHT", GLFW_KEY_RIGHT},
    {"UP", GLFW_KEY_UP},          {"DOWN", GLFW_KEY_DOWN},       {"LSHIFT", GLFW_KEY_LEFT_SHIFT},
    {"[", GLFW_KEY_LEFT_BRACKET}, {"]", GLFW_KEY_RIGHT_BRACKET}, {"-", GLFW_KEY_MINUS},
    {"=", GLFW_KEY_EQUAL},        {",", GLFW_KEY_COMMA},         {".", GLFW_KEY_PERIOD},
};

} // namespace

std::span<const KeyBinding> keyBindings() {
    return kBindings;
}

Action actionFor(int key, int mods) {
    const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
    Action plain = Action::None;
    for (const KeyBinding& b : kBindings) {
        if (b.key != key) continue;
        if (b.shift && shift) return b.action;
        if (!b.shift) plain = b.action;
    }
    return plain;
}

std::vector<std::string> helpLines() {
    std::vector<std::string> lines;
    std::string_view previousLabel, previousHelp;
    for (const KeyBinding& b : kBindings) {
        if (b.label == previousLabel && b.help == previousHelp) continue;
        // The tab makes the HUD align the help column (its font is proportional).
        lines.push_back(std::string(b.label) + "\t" + std::string(b.help));
        previousLabel = b.label;
        previousHelp = b.help;
    }
    return lines;
}

std::optional<int> parseKeyName(std::string_view name) {
    std::string upper(name);
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const NamedKey& k : kNamedKeys)
        if (upper == k.name) return k.key;
    if (upper.size() == 1 && upper[0] >= 'A' && upper[0] <= 'Z')
        return GLFW_KEY_A + (upper[0] - 'A');
    if (upper.size() == 1 && upper[0] >= '0' && upper[0] <= '9')
        return GLFW_KEY_0 + (upper[0] - '0');
    if (upper.size() >= 2 && upper.size() <= 3 && upper[0] == 'F') {
        int n = 0;
        for (std::size_t i = 1; i < upper.size(); ++i) {
            if (!std::isdigit(static_cast<unsigned char>(upper[i]))) return std::nullopt;
            n = n * 10 + (upper[i] - '0');
        }
        if (n >= 1 && n <= 12) return GLFW_KEY_F1 + (n - 1);
    }
    return std::nullopt;
}

} // namespace fl::app
