#include <app/CaptureScript.h>

#include <scene/Ground.h>

#include <base/InputFile.h>
#include <base/Numbers.h>
#include <base/Text.h>

#include <io/JsonText.h>
#include <renderer/soft/PenumbraMap.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace fl::app {

namespace {

using Json = nlohmann::json;

// Throws "FIELD: problem"; parseCaptureScript prefixes the file name.
[[noreturn]] void fail(const std::string& field, const std::string& problem) {
    throw CaptureScriptError(field + ": " + problem);
}

// A number of the script, by the rule of the command line (base/Numbers.h).
double readNumber(const Json& j, const std::string& field, double lo, double hi, bool integer) {
    try {
        return jsonNumber(j, lo, hi, integer);
    } catch (const std::runtime_error& e) {
        fail(field, e.what());
    }
}

int readInt(const Json& j, const std::string& field, int lo, int hi) {
    return static_cast<int>(readNumber(j, field, lo, hi, true));
}

glm::vec3 readVec3(const Json& j, const std::string& field) {
    if (!j.is_array() || j.size() != 3) fail(field, "expected [x, y, z]");
    glm::vec3 v{0.0f};
    for (int k = 0; k < 3; ++k) {
        const Json& c = j[static_cast<std::size_t>(k)];
        v[k] = static_cast<float>(readNumber(c, field + "[" + std::to_string(k) + "]",
                                             -kMaxWorldCoordinate, kMaxWorldCoordinate, false));
    }
    return v;
}

void checkKeys(const Json& obj, const std::string& field, const std::set<std::string>& known) {
    if (!obj.is_object()) fail(field, "expected an object");
    for (const auto& [key, value] : obj.items())
        if (!known.count(key)) fail(field + "." + key, "unknown field");
}

// kCameraPathNames as the messages quote them: "default", "auto", "orbit".
std::string pathNames() {
    std::string out;
    for (std::string_view n : kCameraPathNames)
        out += (out.empty() ? "\"" : ", \"") + std::string(n) + "\"";
    return out;
}

void parseCamera(const Json& j, const std::filesystem::path& dir, CaptureScript& s) {
    checkKeys(j, "camera", {"frames", "path", "file", "fov", "interpolation", "keys"});
    if (!j.contains("frames")) fail("camera.frames", "missing (the number of frames)");
    s.frames = readInt(j["frames"], "camera.frames", 1, kMaxCaptureFrames);
    const bool hasKeys = j.contains("keys"), hasFile = j.contains("file");
    if (j.contains("path")) {
        const std::string path = j["path"].is_string() ? j["path"].get<std::string>() : "";
        if (std::find(kCameraPathNames.begin(), kCameraPathNames.end(), path) ==
            kCameraPathNames.end())
            fail("camera.path", "expected one of " + pathNames());
        if (hasKeys || hasFile) fail("camera.path", "give one of path, file and keys");
        s.cameraPath = path;
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
    if (!hasKeys) fail("camera", "missing \"path\" (" + pathNames() + "), \"file\" or \"keys\"");
    try {
        s.camera = parseCameraPath(j.dump());
    } catch (const std::runtime_error& e) {
        throw CaptureScriptError(std::string("camera.") + e.what());
    }
}

void parseLight(const Json& j, CaptureScript& s) {
    checkKeys(j, "light", {"radius", "size", "keys"});
    if (j.contains("radius") && j.contains("size"))
        fail("light.size", "give radius (scene units) or size (a fraction of the model's radius)");
    if (j.contains("size"))
        s.lightSize = static_cast<float>(readNumber(j["size"], "light.size", 0.0, 1.0, false));
    if (j.contains("radius")) {
        s.lightRadius = static_cast<float>(
            readNumber(j["radius"], "light.radius", 0.0, kMaxWorldCoordinate, false));
    }
    if (j.contains("keys")) {
        if (!j["keys"].is_array() || j["keys"].empty())
            fail("light.keys", "expected an array of [x, y, z] positions");
        for (std::size_t i = 0; i < j["keys"].size(); ++i)
            s.lightKeys.push_back(readVec3(j["keys"][i], "light.keys[" + std::to_string(i) + "]"));
    }
}

// A JSON value as an option's text ("16/24", "5", "0.25", "true").
std::string optionText(const Json& v) {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_number_integer()) return std::to_string(v.get<long long>());
    if (v.is_number()) {
        std::ostringstream out;
        out << std::setprecision(9) << v.get<double>();
        return out.str();
    }
    return v.dump();
}

// Why `key` is not an option of method `d`: another method's option, or no option at all.
std::string unknownKeyProblem(const MethodDescriptor& d, const std::string& name,
                              const std::string& key) {
    const std::string takers = methodNamesWhere(
        [&key](const MethodDescriptor& other) { return other.option(key) != nullptr; });
    if (!takers.empty()) return "only " + takers + " take(s) \"" + key + "\"";
    std::string keys;
    for (const MethodOption* k : d.options) {
        if (!keys.empty()) keys += ", ";
        keys += k->key;
    }
    if (keys.empty()) keys = "no options";
    std::string problem = "unknown key (";
    problem += name;
    problem += " takes: ";
    problem += keys;
    problem += ")";
    return problem;
}

MethodSpec parseMethodEntry(const Json& j, const std::string& field) {
    MethodSpec m;
    std::string name;
    std::vector<std::pair<std::string, std::string>> given; // key, value text
    if (j.is_string()) {
        // "name" or "name:VALUE": VALUE is the method's first option (pcss: preset, pcf: kernel,
        // the flooding methods: passes).
        const std::string text = j.get<std::string>();
        const auto colon = text.find(':');
        name = text.substr(0, colon);
        if (colon != std::string::npos) {
            const MethodDescriptor* d = findMethod(name);
            if (d && d->options.empty()) fail(field, "\"" + name + "\" takes no option");
            if (d) given.emplace_back(d->options.front()->key, text.substr(colon + 1));
        }
        m.label = text;
    } else if (j.is_object()) {
        if (!j.contains("method") || !j["method"].is_string())
            fail(field + ".method", "missing (a method name)");
        name = j["method"].get<std::string>();
        for (const auto& [key, value] : j.items())
            if (key != "method" && key != "label") given.emplace_back(key, optionText(value));
    } else {
        fail(field, "expected a method name or {\"method\": ..}");
    }
    const MethodDescriptor* d = findMethod(name);
    if (!d) fail(field, "unknown method \"" + name + "\" (known: " + methodNames() + ")");
    m.method = std::string(d->name);
    std::string suffix;
    for (const auto& [key, value] : given) {
        const std::string f = field + "." + key;
        const MethodOption* o = d->option(key);
        if (!o) fail(f, unknownKeyProblem(*d, name, key));
        const std::string problem = checkOptionValue(*o, value);
        if (!problem.empty()) fail(f, problem);
        m.options.set(o->flag, value);
        suffix = ":" + value;
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

void parseResolutions(const Json& r, CaptureScript& s) {
    if (!r.is_array() || r.empty()) fail("resolutions", "expected [[W, H], ...]");
    for (std::size_t i = 0; i < r.size(); ++i) {
        const std::string f = "resolutions[" + std::to_string(i) + "]";
        if (!r[i].is_array() || r[i].size() != 2) fail(f, "expected [W, H]");
        s.resolutions.emplace_back(readInt(r[i][0], f + "[0]", 1, 8192),
                                   readInt(r[i][1], f + "[1]", 1, 8192));
    }
}

void parseShadowMap(const Json& m, CaptureScript& s) {
    std::set<std::string> keys{"provider", "size"};
    for (const TsmOption& t : tsmOptions()) keys.emplace(t.key);
    checkKeys(m, "shadowMap", keys);
    if (m.contains("provider")) {
        if (m["provider"] != "uniform" && m["provider"] != "tsm")
            fail("shadowMap.provider", "expected \"uniform\" or \"tsm\"");
        s.shadowMapProvider = m["provider"].get<std::string>();
    }
    if (m.contains("size")) s.shadowMapSize = readInt(m["size"], "shadowMap.size", 16, 8192);
    for (const TsmOption& t : tsmOptions())
        if (m.contains(t.key))
            s.tsm.*t.field = static_cast<float>(readNumber(
                m[std::string(t.key)], "shadowMap." + std::string(t.key), t.min, t.max, false));
}

// The --jfa-passes option's own validation: 1 to 13, or "auto".
void parseJfaPasses(const Json& p, CaptureScript& s) {
    if (p.is_number_integer())
        s.jfaPasses = std::to_string(p.get<long long>());
    else if (p.is_string())
        s.jfaPasses = p.get<std::string>();
    else
        fail("jfaPasses", "expected an integer or \"auto\"");
    if (const std::string bad = checkOptionValue(floodPassesOption(), s.jfaPasses); !bad.empty())
        fail("jfaPasses", bad);
}

// The keys a "reference" object may hold: "kind" and every ground truth's options.
std::set<std::string> referenceKeys() {
    std::set<std::string> keys{"kind"};
    for (const MethodDescriptor& m : methodTable())
        if (!m.truth.empty())
            for (const MethodOption* o : m.options) keys.emplace(o->key);
    return keys;
}

void parseReference(const Json& r, CaptureScript& s) {
    checkKeys(r, "reference", referenceKeys());
    if (r.contains("kind")) {
        if (!r["kind"].is_string())
            fail("reference.kind", "expected \"" + groundTruthKinds() + "\"");
        s.reference.kind = r["kind"].get<std::string>();
        try {
            (void)s.reference.method();
        } catch (const std::invalid_argument&) {
            fail("reference.kind",
                 "\"" + s.reference.kind + "\" is not one of " + groundTruthKinds());
        }
    }
    // Each option by the chosen ground truth's row of the method table (its range or
    // choices), as the methods' own options are checked.
    const MethodDescriptor& truth = s.reference.method();
    for (const auto& [key, value] : r.items()) {
        if (key == "kind") continue;
        const std::string f = "reference." + key;
        const MethodOption* o = truth.option(key);
        if (!o) fail(f, "the " + s.reference.kind + " reference does not take it");
        const std::string given = optionText(value);
        if (const std::string bad = checkOptionValue(*o, given); !bad.empty()) fail(f, bad);
        s.reference.options.set(o->flag, given);
    }
}

void parseMethods(const Json& j, CaptureScript& s) {
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
}

void parseGround(const Json& g, CaptureScript& s) {
    if (!g.is_string() || !parseGroundMode(g.get<std::string>())) {
        std::string names; // "auto|on|off", from the one list
        for (std::string_view n : kGroundModeNames)
            names += (names.empty() ? "" : "|") + std::string(n);
        fail("ground", "expected \"" + names + "\"");
    }
    s.ground = g.get<std::string>();
}

void parseAnimation(const Json& a, CaptureScript& s) {
    checkKeys(a, "animation", {"name", "start", "fps"});
    if (a.contains("name")) {
        const Json& n = a["name"];
        if (n.is_number_integer() && n.get<long long>() >= 0)
            s.animation.name = std::to_string(n.get<long long>());
        else if (n.is_string())
            s.animation.name = n.get<std::string>();
        else
            fail("animation.name", "expected \"all\", \"none\", a name or an index");
    }
    if (a.contains("start"))
        s.animation.start =
            readNumber(a["start"], "animation.start", 0.0, kMaxAnimationTime, false);
    if (a.contains("fps"))
        s.animation.fps = readNumber(a["fps"], "animation.fps", 0.0, 1000.0, false);
}

// Options the map cannot use (JFA passes beyond its size) are one clear error here, not a
// failure later. The eye-space methods are checked against each resolution.
void checkMethodsFit(const CaptureScript& s) {
    for (const MethodSpec& m : s.methods) {
        const MethodDescriptor& d = methodOrThrow(m.method);
        if (!d.check) continue;
        MethodOptions o = m.options;
        if (!o.has(floodPassesOption().flag)) o.set(floodPassesOption().flag, s.jfaPasses);
        for (const auto& [w, h] : s.resolutions) try {
                d.check(o, d, s.shadowMapSize, w, h);
            } catch (const std::invalid_argument& e) {
                fail((m.options.has(floodPassesOption().flag) ? "methods (" + m.label + ").passes"
                                                              : std::string("jfaPasses")) +
                         " at " + std::to_string(w) + "x" + std::to_string(h),
                     e.what());
            }
    }
}

// Every field of the script's top-level object, in the order the errors are reported.
void parseScriptFields(const Json& j, const std::filesystem::path& dir, CaptureScript& s) {
    checkKeys(j, "script",
              {"scene", "camera", "light", "resolutions", "shadowMap", "jfaPasses", "reference",
               "methods", "saveFrames", "ground", "animation", "comment"});
    if (j.contains("scene")) {
        if (!j["scene"].is_string()) fail("scene", "expected \"default\" or a file name");
        if (j["scene"] != "default") s.scene = dir / j["scene"].get<std::string>();
    }
    if (!j.contains("camera")) fail("camera", "missing ({\"frames\": N, ...})");
    parseCamera(j["camera"], dir, s);
    if (j.contains("light")) parseLight(j["light"], s);
    if (j.contains("resolutions"))
        parseResolutions(j["resolutions"], s);
    else
        s.resolutions = {{512, 512}};
    if (j.contains("shadowMap")) parseShadowMap(j["shadowMap"], s);
    if (j.contains("jfaPasses")) parseJfaPasses(j["jfaPasses"], s);
    if (j.contains("reference")) parseReference(j["reference"], s);
    parseMethods(j, s);
    if (j.contains("ground")) parseGround(j["ground"], s);
    if (j.contains("animation")) parseAnimation(j["animation"], s);
    if (j.contains("saveFrames")) {
        if (!j["saveFrames"].is_boolean()) fail("saveFrames", "expected true or false");
        s.saveFrames = j["saveFrames"].get<bool>();
    }
    checkMethodsFit(s);
}

} // namespace

CaptureScript parseCaptureScript(const std::string& text, const std::filesystem::path& file) {
    const std::string name = file.string();
    Json j;
    try {
        j = parseJsonText(text);
    } catch (const std::runtime_error& e) {
        throw CaptureScriptError(name + ": " + e.what());
    }
    CaptureScript s;
    s.file = file;
    try {
        parseScriptFields(j, file.parent_path(), s);
    } catch (const CaptureScriptError& e) {
        throw CaptureScriptError(name + ": " + e.what());
    }
    return s;
}

CaptureScript readCaptureScript(const std::filesystem::path& file) {
    // Regular files within the text limit only: a FIFO would be read forever.
    try {
        return parseCaptureScript(readInputFile(file, "capture script", kTextInputLimitMiB), file);
    } catch (const InputFileError& e) {
        throw CaptureScriptError(e.what());
    }
}

std::string referenceText(const CaptureScript::Reference& r) {
    const MethodDescriptor& truth = r.method();
    return cat(r.kind, ": ", truth.describe ? truth.describe(r.options) : std::string(truth.help));
}

RenderSettings settingsFor(const RenderSettings& base, const MethodSpec& m) {
    RenderSettings s = base;
    s.method = m.method;
    for (const auto& [flag, value] : m.options.values()) s.options.set(flag, value);
    return s;
}

} // namespace fl::app
