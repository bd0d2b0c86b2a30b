// Camera paths: interpolation through the keys, JSON round trip, and messages for bad files.

#include "TestPaths.h"

#include <io/ImageIO.h>
#include <scene/CameraPath.h>

#include <gtest/gtest.h>

namespace fl {
namespace {

TEST(CameraPath, PassesThroughEveryKey) {
    const CameraPath p({{{0, 1, 0}, {0, 0, -1}}, {{1, 1, 0}, {1, 0, -1}}, {{2, 2, 0}, {2, 0, -1}}});
    EXPECT_EQ(p.keyAt(0.0f).eye, glm::vec3(0, 1, 0));
    EXPECT_NEAR(glm::length(p.keyAt(0.5f).eye - glm::vec3(1, 1, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(p.keyAt(1.0f).eye - glm::vec3(2, 2, 0)), 0.0f, 1e-6f);
    EXPECT_THROW(CameraPath({{{0, 0, 0}, {0, 0, 1}}}), std::invalid_argument);
    EXPECT_THROW(CameraPath({{{0, 0, 0}, {0, 0, 0}}, {{1, 0, 0}, {0, 0, 0}}}),
                 std::invalid_argument);
}

TEST(CameraPath, JsonRoundTrip) {
    const CameraPath p({{{0, 1, 2}, {3, 4, 5}}, {{6, 7, 8}, {9, 10, 11}}}, 40.0f);
    const auto file = test::outputDir("camera_path") / "path.json";
    writeCameraPath(file, p);
    const CameraPath q = readCameraPath(file);
    EXPECT_EQ(q.yfovDegrees(), 40.0f);
    ASSERT_EQ(q.keys().size(), 2u);
    EXPECT_EQ(q.keys()[1].target, glm::vec3(9, 10, 11));
}

TEST(CameraPath, BadFilesNameTheField) {
    const auto dir = test::outputDir("camera_path");
    const std::pair<const char*, const char*> cases[] = {
        {"{\"keys\": [{\"eye\": [0,0,0], \"target\": [1,0,0]}]}", "at least two keys"},
        {"{\"keys\": [{\"eye\": [0,0], \"target\": [1,0,0]}, {\"eye\": [0,0,1], \"target\": "
         "[1,0,0]}]}",
         "keys[0].eye"},
        {"{\"keys\": [{\"eye\": [0,0,0], \"target\": [1,0,\"x\"]}, {\"eye\": [0,0,1], "
         "\"target\": [1,0,0]}]}",
         "keys[0].target[2]"},
        {"{\"fov\": 500, \"keys\": []}", "fov"},
        // Found by fuzz/fuzz_camera_path: a key at 1.7e38 (within a float) gave infinite
        // cameras between the keys.
        {"{\"keys\": [{\"eye\": [1e3,-2,0.5], \"target\": [0,0,0]}, {\"eye\": "
         "[166666666666666666666666666666666666666,1,1], \"target\": [1,1,2]}]}",
         "keys[1].eye[0]: must be a finite number in [-1e+15, 1e+15]"},
        {"{}", "keys: missing"},
        {"[1, 2", "not valid JSON"},
    };
    int i = 0;
    for (const auto& [text, expected] : cases) {
        const auto file = dir / ("bad_" + std::to_string(i++) + ".json");
        writeTextFile(file, text);
        try {
            (void)readCameraPath(file);
            ADD_FAILURE() << text;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos);
        }
    }
    EXPECT_THROW((void)readCameraPath(dir / "missing.json"), std::runtime_error);
}

} // namespace
} // namespace fl
