// Capture scripts (app/CaptureScript.h): the formats they accept, the options methods carry,
// and a message naming the field for every malformed or missing one.

#include "TestPaths.h"
#include <app/CaptureScript.h>

#include <renderer/methods/OptionStructs.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/soft/FilteredShadow.h>

#include <gtest/gtest.h>

namespace fl::app {
namespace {

const std::filesystem::path kFile = "/scripts/test.json";

CaptureScript parse(const std::string& text) {
    return parseCaptureScript(text, kFile);
}

// The reference's option `key` (given or its row's default), as text and as an integer.
std::string referenceValue(const CaptureScript& s, std::string_view key) {
    return s.reference.options.text(*s.reference.method().option(key));
}
int referenceInt(const CaptureScript& s, std::string_view key) {
    return s.reference.options.integer(*s.reference.method().option(key));
}

// A minimal valid script with `extra` members added (leading comma included by the caller).
std::string script(const std::string& extra = "",
                   const std::string& methods = R"(["hard", "jfa-l"])") {
    return R"({"camera": {"frames": 3, "path": "default"}, "methods": )" + methods + extra + "}";
}

TEST(CaptureScript, MinimalScriptHasDefaults) {
    const CaptureScript s = parse(script());
    EXPECT_EQ(s.frames, 3);
    EXPECT_EQ(s.jfaPasses, "auto"); // as --jfa-passes
    EXPECT_EQ(parse(script(R"(, "jfaPasses": "auto")")).jfaPasses, "auto");
    EXPECT_FALSE(s.camera); // the default walkthrough
    EXPECT_TRUE(s.scene.empty());
    ASSERT_EQ(s.resolutions.size(), 1u);
    EXPECT_EQ(s.resolutions[0], std::make_pair(512, 512));
    EXPECT_EQ(s.shadowMapProvider, "uniform");
    EXPECT_EQ(referenceInt(s, "samples"), ReferenceSettings{}.samples);
    ASSERT_EQ(s.methods.size(), 2u);
    EXPECT_EQ(s.methods[1].method, "jfa-l");
    EXPECT_EQ(s.methods[1].label, "jfa-l");
    EXPECT_TRUE(s.saveFrames);
    EXPECT_EQ(s.ground, "auto");
}

TEST(CaptureScript, EveryField) {
    const CaptureScript s = parse(R"({
      "scene": "scenes/room.glb",
      "camera": {"frames": 10, "fov": 40, "interpolation": "linear",
                 "keys": [{"eye": [0, 1, 5], "target": [0, 0, 0]},
                          {"eye": [5, 1, 0], "target": [0, 0, 0]}]},
      "light": {"radius": 0.5, "keys": [[0, 10, 0], [5, 10, 0]]},
      "resolutions": [[64, 48], [128, 128]],
      "shadowMap": {"provider": "tsm", "size": 512},
      "jfaPasses": 5,
      "reference": {"samples": 16, "mapSize": 256},
      "methods": ["pcss:16/24", {"method": "pcss", "preset": "32/64"}, "pcf:5",
                  {"method": "jfa-l", "passes": 4, "label": "jfa-l short"}, "flood-e:3",
                  "reference"],
      "saveFrames": false, "ground": "off"})");
    EXPECT_EQ(s.scene, std::filesystem::path("/scripts/scenes/room.glb"));
    EXPECT_EQ(s.ground, "off");
    ASSERT_TRUE(s.camera);
    EXPECT_EQ(s.camera->interpolation(), PathInterpolation::Linear);
    EXPECT_EQ(s.camera->yfovDegrees(), 40.0f);
    EXPECT_EQ(s.frames, 10);
    EXPECT_EQ(*s.lightRadius, 0.5f);
    ASSERT_EQ(s.lightKeys.size(), 2u);
    EXPECT_EQ(lightPositionAt(s.lightKeys, 0, 11), glm::vec3(0, 10, 0));
    EXPECT_EQ(lightPositionAt(s.lightKeys, 5, 11), glm::vec3(2.5f, 10, 0));
    EXPECT_EQ(lightPositionAt(s.lightKeys, 10, 11), glm::vec3(5, 10, 0));
    EXPECT_EQ(s.resolutions[1], std::make_pair(128, 128));
    EXPECT_EQ(s.shadowMapProvider, "tsm");
    EXPECT_EQ(s.shadowMapSize, 512);
    EXPECT_EQ(s.jfaPasses, "5");
    EXPECT_EQ(s.reference.kind, "maps");
    EXPECT_EQ(s.reference.method().name, "reference");
    EXPECT_EQ(referenceInt(s, "samples"), 16);
    EXPECT_EQ(referenceInt(s, "mapSize"), 256);
    EXPECT_FALSE(s.saveFrames);
    ASSERT_EQ(s.methods.size(), 6u);
    const MethodOption& preset = *findMethod("pcss")->option("preset");
    const MethodOption& kernel = *findMethod("pcf")->option("kernel");
    const MethodOption& passes = floodPassesOption();
    EXPECT_EQ(s.methods[0].label, "pcss:16/24");
    EXPECT_EQ(s.methods[0].options.text(preset), "16/24");
    EXPECT_EQ(parsePcssPreset(s.methods[0].options.text(preset))->filterSamples, 24);
    EXPECT_EQ(s.methods[1].label, "pcss:32/64");
    EXPECT_EQ(parsePcssPreset(s.methods[1].options.text(preset))->blockerSamples, 32);
    ASSERT_TRUE(s.methods[2].options.has(kernel.flag));
    EXPECT_EQ(s.methods[2].options.integer(kernel), 5);
    EXPECT_EQ(s.methods[3].label, "jfa-l short");
    ASSERT_TRUE(s.methods[3].options.has(passes.flag));
    EXPECT_EQ(s.methods[3].options.integer(passes), 4);
    ASSERT_TRUE(s.methods[4].options.has(passes.flag));
    EXPECT_EQ(s.methods[4].options.integer(passes), 3);
    EXPECT_EQ(s.methods[5].method, "reference");

