// The command-line options the subcommands share, and the validators every option uses.
#include <app/Common.h>

#include <scene/Camera.h>
#include <scene/Ground.h>

#include <base/InputFile.h>
#include <base/Text.h>

#include <cstdio>

namespace fl::app {

namespace {
constexpr int kMaxImageSize = 8192; // per side: 8192² RGBA16F + R32F + depth ≈ 768 MiB
constexpr int kMaxShadowMapSize = 8192;

// --shadow-map-size, --shadow-map and TSM's stability steps.
void addShadowMapOptions(CLI::App& cmd, SceneOptions& o) {
    cmd.add_option("--shadow-map-size", o.shadowMapSize, "Shadow map texels per side")
        ->check(integer(16, kMaxShadowMapSize))
        ->capture_default_str();
    cmd.add_option(
           "--shadow-map", o.shadowMap,
           "Shadow-map provider: uniform (fitted to what casts shadows) or tsm (trapezoidal)")
        ->check(CLI::IsMember({"uniform", "tsm"}))
        ->capture_default_str();
    for (const TsmOption& t : tsmOptions()) // out of range: a usage error naming flag and range
        cmd.add_option(std::string(t.flag), o.tsm.*t.field, std::string(t.help))
            ->check(number(t.min, t.max))
            ->capture_default_str();
}

// --method (its help lists the table), every method's options, the depth bias and --timing.
void addMethodChoice(CLI::App& cmd, SceneOptions& o) {
    std::string methodHelp = "Shadow method:";
    std::vector<std::string> names;
    for (const MethodDescriptor& m : methodTable()) {
        methodHelp += "\n  " + std::string(m.name) + ": " + std::string(m.help);
        names.emplace_back(m.name);
    }
    cmd.add_option("--method", o.method, methodHelp)
        ->check(CLI::IsMember(names))
        ->capture_default_str();
    addMethodOptions(cmd, o);
    cmd.add_option("--bias-slope", o.slopeBias,
                   "Slope-scaled depth bias (polygon offset factor, in light depth)")
        ->check(number(0.0, 64.0))
        ->capture_default_str();
    cmd.add_option("--bias-constant", o.constantBias,
                   "Constant depth bias (polygon offset units, in light depth)")
        ->check(number(0.0, 4096.0))
        ->capture_default_str();
    cmd.add_option("--timing", o.timing, "Pass timing: auto, query (GL timers), finish (glFinish)")
        ->check(CLI::IsMember({"auto", "query", "finish"}))
        ->capture_default_str();
}

// The camera, the scene's clock and the added ground.
void addViewOptions(CLI::App& cmd, SceneOptions& o) {
    cmd.add_option(
           "--camera", o.camera,
           "auto (frame the scene; on an added ground, the model and its shadow; a skinned or "
           "animated model as it stands at --time), a glTF camera index N (the file's own), or "
           "default: auto for a file, the built-in scene's own camera for it")
        ->capture_default_str();
    cmd.add_option("--eye", o.eye, "Camera position x,y,z (with --target)")
        ->check(number())
        ->delimiter(',')
        ->expected(3);
    cmd.add_option("--target", o.target, "Camera target x,y,z (with --eye)")
        ->check(number())
        ->delimiter(',')
        ->expected(3);
    cmd.add_option("--fov", o.fov,
                   "Vertical field of view, degrees. Default: the glTF camera's, else " +
                       fixed(kAutoViewFovDegrees, 0))
        ->check(number(1.0, 170.0));
    cmd.add_option("--time", o.time,
                   "Seconds into the scene's animations (glTF animations, skins, morph targets)")
        ->check(number(0.0, kMaxAnimationTime))
        ->capture_default_str();
    cmd.add_option("--animation", o.animation,
                   "Which animations play: all, none, or one by name or index")
        ->capture_default_str();
    cmd.add_option("--ground", o.ground,
                   "A ground plane to receive the shadow: auto (added when the scene has no "
                   "surface under it, as a single model has not), on, off")
        ->check(CLI::IsMember(
            std::vector<std::string>(kGroundModeNames.begin(), kGroundModeNames.end())))
        ->capture_default_str();
}

// --light-dir or --light-position: the light placed by hand.
void addLightPlacement(CLI::App& cmd, SceneOptions& o) {
    auto* dir = cmd.add_option("--light-dir", o.lightDir,
                               "Light travel direction x,y,z (0,-1,0: straight down): moves the "
                               "scene's light 2.5 scene radii back along it")
                    ->check(number(-kMaxWorldCoordinate, kMaxWorldCoordinate))
                    ->delimiter(',')
                    ->expected(3);
    cmd.add_option("--light-position", o.lightPosition,
                   "Light position x,y,z: moves the scene's light there, aimed at the scene's "
                   "centre")
        ->check(number(-kMaxWorldCoordinate, kMaxWorldCoordinate))
        ->delimiter(',')
        ->expected(3)
        ->excludes(dir);
}

} // namespace

void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool sceneAsOption) {
    const std::string sceneHelp = "glTF 2.0 scene (.gltf/.glb, at most " +
                                  std::to_string(kSceneInputLimitMiB) +
                                  " MiB; a .gltf's buffers and images are read where their "
                                  "relative URIs point from its folder, '..' included); default: "
                                  "the built-in scene";
    cmd.add_option(sceneAsOption ? "--scene" : "scene", o.scene, sceneHelp);
    // 0 is allowed: a point light, for which every soft method gives exactly the hard shadows.
    CLI::Option* radius =
        cmd.add_option("--light-radius", o.lightRadius,
                       "Disk light radius in scene units (0 = a point light: hard shadows); at "
                       "most the light's distance to the scene's centre. Default: the scene "
                       "light's extras.radius, else --light-size " +
                           fixed(kDefaultLightSize, 2))
            ->check(number(0.0, kMaxWorldCoordinate));
    cmd.add_option("--light-size", o.lightSize,
                   "Disk light radius as a fraction of the model's bounding radius (the bounds "
                   "without an added ground): the same softness on any model. Default " +
                       fixed(kDefaultLightSize, 2) +
                       " where the scene's light gives no radius (extras.radius)")
        ->check(number(0.0, 1.0))
        ->excludes(radius);
    cmd.add_option("--shader-dir", o.shaderDir,
                   "Load shaders from this folder instead of the binary (files of at most " +
                       std::to_string(kTextInputLimitMiB) + " MiB)");
    addShadowMapOptions(cmd, o);
    addMethodChoice(cmd, o);
    addViewOptions(cmd, o);
    addLightPlacement(cmd, o);
}

