#include "CaptureScript.h"

#include <renderer/soft/PenumbraMap.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace fl::app {

namespace {

using Json = nlohmann::json;

// Throws "FIELD: problem"; parseCaptureScript prefixes the file name.
[[noreturn]] void fail(const std::string& field, const std::string& problem) {
    throw CaptureScriptError(field + ": " + problem);
}

int readInt(const Json& j, const std::string& field, int lo, int hi) {
    if (!j.is_number_integer()) fail(field, "expected an integer");
    const auto v = j.get<long long>();
    if (v < lo || v > hi)
        fail(field, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                        ", got " + std::to_string(v));
    return static_cast<int>(v);
}

glm::vec3 readVec3(const Json& j, const std::string& field) {
    if (!j.is_array() || j.size() != 3) fail(field, "expected [x, y, z]");
    glm::vec3 v{0.0f};
    for (int k = 0; k < 3; ++k) {
        const Json& c = j[static_cast<std::size_t>(k)];
        if (!c.is_number()) fail(field, "expected [x, y, z] numbers");
        v[k] = c.get<float>();
        if (!std::isfinite(v[k])) fail(field, "not finite");
    }
    return v;
}

void checkKeys(const Json& obj, const std::string& field, const std::set<std::string>& known) {
    if (!obj.is_object()) fail(field, "expected an object");
    for (const auto& [key, value] : obj.items())
        if (!known.count(key)) fail(field + "." + key, "unknown field");
}

void parseCamera(const Json& j, const std::filesystem::path& dir, CaptureScript& s) {
    checkKeys(j, "camera", {"frames", "path", "file", "fov", "interpolation", "keys"});
    if (!j.contains("frames")) fail("camera.frames", "missing (the number of frames)");
    s.frames = readInt(j["frames"], "camera.frames", 1, 100000);
    const bool hasKeys = j.contains("keys"), hasFile = j.contains("file");
    if (j.contains("path")) {
        if (j["path"] != "default") fail("camera.path", "expected \"default\"");
        if (hasKeys || hasFile) fail("camera.path", "give one of path, file and keys");
        return;
    }
    if (hasFile) {
        if (hasKeys) fail("camera.file", "give one of path, file and keys");
        if (!j["file"].is_string()) fail("camera.file", "expected a file name");
        try {
            s.camera = readCameraPath(dir / j["file"].get<std::string>());
        } catch (const std::runtime_error& e) {
            fail("camera.file", e.what());
        }
        return;
    }
    if (!hasKeys) fail("camera", "missing \"path\": \"default\", \"file\" or \"keys\"");
    try {
        s.camera = parseCameraPath(j.dump());
    } catch (const std::runtime_error& e) {
        throw CaptureScriptError(std::string("camera.") + e.what());
    }
}

void parseLight(const Json& j, CaptureScript& s) {
    checkKeys(j, "light", {"radius", "keys"});
    if (j.contains("radius")) {
        if (!j["radius"].is_number()) fail("light.radius", "expected a number");
        const float r = j["radius"].get<float>();
        if (!std::isfinite(r) || r < 0.0f) fail("light.radius", "must be a finite number >= 0");
        s.lightRadius = r;
    }
    if (j.contains("keys")) {
        if (!j["keys"].is_array() || j["keys"].empty())
            fail("light.keys", "expected an array of [x, y, z] positions");
        for (std::size_t i = 0; i < j["keys"].size(); ++i)
            s.lightKeys.push_back(readVec3(j["keys"][i], "light.keys[" + std::to_string(i) + "]"));
    }
}

MethodSpec parseMethodEntry(const Json& j, const std::string& field) {
    MethodSpec m;
    Json options = Json::object();
    std::string name;
    if (j.is_string()) {
        // "name" or "name:option": the option is the preset of pcss, the kernel of pcf and the
        // pass count of the flooding methods.
        const std::string text = j.get<std::string>();
        const auto colon = text.find(':');
        name = text.substr(0, colon);
        if (colon != std::string::npos) {
            const std::string opt = text.substr(colon + 1);
            if (name == "pcss") {
                options["preset"] = opt;
            } else {
                try {
                    std::size_t used = 0;
                    const int v = std::stoi(opt, &used);
                    if (used != opt.size()) throw std::invalid_argument(opt);
                    options[name == "pcf" ? "kernel" : "passes"] = v;
                } catch (const std::exception&) {
                    fail(field, "\"" + text + "\": expected an integer after ':'");
                }
            }
        }
        m.label = text;
    } else if (j.is_object()) {
        checkKeys(j, field, {"method", "preset", "kernel", "passes", "label"});
        if (!j.contains("method") || !j["method"].is_string())
            fail(field + ".method", "missing (a method name)");
        name = j["method"].get<std::string>();
        options = j;
    } else {
        fail(field, "expected a method name or {\"method\": ..}");
    }
    const auto method = parseMethod(name);
    if (!method) {
        std::string known;
        for (ShadowMethod k : allShadowMethods()) {
            known += ' ';
            known += methodName(k);
        }
        fail(field, "unknown method \"" + name + "\" (known:" + known + ")");
    }
    m.method = *method;
    const bool flooding = m.method == ShadowMethod::JfaL || m.method == ShadowMethod::FloodL ||
                          m.method == ShadowMethod::JfaE || m.method == ShadowMethod::FloodE;
    std::string suffix;
    if (options.contains("preset")) {
        if (m.method != ShadowMethod::Pcss) fail(field + ".preset", "only pcss takes a preset");
        if (!options["preset"].is_string()) fail(field + ".preset", "expected \"16/24\" etc.");
        m.presetText = options["preset"].get<std::string>();
        m.pcss = parsePcssPreset(m.presetText);
        if (!m.pcss)
            fail(field + ".preset",
                 "unknown PCSS preset \"" + m.presetText + "\" (known: 16/16, 16/24, 32/64)");
        suffix = ":" + m.presetText;
    }
    if (options.contains("kernel")) {
        if (m.method != ShadowMethod::Pcf) fail(field + ".kernel", "only pcf takes a kernel");
        m.pcfKernel = readInt(options["kernel"], field + ".kernel", 1, kMaxPcfKernel);
        suffix = ":" + std::to_string(*m.pcfKernel);
    }
    if (options.contains("passes")) {
        if (!flooding) fail(field + ".passes", "only the flooding methods take passes");
        m.passes = readInt(options["passes"], field + ".passes", 1, 13);
        suffix = ":" + std::to_string(*m.passes);
    }
    if (j.is_object()) {
        m.label = name + suffix;
        if (j.contains("label")) {
            if (!j["label"].is_string() || j["label"].get<std::string>().empty())
                fail(field + ".label", "expected a non-empty string");
            m.label = j["label"].get<std::string>();
        }
    }
    return m;
}

} // namespace