    // The options reach the render settings.
    const RenderSettings pcss = settingsFor(RenderSettings{}, s.methods[1]);
    EXPECT_EQ(pcss.method, "pcss");
    EXPECT_EQ(parsePcssPreset(pcss.options.text(preset))->filterSamples, 64);
    EXPECT_EQ(settingsFor(RenderSettings{}, s.methods[2]).options.integer(kernel), 5);
    EXPECT_EQ(settingsFor(RenderSettings{}, s.methods[3]).options.integer(passes), 4);
}

TEST(CaptureScript, TheReferenceIsChosenByKind) {
    const CaptureScript rays =
        parse(script(R"(, "reference": {"kind": "raytrace", "samples": 64})"));
    EXPECT_EQ(rays.reference.kind, "raytrace");
    EXPECT_EQ(rays.reference.method().name, "raytrace");
    EXPECT_EQ(referenceInt(rays, "samples"), 64);
    EXPECT_EQ(referenceText(rays.reference), "raytrace: 64 shadow rays per pixel (Embree)");
    const CaptureScript maps = parse(script(R"(, "reference": {"kind": "maps", "mapSize": 512})"));
    EXPECT_EQ(maps.reference.method().name, "reference");
    EXPECT_EQ(referenceText(maps.reference), "maps: 256 point-light shadow maps of 512^2 (spiral)");
    const CaptureScript grid = parse(script(R"(, "reference": {"pattern": "grid"})"));
    EXPECT_EQ(referenceValue(grid, "pattern"), "grid");
    EXPECT_EQ(referenceText(grid.reference), "maps: 256 point-light shadow maps of 2048^2 (grid)");
    // The ray tracer's terminator offset: on unless the script says off.
    EXPECT_EQ(referenceValue(rays, "terminatorOffset"), "on");
    EXPECT_EQ(
        referenceValue(
            parse(script(R"(, "reference": {"kind": "raytrace", "terminatorOffset": "off"})")),
            "terminatorOffset"),
        "off");
    // Any option of the truth's row, stored by its flag as the script gives it.
    const CaptureScript rayGrid =
        parse(script(R"(, "reference": {"kind": "raytrace", "grid": true, "samples": 16.0})"));
    EXPECT_EQ(rayGrid.reference.options.values().size(), 2u);
    EXPECT_EQ(referenceValue(rayGrid, "grid"), "true");
    EXPECT_EQ(referenceInt(rayGrid, "samples"), 16);
    EXPECT_EQ(referenceText(rayGrid.reference),
              "raytrace: 16 shadow rays per pixel to the strata's centres (Embree)");
    // The default is the shadow-map ground truth (the faster one on this machine).
    EXPECT_EQ(parse(script()).reference.kind, "maps");
    // Every ground truth of the table takes its own row's options and describes itself.
    for (const MethodDescriptor& m : methodTable()) {
        if (m.truth.empty()) continue;
        EXPECT_NE(m.describe, nullptr) << m.name;
        const CaptureScript t =
            parse(script(R"(, "reference": {"kind": ")" + std::string(m.truth) + "\"}"));
        EXPECT_EQ(&t.reference.method(), &m);
        EXPECT_TRUE(referenceText(t.reference).starts_with(std::string(m.truth) + ": "))
            << referenceText(t.reference);
    }
}