void addMethodOptions(CLI::App& cmd, SceneOptions& o) {
    for (const MethodOption* opt : allMethodOptions()) {
        // "jfa-l, flood-l: ..." — which methods take it, from the table.
        const std::string takers =
            methodNamesWhere([&](const MethodDescriptor& m) { return m.takesFlag(opt->flag); });
        const std::string help = takers + ": " + std::string(opt->help);
        const std::string flag(opt->flag);
        if (opt->kind == OptionKind::Flag) {
            cmd.add_flag_callback(
                flag, [&o, flag] { o.methodOptions[flag] = "true"; }, help);
            continue;
        }
        cmd.add_option_function<std::string>(
               flag, [&o, flag](const std::string& v) { o.methodOptions[flag] = v; }, help)
            ->check(CLI::Validator(
                [opt](const std::string& text) { return checkOptionValue(*opt, text); },
                opt->kind == OptionKind::Choice ? std::string(opt->choices)
                : opt->word.empty()
                    ? rangeText(opt->min, opt->max, "")
                    : rangeText(opt->min, opt->max, "") + " or " + std::string(opt->word)))
            ->default_str(std::string(opt->defaultValue));
    }
}

void addSizeOptions(CLI::App& cmd, int& width, int& height) {
    cmd.add_option("--width", width, "Image width in pixels")
        ->check(integer(1, kMaxImageSize))
        ->capture_default_str();
    cmd.add_option("--height", height, "Image height in pixels")
        ->check(integer(1, kMaxImageSize))
        ->capture_default_str();
}

std::string rangeText(double lo, double hi, const char* unbounded) {
    // %g: 8192 and 0.5, not 8192.000000; 1e+15 for the world's bound.
    const auto g = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, "%g", v);
        return std::string(b);
    };
    const bool low = lo > -kUnbounded, high = hi < kUnbounded;
    if (low && high) return "in [" + g(lo) + ", " + g(hi) + "]";
    if (low) return ">= " + g(lo);
    if (high) return "<= " + g(hi);
    return unbounded;
}

// The description is the range, so --help shows every number's range beside its type
// ("INT:in [16, 8192]=1024").
CLI::Validator number(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](const std::string& text) { return numberProblem(text, lo, hi, false); },
        rangeText(lo, hi, "NUMBER"));
}

CLI::Validator integer(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](const std::string& text) { return numberProblem(text, lo, hi, true); },
        rangeText(lo, hi, "INT"));
}

namespace {

// Levenshtein distance over bytes.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

} // namespace

std::string suggestFlags(const CLI::App& cmd) {
    std::string out;
    for (const std::string& arg : cmd.remaining()) {
        if (arg.size() < 2 || arg[0] != '-') continue;
        const std::string flag = arg.substr(0, arg.find('=')); // --flag=value
        std::string best;
        std::size_t bestDistance = std::max<std::size_t>(2, flag.size() / 3) + 1;
        for (const CLI::Option* o : cmd.get_options()) {
            std::vector<std::string> names;
            for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
            for (const std::string& n : o->get_snames()) names.push_back("-" + n);
            for (const std::string& n : names)
                if (const std::size_t d = editDistance(flag, n); d < bestDistance) {
                    bestDistance = d;
                    best = n;
                }
        }
        out += flag + ": not an option of `" + cmd.get_name() + "`" +
               (best.empty() ? std::string() : "; did you mean " + best + "?") + "\n";
    }
    return out;
}

CLI::Validator outputFolder() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            if (text.empty()) return "empty folder name (use . for the current folder)";
            return {};
        },
        "FOLDER");
}

CLI::Validator outputStem() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            if (text.empty()) return "empty file name (the files would be hidden: .png, .exr)";
            if (text.find('/') != std::string::npos)
                return "'" + text +
                       "' contains '/'; a name stays inside --out (give folders there)";
            if (text.front() == '.')
                return "'" + text + "' starts with '.' (hidden files, or a path outside --out)";
            return {};
        },
        "NAME");
}

CLI::Validator outputFile() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            if (text.empty()) return "empty file name";
            const std::string last = std::filesystem::path(text).filename().string();
            if (last.empty() || last == "." || last == "..")
                return "'" + text + "' names a folder, not a file";
            return {};
        },
        "FILE");
}

CLI::Option* addOutOption(CLI::App& cmd, std::string& out, const std::string& help) {
    // One rule for every output: said once here, where every command's --out is.
    return cmd
        .add_option("--out", out, help + ". Missing folders are created, for every output alike")
        ->check(outputFolder())
        ->capture_default_str();
}

CLI::Option* addNameOption(CLI::App& cmd, std::string& name, const std::string& help) {
    return cmd.add_option("--name", name, help)->check(outputStem())->capture_default_str();
}

} // namespace fl::app