CaptureScript parseCaptureScript(const std::string& text, const std::filesystem::path& file) {
    const std::string name = file.string();
    Json j;
    try {
        j = Json::parse(text);
    } catch (const Json::parse_error& e) {
        throw CaptureScriptError(name + ": not valid JSON: " + e.what());
    }
    CaptureScript s;
    s.file = file;
    const std::filesystem::path dir = file.parent_path();
    try {
        checkKeys(j, "script",
                  {"scene", "camera", "light", "resolutions", "shadowMap", "jfaPasses", "reference",
                   "methods", "saveFrames", "comment"});
        if (j.contains("scene")) {
            if (!j["scene"].is_string()) fail("scene", "expected \"default\" or a file name");
            if (j["scene"] != "default") s.scene = dir / j["scene"].get<std::string>();
        }
        if (!j.contains("camera")) fail("camera", "missing ({\"frames\": N, ...})");
        parseCamera(j["camera"], dir, s);
        if (j.contains("light")) parseLight(j["light"], s);
        if (j.contains("resolutions")) {
            const Json& r = j["resolutions"];
            if (!r.is_array() || r.empty()) fail("resolutions", "expected [[W, H], ...]");
            for (std::size_t i = 0; i < r.size(); ++i) {
                const std::string f = "resolutions[" + std::to_string(i) + "]";
                if (!r[i].is_array() || r[i].size() != 2) fail(f, "expected [W, H]");
                s.resolutions.emplace_back(readInt(r[i][0], f + "[0]", 1, 8192),
                                           readInt(r[i][1], f + "[1]", 1, 8192));
            }
        } else {
            s.resolutions = {{512, 512}};
        }
        if (j.contains("shadowMap")) {
            const Json& m = j["shadowMap"];
            checkKeys(m, "shadowMap", {"provider", "size"});
            if (m.contains("provider")) {
                if (m["provider"] != "uniform" && m["provider"] != "tsm")
                    fail("shadowMap.provider", "expected \"uniform\" or \"tsm\"");
                s.shadowMapProvider = m["provider"].get<std::string>();
            }
            if (m.contains("size"))
                s.shadowMapSize = readInt(m["size"], "shadowMap.size", 16, 8192);
        }
        if (j.contains("jfaPasses")) s.jfaPasses = readInt(j["jfaPasses"], "jfaPasses", 1, 13);
        if (j.contains("reference")) {
            const Json& r = j["reference"];
            checkKeys(r, "reference", {"samples", "mapSize"});
            if (r.contains("samples"))
                s.reference.samples = readInt(r["samples"], "reference.samples", 1, 4096);
            if (r.contains("mapSize"))
                s.reference.mapSize = readInt(r["mapSize"], "reference.mapSize", 16, 8192);
        }
        if (!j.contains("methods")) fail("methods", "missing (a list of method names)");
        if (!j["methods"].is_array() || j["methods"].empty())
            fail("methods", "expected a non-empty list of methods");
        std::set<std::string> labels;
        for (std::size_t i = 0; i < j["methods"].size(); ++i) {
            const std::string f = "methods[" + std::to_string(i) + "]";
            MethodSpec m = parseMethodEntry(j["methods"][i], f);
            if (!labels.insert(m.label).second)
                fail(f, "\"" + m.label + "\" is listed twice (give a \"label\")");
            s.methods.push_back(std::move(m));
        }
        if (j.contains("saveFrames")) {
            if (!j["saveFrames"].is_boolean()) fail("saveFrames", "expected true or false");
            s.saveFrames = j["saveFrames"].get<bool>();
        }
        // Pass counts beyond what the map holds are one clear error here, not a failure later.
        for (const MethodSpec& m : s.methods) {
            PenumbraSettings ps;
            ps.passes = m.passes.value_or(s.jfaPasses);
            try {
                (void)penumbraPlan(ps, s.shadowMapSize);
            } catch (const std::invalid_argument& e) {
                fail(m.passes ? "methods (" + m.label + ").passes" : std::string("jfaPasses"),
                     e.what());
            }
        }
    } catch (const CaptureScriptError& e) {
        throw CaptureScriptError(name + ": " + e.what());
    }
    return s;
}

CaptureScript readCaptureScript(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw CaptureScriptError(file.string() + ": cannot open");
    std::ostringstream text;
    text << in.rdbuf();
    return parseCaptureScript(text.str(), file);
}

glm::vec3 lightPositionAt(const std::vector<glm::vec3>& keys, int i, int n) {
    if (keys.empty()) return glm::vec3(0.0f);
    if (keys.size() == 1 || n <= 1) return keys.front();
    const float u =
        static_cast<float>(i) / static_cast<float>(n - 1) * static_cast<float>(keys.size() - 1);
    const auto k = std::min(static_cast<std::size_t>(u), keys.size() - 2);
    return glm::mix(keys[k], keys[k + 1], u - static_cast<float>(k));
}

RenderSettings settingsFor(const RenderSettings& base, const MethodSpec& m) {
    RenderSettings s = base;
    s.method = m.method;
    if (m.passes) s.penumbra.passes = *m.passes;
    if (m.pcfKernel) s.filtered.pcfKernel = *m.pcfKernel;
    if (m.pcss) s.filtered.pcss = *m.pcss;
    return s;
}

} // namespace fl::app
