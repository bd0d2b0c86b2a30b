// Compares one channel of two EXR files (or of every EXR file two folders share by relative
// path), counting the receivers whose value moved by more than a threshold: the check behind
// "the same picture" of an optimisation (issue 28: the packed surfaces pass against the unpacked
// one; docs/history/gpu-and-lean-frame.md, "Lean frame"). Receivers are the pixels whose
// `receiver` channel is 1 in the first file (every pixel if it has none).
//   exr_diff A B [--channel visibility] [--threshold 0.00392]
// Prints one row per file pair and a total; exit 1 if any file is missing from B or differs in
// size.

#include <io/ImageIO.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Tally {
    long receivers = 0, moved = 0;
    double maxAbs = 0.0, sumSq = 0.0;
};

const std::vector<float>* channel(const std::vector<fl::ExrChannel>& cs, const std::string& name) {
    for (const fl::ExrChannel& c : cs)
        if (c.name == name) return &c.values;
    return nullptr;
}

// Adds the pair a/b to `t`; false (with a message) when they cannot be compared.
bool comparePair(const fs::path& a, const fs::path& b, const std::string& name, float threshold,
                 bool everyPixel, Tally& total) {
    int wa = 0, ha = 0, wb = 0, hb = 0;
    const std::vector<fl::ExrChannel> ca = fl::readExr(a, wa, ha), cb = fl::readExr(b, wb, hb);
    const std::vector<float>*va = channel(ca, name), *vb = channel(cb, name);
    if (wa != wb || ha != hb || !va || !vb) {
        std::fprintf(stderr, "%s: no channel '%s' in both, or the sizes differ\n",
                     b.string().c_str(), name.c_str());
        return false;
    }
    const std::vector<float>* receiver = everyPixel ? nullptr : channel(ca, "receiver");
    Tally t;
    for (std::size_t i = 0; i < va->size(); ++i) {
        if (receiver && (*receiver)[i] < 0.5f) continue;
        const double d = std::abs(double((*va)[i]) - double((*vb)[i]));
        ++t.receivers;
        t.moved += d > threshold;
        t.maxAbs = std::max(t.maxAbs, d);
        t.sumSq += d * d;
    }
    std::printf("%-60s receivers %8ld  moved > %.5f: %6ld (%.4f%%)  max %.5f  rms %.6f\n",
                a.string().c_str(), t.receivers, double(threshold), t.moved,
                t.receivers ? 100.0 * double(t.moved) / double(t.receivers) : 0.0, t.maxAbs,
                t.receivers ? std::sqrt(t.sumSq / double(t.receivers)) : 0.0);
    total.receivers += t.receivers;
    total.moved += t.moved;
    total.maxAbs = std::max(total.maxAbs, t.maxAbs);
    total.sumSq += t.sumSq;
    return true;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Compares one channel of two EXR files or folders of them"};
    fs::path a, b;
    std::string name = "visibility";
    float threshold = 1.0f / 255.0f;
    app.add_option("A", a, "EXR file or folder (the reference)")->required();
    app.add_option("B", b, "EXR file or folder (the same relative paths)")->required();
    app.add_option("--channel", name, "Channel to compare");
    app.add_option("--threshold", threshold, "A receiver moved if |A - B| exceeds this");
    bool everyPixel = false;
    app.add_flag("--all", everyPixel, "Compare every pixel, not only the receivers");
    CLI11_PARSE(app, argc, argv);
    std::vector<std::pair<fs::path, fs::path>> pairs;
    if (fs::is_directory(a)) {
        for (const auto& e : fs::recursive_directory_iterator(a))
            if (e.path().extension() == ".exr")
                pairs.emplace_back(e.path(), b / fs::relative(e.path(), a));
        std::sort(pairs.begin(), pairs.end());
    } else {
        pairs.emplace_back(a, b);
    }
    Tally total;
    bool ok = true;
    try {
        for (const auto& [pa, pb] : pairs)
            ok = comparePair(pa, pb, name, threshold, everyPixel, total) && ok;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    std::printf("total: %zu files, receivers %ld, moved %ld (%.4f%%), max %.5f, rms %.6f\n",
                pairs.size(), total.receivers, total.moved,
                total.receivers ? 100.0 * double(total.moved) / double(total.receivers) : 0.0,
                total.maxAbs,
                total.receivers ? std::sqrt(total.sumSq / double(total.receivers)) : 0.0);
    return ok ? 0 : 1;
}
