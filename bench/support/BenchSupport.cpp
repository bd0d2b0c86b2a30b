#include "BenchSupport.h"

#include <scene/GltfLoader.h>

#include <algorithm>
#include <iostream>

namespace fl::bench {

int guarded(const std::function<int()>& body) {
    try {
        return body();
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}

int parseAndRun(CLI::App& app, int argc, char** argv, const std::function<int()>& body) {
    CLI11_PARSE(app, argc, argv);
    return guarded(body);
}

Scene loadBenchScene(const std::string& path) {
    return loadGltf(path.empty() ? std::string(FLOODLIGHT_SOURCE_DIR) + "/assets/default.glb"
                                 : path);
}

void addFrameSizeOptions(CLI::App& app, int& size, int& shadowMap) {
    app.add_option("--size", size, "Frame width and height")->capture_default_str();
    app.add_option("--shadow-map-size", shadowMap)->capture_default_str();
}

void MethodFlags::add(CLI::App& app) {
    for (const MethodOption* o : allMethodOptions()) {
        const std::string flag(o->flag), help(o->help);
        if (o->kind == OptionKind::Flag)
            app.add_flag(flag, flags_[flag], help);
        else
            app.add_option(flag, text_[flag],
                           help + " (default " + std::string(o->defaultValue) + ")");
    }
}

void MethodFlags::apply(const CLI::App& app, MethodOptions& options) const {
    for (const auto& [flag, value] : text_)
        if (!app.get_option(flag)->empty()) options.set(flag, value);
    for (const auto& [flag, on] : flags_)
        if (on) options.set(flag, true);
    for (const MethodOption* o : allMethodOptions())
        if (options.has(o->flag)) (void)options.text(*o); // validates
}

std::optional<std::string> parseSets(const std::vector<std::string>& sets, MethodOptions& out) {
    const auto known = allMethodOptions();
    for (const std::string& kv : sets) {
        const std::size_t eq = kv.find('=');
        if (eq == std::string::npos || kv.rfind("--", 0) != 0)
            return "--set " + kv + ": expected --FLAG=VALUE";
        const std::string flag = kv.substr(0, eq);
        if (std::none_of(known.begin(), known.end(),
                         [&](const MethodOption* o) { return o->flag == flag; }))
            return "--set " + kv + ": no method takes " + flag;
        out.set(flag, kv.substr(eq + 1));
    }
    return std::nullopt;
}

std::vector<MethodEntry> sweptMethods(bool withFloodReferences) {
    std::vector<MethodEntry> out;
    for (const MethodDescriptor& m : methodTable()) {
        if (!m.truth.empty()) continue;
        const bool isReference =
            std::any_of(methodTable().begin(), methodTable().end(),
                        [&](const MethodDescriptor& other) { return other.reference == m.name; });
        if (isReference && !withFloodReferences) continue;
        const std::string name(m.name);
        const MethodOption* swept = nullptr;
        for (const MethodOption* opt : m.options)
            if (!opt->sweep.empty()) swept = opt;
        if (!swept) {
            out.push_back({name, &m, {}, {}});
            continue;
        }
        std::string_view items = swept->sweep == "*" ? swept->choices : swept->sweep;
        while (!items.empty()) {
            const std::size_t bar = items.find('|');
            const std::string item(items.substr(0, bar));
            const std::size_t eq = item.find('=');
            const std::string value = eq == std::string::npos ? item : item.substr(eq + 1);
            out.push_back({name + " " + item.substr(0, eq), &m, std::string(swept->flag), value});
            items = bar == std::string_view::npos ? std::string_view{} : items.substr(bar + 1);
        }
    }
    return out;
}

std::vector<Lane> lanesOf(const std::vector<std::string>& labels,
                          const std::vector<std::unique_ptr<Renderer>>& renderers) {
    std::vector<Lane> lanes;
    for (std::size_t k = 0; k < labels.size(); ++k)
        lanes.push_back({labels[k], renderers.at(k).get(), {}});
    return lanes;
}

} // namespace fl::bench