TEST(CaptureScript, CameraFromAFile) {
    const auto dir = test::outputDir("capture_script");
    writeCameraPath(dir / "path.json",
                    CameraPath({{{0, 1, 2}, {0, 0, 0}}, {{2, 1, 0}, {0, 0, 0}}}));
    const CaptureScript s =
        parseCaptureScript(R"({"camera": {"frames": 2, "file": "path.json"}, "methods": ["hard"]})",
                           dir / "script.json");
    ASSERT_TRUE(s.camera);
    EXPECT_EQ(s.camera->keys().size(), 2u);
}

TEST(CaptureScript, LinearInterpolationIsPiecewiseStraight) {
    const CameraPath p({{{0, 0, 0}, {0, 0, -1}}, {{2, 0, 0}, {2, 0, -1}}, {{2, 2, 0}, {2, 2, -1}}},
                       50.0f, PathInterpolation::Linear);
    EXPECT_NEAR(glm::length(p.keyAt(0.25f).eye - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(p.keyAt(0.75f).eye - glm::vec3(2, 1, 0)), 0.0f, 1e-6f);
}

struct Bad {
    std::string text;
    std::string field; // the message must name it
};

TEST(CaptureScript, EveryMalformedFieldIsNamed) {
    const std::vector<Bad> cases = {
        {"{", "not valid JSON"},
        {"[1, 2]", "script"},
        {R"({"methods": ["hard"]})", "camera"},
        {R"({"camera": {"path": "default"}, "methods": ["hard"]})", "camera.frames"},
        {R"({"camera": {"frames": 0, "path": "default"}, "methods": ["hard"]})", "camera.frames"},
        {R"({"camera": {"frames": "3", "path": "default"}, "methods": ["hard"]})", "camera.frames"},
        {R"({"camera": {"frames": 3, "path": "spiral"}, "methods": ["hard"]})", "camera.path"},
        {R"({"camera": {"frames": 3}, "methods": ["hard"]})", "camera"},
        {R"({"camera": {"frames": 3, "file": "/nonexistent.json"}, "methods": ["hard"]})",
         "camera.file"},
        {R"({"camera": {"frames": 3, "keys": [{"eye": [0, 0, 0]}]}, "methods": ["hard"]})",
         "camera.keys[0]"},
        {R"({"camera": {"frames": 3, "interpolation": "cubic", "keys": []},
             "methods": ["hard"]})",
         "camera.interpolation"},
        {R"({"camera": {"frames": 3, "path": "default", "speed": 2}, "methods": ["hard"]})",
         "camera.speed"},
        {R"({"camera": {"frames": 3, "path": "default"}})", "methods"},
        {script(R"(, "light": {"radius": -1})"), "light.radius"},
        {script(R"(, "light": {"keys": [[0, 1]]})"), "light.keys[0]"},
        {script(R"(, "resolutions": [[64]])"), "resolutions[0]"},
        {script(R"(, "resolutions": [[64, 0]])"), "resolutions[0][1]"},
        {script(R"(, "resolutions": [])"), "resolutions"},
        {script(R"(, "shadowMap": {"provider": "cascaded"})"), "shadowMap.provider"},
        {script(R"(, "shadowMap": {"size": 4})"), "shadowMap.size"},
        {script(R"(, "jfaPasses": 99)"), "jfaPasses"},
        {script(R"(, "jfaPasses": "many")"), "jfaPasses"},
        {script(R"(, "jfaPasses": 2.5)"), "jfaPasses"},
        {script(R"(, "jfaPasses": 10, "shadowMap": {"size": 256})"), "jfaPasses"},
        {script(R"(, "reference": {"samples": 0})"), "reference.samples"},
        {script(R"(, "reference": {"mapSize": "big"})"), "reference.mapSize"},
        {script(R"(, "reference": {"kind": "photons"})"), "reference.kind"},
        {script(R"(, "reference": {"kind": 2})"), "reference.kind"},
        {script(R"(, "reference": {"kind": "raytrace", "mapSize": 512})"), "reference.mapSize"},
        {script(R"(, "reference": {"pattern": "halton"})"), "reference.pattern"},
        {script(R"(, "reference": {"pattern": 3})"), "reference.pattern"},
        {script(R"(, "reference": {"kind": "raytrace", "pattern": "grid"})"), "reference.pattern"},
        {script(R"(, "reference": {"kind": "raytrace", "samples": 100000})"), "reference.samples"},
        {script(R"(, "reference": {"kind": "raytrace", "terminatorOffset": "maybe"})"),
         "reference.terminatorOffset"},
        {script(R"(, "reference": {"terminatorOffset": "off"})"), "reference.terminatorOffset"},
        {script(R"(, "reference": {"grid": true})"), "reference.grid"},
        {script(R"(, "reference": {"kind": "raytrace", "grid": "yes"})"), "reference.grid"},
        {script(R"(, "reference": {"lights": 3})"), "reference.lights"},
        {script(R"(, "saveFrames": "yes")"), "saveFrames"},
        {script(R"(, "ground": "maybe")"), "ground"},
        {script(R"(, "ground": true)"), "ground"},
        {script(R"(, "frames": 3)"), "script.frames"},
        {script("", R"([])"), "methods"},
        {script("", R"("hard")"), "methods"},
        {script("", R"(["hard", "no-such-method"])"), "methods[1]"},
        {script("", R"(["pcss:8/8"])"), "methods[0].preset"},
        {script("", R"(["pcf:big"])"), "methods[0]"},
        {script("", R"(["pcf:99"])"), "methods[0].kernel"},
        {script("", R"([{"preset": "16/24"}])"), "methods[0].method"},
        {script("", R"([{"method": "hard", "preset": "16/24"}])"), "methods[0].preset"},
        {script("", R"([{"method": "pcf", "passes": 3}])"), "methods[0].passes"},
        {script("", R"([{"method": "pcf", "colour": 3}])"), "methods[0].colour"},
        // --penumbra: only the methods with a penumbra map, and only outer or both.
        {script("", R"([{"method": "pcss", "penumbra": "both"}])"), "only jfa-l, flood-l take"},
        {script("", R"([{"method": "jfa-l", "penumbra": "inner"}])"), "methods[0].penumbra"},
        {script("", R"(["hard", "hard"])"), "methods[1]"},
        {script("", R"([42])"), "methods[0]"},
        {script(R"(, "animation": {"start": -1})"), "animation.start"},
        {script(R"(, "animation": {"fps": "fast"})"), "animation.fps"},
        {script(R"(, "animation": {"name": [1]})"), "animation.name"},
        {script(R"(, "animation": {"speed": 2})"), "animation.speed"},
    };
    for (const Bad& c : cases) {
        try {
            (void)parse(c.text);
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const CaptureScriptError& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find(kFile.string()), std::string::npos) << msg;
            EXPECT_NE(msg.find(c.field), std::string::npos)
                << "expected '" << c.field << "' in: " << msg;
        }
    }
}

