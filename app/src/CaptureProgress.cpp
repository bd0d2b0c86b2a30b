#include <app/CaptureProgress.h>

#include <app/Common.h>

#include <base/InputFile.h>
#include <base/OutputFiles.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <utility>

namespace fl::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The journal of a 100,000-frame capture with a dozen methods is a few hundred MiB.
constexpr std::uintmax_t kJournalLimitMiB = 1024;

json metricsJson(const FrameMetrics& f) {
    return json::array({f.pixels, f.penumbraPixels, f.sumSquared, f.sumSquaredPenumbra, f.rmse,
                        f.rmsePenumbra, f.misclassified, f.widthMethod, f.widthReference,
                        f.widthError});
}

FrameMetrics metricsFrom(const json& a) {
    if (!a.is_array() || a.size() != 10) throw std::runtime_error("metrics: not 10 numbers");
    FrameMetrics f;
    f.pixels = a[0].get<std::size_t>();
    f.penumbraPixels = a[1].get<std::size_t>();
    f.sumSquared = a[2].get<double>();
    f.sumSquaredPenumbra = a[3].get<double>();
    f.rmse = a[4].get<double>();
    f.rmsePenumbra = a[5].get<double>();
    f.misclassified = a[6].get<double>();
    f.widthMethod = a[7].get<double>();
    f.widthReference = a[8].get<double>();
    f.widthError = a[9].get<double>();
    return f;
}

FloatImage imageFrom(const std::map<std::string, std::vector<float>>& channels,
                     const std::string& name, int w, int h, const fs::path& file) {
    const auto it = channels.find(name);
    if (it == channels.end() || it->second.size() != std::size_t(w) * std::size_t(h))
        throw InputError(file.string() + ": no channel '" + name +
                         "' (damaged; run without --resume to start over)");
    return FloatImage{w, h, 1, it->second};
}

std::map<std::string, std::vector<float>> readChannels(const fs::path& file, int& w, int& h) {
    if (!fs::is_regular_file(file))
        throw InputError(file.string() + ": missing, but the progress journal needs it (run "
                                         "without --resume to start over)");
    std::map<std::string, std::vector<float>> out;
    for (ExrChannel& c : readExr(file, w, h)) out[c.name] = std::move(c.values);
    return out;
}

std::string headerLine(const std::string& identity, int totalFrames) {
    return json{{"floodlightCapture", 1}, {"identity", identity}, {"frames", totalFrames}}.dump();
}

} // namespace

CaptureIdentity& CaptureIdentity::add(std::string_view bytes) {
    for (const char c : bytes) {
        h_ ^= static_cast<unsigned char>(c);
        h_ *= 1099511628211ull;
    }
    h_ ^= 0xff; // a separator: ("ab", "c") and ("a", "bc") differ
    h_ *= 1099511628211ull;
    return *this;
}

CaptureIdentity& CaptureIdentity::add(double value) {
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    return add(std::string_view(bytes, sizeof bytes));
}

std::string CaptureIdentity::hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h_));
    return text;
}

std::string recordLine(const FrameRecord& r) {
    json runs = json::array();
    for (const RunFrame& f : r.runs) {
        json phases = json::array();
        for (const auto& [name, ms] : f.phases) phases.push_back({name, ms});
        runs.push_back(
            {{"metrics", metricsJson(f.row.metrics)},
             {"flicker", f.row.flicker ? json(*f.row.flicker) : json()},
             {"screenFlicker", f.row.screenFlicker ? json(*f.row.screenFlicker) : json()},
             {"dI", f.row.deltaBuckets ? json(*f.row.deltaBuckets) : json()},
             {"ms", f.frameMs},
             {"phases", phases},
             {"flood", f.flood ? json{f.flood->passes, f.flood->activeShare} : json()},
             {"bias", json{f.row.bias.acneCandidates, f.row.bias.acne,
                           f.row.bias.peterPanningCandidates, f.row.bias.peterPanning}}});
    }
    return json{
        {"size", r.size}, {"frame", r.frame}, {"referenceMs", r.referenceMs}, {"runs", runs}}
        .dump();
}

