#include "ImageCompare.h"
#include "TestPaths.h"

#include <renderer/run/Capture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace fl::test {

CompareResult compareImages(const ByteImage& actual, const ByteImage& golden,
                            const Tolerance& tol) {
    CompareResult r;
    if (actual.width != golden.width || actual.height != golden.height || actual.channels != 4 ||
        golden.channels != 4) {
        r.sizeMatches = false;
        std::ostringstream s;
        s << "size mismatch: actual " << actual.width << "x" << actual.height << " golden "
          << golden.width << "x" << golden.height;
        r.report = s.str();
        return r;
    }
    const size_t pixels = static_cast<size_t>(actual.width) * static_cast<size_t>(actual.height);
    double sum = 0.0;
    size_t over = 0;
    for (size_t i = 0; i < pixels; ++i) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            const int d = std::abs(int(actual.data[i * 4 + c]) - int(golden.data[i * 4 + c]));
            worst = std::max(worst, d);
            sum += d;
        }
        r.maxAbs = std::max(r.maxAbs, worst);
        if (worst > tol.pixelThreshold) ++over;
    }
    r.meanAbs = sum / static_cast<double>(pixels * 3);
    r.percentOver = 100.0 * static_cast<double>(over) / static_cast<double>(pixels);
    r.pass =
        r.maxAbs <= tol.maxAbs && r.meanAbs <= tol.meanAbs && r.percentOver <= tol.maxPercentOver;
    std::ostringstream s;
    s << "max abs " << r.maxAbs << " (<= " << tol.maxAbs << "), mean abs " << r.meanAbs
      << " (<= " << tol.meanAbs << "), pixels over " << tol.pixelThreshold << ": " << r.percentOver
      << "% (<= " << tol.maxPercentOver << "%)";
    r.report = s.str();
    return r;
}

CompareResult compareWithGolden(const ByteImage& actual, const std::string& name,
                                const Tolerance& tol) {
    const std::filesystem::path golden = dataDir() / "golden" / (name + ".png");
    const char* update = std::getenv("FLOODLIGHT_UPDATE_GOLDENS");
    if (update && std::strcmp(update, "1") == 0) {
        writePng(golden, actual);
        CompareResult r;
        r.pass = true;
        r.report = "golden rewritten: " + golden.string();
        return r;
    }
    if (!std::filesystem::exists(golden)) {
        CompareResult r;
        r.report = "missing golden " + golden.string() +
                   " (regenerate with FLOODLIGHT_UPDATE_GOLDENS=1, see tests/golden/README.md)";
        writePng(outputDir("golden") / (name + ".actual.png"), actual);
        return r;
    }
    const ByteImage expected = readPng(golden);
    CompareResult r = compareImages(actual, expected, tol);
    if (r.pass) return r;
    const std::filesystem::path dir = outputDir("golden");
    writePng(dir / (name + ".actual.png"), actual);
    if (r.sizeMatches) writeImageDiff(actual, expected, tol, dir / (name + ".diff.png"));
    r.report += "\n  wrote " + (dir / (name + ".actual.png")).string() + " and " +
                (dir / (name + ".diff.png")).string();
    return r;
}

void writeImageDiff(const ByteImage& a, const ByteImage& b, const Tolerance& tol,
                    const std::filesystem::path& file) {
    ByteImage diff{a.width, a.height, 4, std::vector<std::uint8_t>(a.data.size())};
    for (size_t i = 0; i < a.data.size() / 4 && i < b.data.size() / 4; ++i) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            const int d = std::abs(int(a.data[i * 4 + c]) - int(b.data[i * 4 + c]));
            worst = std::max(worst, d);
            diff.data[i * 4 + c] = static_cast<std::uint8_t>(std::min(255, d * 4));
        }
        if (worst > tol.pixelThreshold) diff.data[i * 4 + 0] = 255;
        diff.data[i * 4 + 3] = 255;
    }
    writePng(file, diff);
}

std::string writeVisibilityDiff(const FloatImage& a, const FloatImage& b, const std::string& name) {
    const std::filesystem::path dir = outputDir("diff");
    writePng(dir / (name + ".a.png"), visibilityToGrey(a));
    writePng(dir / (name + ".b.png"), visibilityToGrey(b));
    FloatImage d = a;
    for (std::size_t i = 0; i < d.data.size() && i < b.data.size(); ++i)
        d.data[i] = std::min(1.0f, 4.0f * std::abs(a.data[i] - b.data[i]));
    writePng(dir / (name + ".diff.png"), visibilityToGrey(d));
    return "wrote " + (dir / (name + ".{a,b,diff}.png")).string();
}

Tolerance frameTolerance() {
    return {.maxAbs = 255, .meanAbs = 1.5, .pixelThreshold = 16, .maxPercentOver = 1.0};
}

void expectFrameMatchesGoldens(const FrameImages& frame, const std::string& name) {
    const CompareResult c =
        compareWithGolden(toSrgb8(frame.color), name + "_colour", frameTolerance());
    EXPECT_TRUE(c.pass) << c.report;
    const CompareResult v = compareWithGolden(visibilityToGrey(frame.visibility),
                                              name + "_visibility", frameTolerance());
    EXPECT_TRUE(v.pass) << v.report;
}

} // namespace fl::test
