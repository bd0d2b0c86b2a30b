// The viewer's key table (one table drives the handling and the help text) and the --script
// parser and player (app/src/ViewerInput, app/src/InputScript).

#include <app/InputScript.h>
#include <app/ViewerInput.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace fl::app {
namespace {

TEST(KeyTable, EveryActionIsBoundAndNoKeyTwice) {
    std::set<Action> bound;
    std::set<std::pair<int, bool>> keys;
    for (const KeyBinding& b : keyBindings()) {
        bound.insert(b.action);
        if (b.key < 0) continue; // mouse rows
        EXPECT_TRUE(keys.insert({b.key, b.shift}).second)
            << "key " << b.key << (b.shift ? " +shift" : "") << " bound twice";
        EXPECT_FALSE(b.help.empty()) << b.label;
    }
    for (int a = static_cast<int>(Action::Quit); a <= static_cast<int>(Action::LightLarger); ++a)
        EXPECT_TRUE(bound.count(static_cast<Action>(a))) << "action " << a << " has no key";
}

TEST(KeyTable, LooksUpShiftedAndPlainKeys) {
    EXPECT_EQ(actionFor(GLFW_KEY_M, 0), Action::NextMethod);
    EXPECT_EQ(actionFor(GLFW_KEY_M, GLFW_MOD_SHIFT), Action::PrevMethod);
    EXPECT_EQ(actionFor(GLFW_KEY_O, GLFW_MOD_SHIFT), Action::PrevOverlay);
    // No Shift binding: Shift does not hide the plain one.
    EXPECT_EQ(actionFor(GLFW_KEY_T, GLFW_MOD_SHIFT), Action::ToggleProvider);
    EXPECT_EQ(actionFor(GLFW_KEY_F12, 0), Action::Screenshot);
    EXPECT_EQ(actionFor(GLFW_KEY_P, 0), Action::Screenshot);
    EXPECT_EQ(actionFor(GLFW_KEY_ESCAPE, 0), Action::Quit);
    EXPECT_EQ(actionFor(GLFW_KEY_Y, 0), Action::None);
    EXPECT_EQ(actionFor(GLFW_KEY_W, 0), Action::None); // held in fly mode, not an action
}

TEST(KeyTable, HelpHasOneLinePerLabelFromTheTable) {
    const std::vector<std::string> help = helpLines();
    std::set<std::string> labels;
    for (const KeyBinding& b : keyBindings()) labels.insert(std::string(b.label));
    EXPECT_EQ(help.size(), labels.size());
    for (const std::string& label : labels) {
        int found = 0;
        for (const std::string& line : help) found += line.rfind(label + "\t", 0) == 0;
        EXPECT_EQ(found, 1) << label;
    }
    bool flooding = false;
    for (const std::string& line : help)
        flooding |= line.find("standard flooding") != std::string::npos;
    EXPECT_TRUE(flooding) << "the help must say how the live comparison works";
}

TEST(KeyNames, ParseLettersDigitsPunctuationAndNamedKeys) {
    EXPECT_EQ(parseKeyName("m"), GLFW_KEY_M);
    EXPECT_EQ(parseKeyName("M"), GLFW_KEY_M);
    EXPECT_EQ(parseKeyName("7"), GLFW_KEY_7);
    EXPECT_EQ(parseKeyName("["), GLFW_KEY_LEFT_BRACKET);
    EXPECT_EQ(parseKeyName("."), GLFW_KEY_PERIOD);
    EXPECT_EQ(parseKeyName("f12"), GLFW_KEY_F12);
    EXPECT_EQ(parseKeyName("F1"), GLFW_KEY_F1);
    EXPECT_EQ(parseKeyName("Left"), GLFW_KEY_LEFT);
    EXPECT_EQ(parseKeyName("tab"), GLFW_KEY_TAB);
    EXPECT_FALSE(parseKeyName("F13"));
    EXPECT_FALSE(parseKeyName("F1x"));
    EXPECT_FALSE(parseKeyName("foo"));
    EXPECT_FALSE(parseKeyName(""));
}

TEST(InputScript, ParsesEveryEvent) {
    const auto ev = parseInputScript("# a comment\n"
                                     "key shift+M   # previous method\n"
                                     "hold w 5\n"
                                     "drag right 1 2 3.5 4 6\n"
                                     "\n"
                                     "click 10 20\n"
                                     "scroll -2\n"
                                     "resize 0 0\n"
                                     "screenshot shot-{method}\n"
                                     "drop scenes/a b.glb\n"
                                     "wait 3\n"
                                     "quit\n",
                                     "s");
    using K = ScriptEvent::Kind;
    ASSERT_EQ(ev.size(), 10u);
    EXPECT_EQ(ev[0].kind, K::Key);
    EXPECT_EQ(ev[0].key, GLFW_KEY_M);
    EXPECT_EQ(ev[0].mods, GLFW_MOD_SHIFT);
    EXPECT_EQ(ev[0].line, 2);
    EXPECT_EQ(ev[1].kind, K::Hold);
    EXPECT_EQ(ev[1].key, GLFW_KEY_W);
    EXPECT_EQ(ev[1].frames, 5);
    EXPECT_EQ(ev[2].kind, K::Drag);
    EXPECT_TRUE(ev[2].rightButton);
    EXPECT_EQ(ev[2].from, glm::vec2(1, 2));
    EXPECT_EQ(ev[2].to, glm::vec2(3.5f, 4));
    EXPECT_EQ(ev[2].steps, 6);
    EXPECT_EQ(ev[3].kind, K::Click);
    EXPECT_EQ(ev[3].line, 6);
    EXPECT_EQ(ev[4].scroll, -2.0);
    EXPECT_EQ(ev[5].kind, K::Resize);
    EXPECT_EQ(ev[5].size, glm::ivec2(0, 0));
    EXPECT_EQ(ev[6].text, "shot-{method}");
    EXPECT_EQ(ev[7].kind, K::Drop);
    EXPECT_EQ(ev[7].text, "scenes/a b.glb"); // the rest of the line
    EXPECT_EQ(ev[8].frames, 3);
    EXPECT_EQ(ev[9].kind, K::Quit);
}

// The message names the source and line, and says what is wrong.
void expectError(const std::string& text, const std::string& expected) {
    try {
        parseInputScript(text, "my.script");
        FAIL() << "no error for: " << text;
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
            << "got: " << e.what() << "\nexpected to contain: " << expected;
    }
}

// Found by fuzz/fuzz_input_script: a position beyond a float (2.7e150) parsed as a finite double
// and became an infinite click position.
TEST(InputScript, ClickBeyondAFloatIsRefused) {
    expectError("wait 2\nclick 10 2" + std::string(150, '7') + "\n",
                "my.script:2: must be a finite number in [-1000000, 1000000]");
    expectError("drag left 0 0 1e39 0\n", "must be a finite number in [-1000000, 1000000]");
}

TEST(InputScript, RejectsBadLinesWithFileAndLine) {
    expectError("wait 1\njump 3\n", "my.script:2: unknown event 'jump'");
    expectError("key\n", "my.script:1: expected 'key NAME'");
    expectError("key banana\n", "unknown key 'banana'");
    expectError("wait 0\n", "my.script:1: must be an integer in [1, 1000000], got '0'");
    expectError("wait 2.5\n", "must be an integer");
    expectError("wait 1e7\n", "must be an integer in [1, 1000000]");
    expectError("scroll x\n", "must be a finite number in [-1000000, 1000000], got 'x'");
    expectError("scroll nan\n", "got 'nan'");
    expectError("scroll 1e400\n", "got '1e400'");
    expectError("resize -1 5\n", "must be an integer in [0, 1000000], got '-1'");
    expectError("drag middle 0 0 1 1\n", "left or right");
    expectError("screenshot ../x\n", "without folders");
    expectError("quit now\n", "expected 'quit'");
}

TEST(InputScript, PlayerPausesOnWaitAndHoldsKeys) {
    ScriptPlayer p(parseInputScript("key M\nhold W 2\nkey T\nwait 3\nkey O\n", "s"));
    auto f0 = p.due(0);
    ASSERT_EQ(f0.size(), 2u); // key M, hold W
    EXPECT_TRUE(p.held(GLFW_KEY_W, 0));
    EXPECT_TRUE(p.held(GLFW_KEY_W, 1));
    EXPECT_TRUE(p.due(1).empty());
    EXPECT_FALSE(p.held(GLFW_KEY_W, 2));
    EXPECT_FALSE(p.held(GLFW_KEY_S, 0));
    const auto f2 = p.due(2);
    ASSERT_EQ(f2.size(), 2u); // key T, wait 3
    EXPECT_EQ(f2[0].key, GLFW_KEY_T);
    EXPECT_TRUE(p.due(4).empty());
    EXPECT_FALSE(p.finished(4));
    const auto f5 = p.due(5);
    ASSERT_EQ(f5.size(), 1u);
    EXPECT_EQ(f5[0].key, GLFW_KEY_O);
    EXPECT_TRUE(p.finished(5));
}

// Issue 42: "screenshot a.png" then "key M" in the same frame took the picture after the key,
// naming it after the wrong method. Steps run in the order written: the screenshot's frame is
// drawn with what came before it, and what follows waits for the next frame.
TEST(InputScript, StepsAfterAScreenshotWaitForItsFrame) {
    ScriptPlayer p(parseInputScript("key M\nscreenshot a.png\nkey M\nkey M\nscreenshot b.png\n"
                                    "quit\n",
                                    "s"));
    const auto f0 = p.due(0);
    ASSERT_EQ(f0.size(), 2u); // key M, then the screenshot of the frame that follows
    EXPECT_EQ(f0[0].kind, ScriptEvent::Kind::Key);
    EXPECT_EQ(f0[1].kind, ScriptEvent::Kind::Screenshot);
    EXPECT_EQ(f0[1].text, "a.png");
    EXPECT_FALSE(p.finished(0));
    const auto f1 = p.due(1);
    ASSERT_EQ(f1.size(), 3u); // key M, key M, screenshot b.png
    EXPECT_EQ(f1[2].text, "b.png");
    const auto f2 = p.due(2);
    ASSERT_EQ(f2.size(), 1u);
    EXPECT_EQ(f2[0].kind, ScriptEvent::Kind::Quit);
    EXPECT_TRUE(p.finished(2));
}

} // namespace
} // namespace fl::app