// JFA-L's halves of the penumbra as a method row's key (the method-options table's "penumbra").
TEST(CaptureScript, PenumbraSidesAreAMethodKey) {
    const CaptureScript s = parse(script(
        "",
        R"([{"method": "jfa-l", "penumbra": "outer"}, {"method": "flood-l", "penumbra": "both"}])"));
    ASSERT_EQ(s.methods.size(), 2u);
    EXPECT_EQ(s.methods[0].options.text(penumbraSidesOption()), "outer");
    EXPECT_EQ(s.methods[0].label, "jfa-l:outer");
    EXPECT_TRUE(penumbraBothSides(s.methods[1].options));
    EXPECT_TRUE(penumbraBothSides(parse(script()).methods[1].options)) << "the default";
}

TEST(CaptureScript, AnimationClip) {
    const CaptureScript plain = parse(script());
    EXPECT_EQ(plain.animation.name, "all");
    EXPECT_EQ(plain.animation.start, 0.0);
    EXPECT_EQ(plain.animation.fps, 0.0);
    const CaptureScript s =
        parse(script(R"(, "animation": {"name": "walk", "start": 1.5, "fps": 24})"));
    EXPECT_EQ(s.animation.name, "walk");
    EXPECT_EQ(s.animation.start, 1.5);
    EXPECT_EQ(s.animation.fps, 24.0);
    EXPECT_EQ(parse(script(R"(, "animation": {"name": 2})")).animation.name, "2");
}