FrameRecord parseRecordLine(const std::string& line) {
    try {
        const json j = json::parse(line);
        FrameRecord r;
        r.size = j.at("size").get<int>();
        r.frame = j.at("frame").get<int>();
        r.referenceMs = j.at("referenceMs").get<double>();
        for (const json& f : j.at("runs")) {
            RunFrame run;
            run.row.frame = r.frame;
            run.row.metrics = metricsFrom(f.at("metrics"));
            if (!f.at("flicker").is_null()) run.row.flicker = f["flicker"].get<double>();
            if (!f.at("screenFlicker").is_null())
                run.row.screenFlicker = f["screenFlicker"].get<double>();
            if (!f.at("dI").is_null()) run.row.deltaBuckets = f["dI"].get<std::array<double, 4>>();
            run.frameMs = f.at("ms").get<double>();
            for (const json& p : f.at("phases"))
                run.phases.emplace_back(p.at(0).get<std::string>(), p.at(1).get<double>());
            if (!f.at("flood").is_null())
                run.flood =
                    FloodSample{f["flood"].at(0).get<int>(), f["flood"].at(1).get<double>()};
            const json& b = f.at("bias");
            run.row.bias = {b.at(0).get<std::size_t>(), b.at(1).get<std::size_t>(),
                            b.at(2).get<std::size_t>(), b.at(3).get<std::size_t>()};
            r.runs.push_back(std::move(run));
        }
        return r;
    } catch (const json::exception& e) {
        throw std::runtime_error(std::string("not a frame record (") + e.what() + ")");
    }
}

CaptureProgress CaptureProgress::start(const fs::path& dir, const std::string& identity,
                                       int totalFrames) {
    CaptureProgress p(dir);
    if (fs::is_regular_file(p.journal())) {
        std::ifstream in(p.journal());
        std::size_t lines = 0;
        for (std::string line; std::getline(in, line);) ++lines;
        std::cout << "note: discarding the unfinished capture in " << dir.string() << " ("
                  << (lines > 0 ? lines - 1 : 0)
                  << " frames finished); --resume would have continued it\n";
    }
    // An earlier run's frames and pictures would otherwise mix with this run's: a script with
    // fewer frames or other methods leaves the rest looking like its own.
    for (const char* old : {"progress.jsonl", "resume", "frames", "report"}) {
        std::error_code ec;
        fs::remove_all(dir / old, ec);
        if (ec)
            throw InputError((dir / old).string() + ": cannot remove the earlier run's " + old +
                             " (" + ec.message() + ")");
    }
    makeOutputFolder(dir / "resume", "--out");
    writeFileAtomically(p.journal(), headerLine(identity, totalFrames) + "\n");
    return p;
}

std::optional<CaptureProgress>
CaptureProgress::resume(const fs::path& dir, const std::string& identity, int totalFrames) {
    CaptureProgress p(dir);
    if (!fs::exists(p.journal())) return std::nullopt;
    // The frame in flight when the run was killed may have left a file half-written under its
    // temporary name: it is rendered again, so that file goes.
    removeKilledTemporaries(dir);
    const std::string text = readInputFile(p.journal(), "--resume", kJournalLimitMiB);
    std::istringstream in(text);
    std::string header;
    std::getline(in, header);
    json h;
    try {
        h = json::parse(header);
    } catch (const json::exception&) {
    }
    const std::string where = p.journal().string();
    if (!h.is_object() || h.value("floodlightCapture", 0) != 1)
        throw InputError(where + ": not a capture's progress (run without --resume to start over)");
    if (h.value("identity", "") != identity || h.value("frames", -1) != totalFrames)
        throw InputError(where + ": the unfinished run there is of another script, scene or "
                                 "build of its inputs; run without --resume to start it over");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::string kept = header + "\n";
    bool torn = false;
    for (std::size_t n = 0; n < lines.size(); ++n) {
        try {
            p.records_.push_back(parseRecordLine(lines[n]));
            kept += lines[n] + "\n";
        } catch (const std::runtime_error& e) {
            // A run killed while writing its last line leaves it torn: that frame was in flight.
            torn = n + 1 == lines.size();
            if (torn) break;
            throw InputError(where + ": line " + std::to_string(n + 2) + ": " + e.what() +
                             " (damaged; run without --resume to start over)");
        }
    }
    if (torn) writeFileAtomically(p.journal(), kept); // appends must not follow the torn line
    makeOutputFolder(dir / "resume", "--out");
    return p;
}

