#pragma once
// The window's key bindings as one table: the viewer looks actions up in it and the HUD's help
// text is generated from it, so the two cannot disagree.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fl::app {

enum class Action {
    None, // held keys (fly movement) and mouse rows: help text only
    Quit,
    NextMethod,
    PrevMethod,
    ToggleProvider,
    ShadowMapSmaller,
    ShadowMapLarger,
    FewerPasses,
    MorePasses,
    NextFloodRegion,
    NextVariant,
    NextOverlay,
    PrevOverlay,
    StepBack,
    StepForward,
    NewPoints,
    ToggleHelp,
    ToggleHud,
    Screenshot,
    Stats,
    ToggleCameraMode,
    ResetView,
    LightLeft,
    LightRight,
    LightUp,
    LightDown,
    LightSmaller,
    LightLarger,
    NextCamera,
    PlayPause,
    AnimationBack,
    AnimationForward,
    AnimationSlower,
    AnimationFaster,
};

struct KeyBinding {
    int key;    // GLFW_KEY_*; -1 for mouse rows
    bool shift; // binding needs Shift held (a Shift binding wins over the plain one)
    Action action;
    std::string_view label; // how the help shows the key(s); equal labels share one help line
    std::string_view help;
};

/// Every binding, in help order.
std::span<const KeyBinding> keyBindings();
/// The action for a key press with GLFW modifier bits `mods`; Action::None if unbound.
Action actionFor(int key, int mods);
/// One line per distinct (label, help): "LABEL\tHELP", e.g. "M / Shift+M\tnext / previous
/// shadow method" (the HUD aligns what follows the tab).
std::vector<std::string> helpLines();
/// GLFW key for a name: a letter or digit, a punctuation character ("[", ","), or one of
/// ESC, TAB, SPACE, ENTER, LEFT, RIGHT, UP, DOWN, F1..F12, LSHIFT (case-insensitive).
std::optional<int> parseKeyName(std::string_view name);

} // namespace fl::app