TEST(CaptureScript, MissingFileIsNamed) {
    try {
        (void)readCaptureScript("/nonexistent/capture.json");
        ADD_FAILURE() << "no error";
    } catch (const CaptureScriptError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/capture.json"), std::string::npos);
    }
}

TEST(CaptureScript, ShippedExamplesParse) {
    for (const char* name : {"short.json", "walkthrough.json", "medium.json"}) {
        const auto file = test::dataDir().parent_path() / "examples" / "capture" / name;
        const CaptureScript s = readCaptureScript(file);
        EXPECT_GE(s.frames, 1) << name;
        bool hasJfa = false, hasFlood = false;
        for (const MethodSpec& m : s.methods) {
            hasJfa = hasJfa || m.method == "jfa-l";
            hasFlood = hasFlood || m.method == "flood-l";
        }
        EXPECT_TRUE(hasJfa && hasFlood) << name << ": the |dI| chart needs both";
    }
    EXPECT_EQ(readCaptureScript(test::dataDir().parent_path() / "examples" / "capture" /
                                "walkthrough.json")
                  .frames,
              462);
}

// A script entry's options reach the method as its typed struct (MethodOptionSet::parse, what
// the renderer does once per settings): values as the script gave them, defaults elsewhere.
TEST(TypedOptions, ScriptOptionsParseIntoTheMethodsStruct) {
    const CaptureScript s = parse(script(
        "", R"(["pcf:5", "pcss:32/64", {"method": "jfa-e", "passes": 4, "occluderPoints": "centre",
               "noMidpointFix": true}, {"method": "jfa-l", "penumbra": "outer"}, "raytrace"])"));
    const auto typed = [&](std::size_t i) {
        return methodOrThrow(s.methods[i].method).options.parse(s.methods[i].options);
    };
    EXPECT_EQ(std::any_cast<PcfOptions>(typed(0)).kernel, 5);
    EXPECT_EQ(std::any_cast<PcssOptions>(typed(1)).preset.filterSamples, 64);
    const auto eye = std::any_cast<EyeFloodOptions>(typed(2));
    EXPECT_EQ(eye.flood.passes, 4);
    EXPECT_FALSE(eye.flood.fullJfa);
    EXPECT_EQ(eye.flood.region, jfa::FloodRegion::View); // the default, "view"
    EXPECT_EQ(eye.flood.bandTile, 8);
    EXPECT_EQ(eye.occluderPoints, OccluderPoints::TexelCentre);
    EXPECT_TRUE(eye.noMidpointFix);
    EXPECT_FALSE(eye.noObjectIdFix);
    EXPECT_EQ(eye.autoPasses, EyeAutoPasses::Measured);
    const auto light = std::any_cast<LightFloodOptions>(typed(3));
    EXPECT_FALSE(light.bothSides);
    EXPECT_EQ(light.flood.passes, kAutoPasses); // "auto"
    const auto rays = std::any_cast<RayTraceOptions>(typed(4));
    EXPECT_EQ(rays.samples, 256);
    EXPECT_FALSE(rays.grid);
    EXPECT_TRUE(rays.terminatorOffset);
    EXPECT_THROW((void)std::any_cast<PcfOptions>(typed(1)), std::bad_any_cast);
}

// Every row parses its defaults, and a bad value fails with the message the CLI gives.
TEST(TypedOptions, DefaultsParseAndBadValuesNameTheFlag) {
    for (const MethodDescriptor& m : methodTable()) {
        EXPECT_NO_THROW((void)m.options.parse(MethodOptions{})) << m.name;
        EXPECT_EQ(m.options.parse(MethodOptions{}).has_value(), !m.options.empty()) << m.name;
    }
    MethodOptions bad;
    bad.set("--pcf-kernel", 0);
    try {
        (void)methodOrThrow("pcf").options.parse(bad);
        ADD_FAILURE() << "kernel 0 parsed";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "--pcf-kernel: must be an integer in [1, 15], got '0'");
    }
}

} // namespace
} // namespace fl::app