fs::path CaptureProgress::statePath(int size, int frame) const {
    return dir_ / "resume" /
           ("state_" + std::to_string(size) + "_" + std::to_string(frame) + ".exr");
}

void CaptureProgress::append(const std::string& line) {
    std::ofstream out(journal(), std::ios::app | std::ios::binary);
    out << line << '\n';
    out.flush();
    if (!out) throw std::runtime_error(journal().string() + ": cannot append the frame's record");
}

void CaptureProgress::save(const FrameRecord& record, const ScorerState& state,
                           const std::vector<std::size_t>& worstRuns) {
    const fs::path statePicture = statePath(record.size, record.frame);
    {
        const FloatImage& ref = state.previousReference;
        std::vector<ExrChannel> channels{{"reference.visibility", ref.data},
                                         {"reference.receivers", state.previousReceivers.data},
                                         {"reference.depth", state.previousDepth.data}};
        for (std::size_t k = 0; k < state.previous.size(); ++k)
            channels.push_back({std::to_string(k) + ".visibility", state.previous[k].data});
        // Uncompressed: ZIP made this file about two thirds of keeping the progress (193 ->
        // 66 ms a frame at 512² with nine methods on llvmpipe's host), for a file that lives
        // until the next frame, or while it holds a method's worst frame.
        writeExr(statePicture, ref.width, ref.height, channels, ExrCompression::None);
    }
    append(recordLine(record));
    // The frame is finished: the files it supersedes go, unless a run's worst frame is there.
    std::vector<fs::path> superseded{state_};
    for (const std::size_t run : worstRuns) {
        if (worst_.size() <= run) worst_.resize(run + 1);
        superseded.push_back(std::exchange(worst_[run], statePicture));
    }
    state_ = statePicture;
    std::error_code ec;
    for (const fs::path& old : superseded)
        if (!old.empty() && old != state_ &&
            std::find(worst_.begin(), worst_.end(), old) == worst_.end())
            fs::remove(old, ec);
    ++saved_;
}

ScorerState CaptureProgress::loadState(int size, int frame, std::size_t runs) const {
    const fs::path file = statePath(size, frame);
    int w = 0, h = 0;
    const auto channels = readChannels(file, w, h);
    ScorerState s;
    s.previousReference = imageFrom(channels, "reference.visibility", w, h, file);
    s.previousReceivers = imageFrom(channels, "reference.receivers", w, h, file);
    s.previousDepth = imageFrom(channels, "reference.depth", w, h, file);
    for (std::size_t k = 0; k < runs; ++k)
        s.previous.push_back(imageFrom(channels, std::to_string(k) + ".visibility", w, h, file));
    return s;
}

WorstPictures CaptureProgress::loadWorst(int size, std::size_t k, int frame) const {
    const fs::path file = statePath(size, frame);
    int w = 0, h = 0;
    const auto channels = readChannels(file, w, h);
    return {imageFrom(channels, std::to_string(k) + ".visibility", w, h, file),
            imageFrom(channels, "reference.visibility", w, h, file),
            imageFrom(channels, "reference.receivers", w, h, file)};
}

void CaptureProgress::adopt(std::optional<std::pair<int, int>> state,
                            const std::vector<std::pair<std::size_t, std::pair<int, int>>>& worst) {
    if (state) state_ = statePath(state->first, state->second);
    for (const auto& [run, at] : worst) {
        if (worst_.size() <= run) worst_.resize(run + 1);
        worst_[run] = statePath(at.first, at.second);
    }
}

void CaptureProgress::finish() {
    std::error_code ec;
    fs::remove(journal(), ec);
    fs::remove_all(dir_ / "resume", ec);
}

} // namespace fl::app
