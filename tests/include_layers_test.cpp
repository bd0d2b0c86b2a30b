// Includes run only downward (issue 29 item 1): each library includes its own headers and those
// of the libraries it links (cmake/layers.txt, the table CMake links them by; issue 43), the CPU
// libraries include no GL header, inside the renderer each folder includes only the folders below
// it, and nothing reaches into another library's src/. The scan reads every source of the tree.

#include "SourceFolders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

// A library of the layer table (cmake/layers.txt, the file CMake links the libraries by).
struct Layer {
    bool cpu = false;                  // kind cpu: builds without GL
    std::vector<std::string> links;    // the libraries it links directly
    std::set<std::string> publicLinks; // those of `links` linked PUBLIC (not in [brackets])
};

/// The table in `text` (cmake/layers.txt's format: "library kind: links", # comments), in the
/// order of its lines. Throws on a line of another shape.
std::vector<std::pair<std::string, Layer>> parseLayers(const std::string& text) {
    static const std::regex line(R"(^([a-z_]+)[ \t]+(cpu|gl):(.*)$)");
    static const std::regex link(R"((\[?)([a-z_]+)\]?)");
    std::vector<std::pair<std::string, Layer>> out;
    std::istringstream in(text);
    std::string l;
    while (std::getline(in, l)) {
        if (l.find_first_not_of(" \t") == std::string::npos || l[l.find_first_not_of(" \t")] == '#')
            continue;
        std::smatch m;
        if (!std::regex_match(l, m, line))
            throw std::runtime_error("not 'library kind: links': " + l);
        Layer layer;
        layer.cpu = m[2].str() == "cpu";
        const std::string links = m[3].str();
        for (auto it = std::sregex_iterator(links.begin(), links.end(), link);
             it != std::sregex_iterator(); ++it) {
            layer.links.push_back((*it)[2].str());
            if ((*it)[1].str().empty()) layer.publicLinks.insert((*it)[2].str());
        }
        out.emplace_back(m[1].str(), layer);
    }
    return out;
}

/// The library `name` and those it links PUBLIC, directly or through their PUBLIC links: what
/// a library that links `name` sees (CMake's usage requirements).
void addPublicClosure(const std::map<std::string, Layer>& table, const std::string& name,
                      std::set<std::string>& out) {
    if (!out.insert(name).second) return;
    for (const std::string& next : table.at(name).publicLinks) addPublicClosure(table, next, out);
}

/// Each library (its folder and include prefix) and the libraries it may include, itself aside:
/// those it links, and what they pass on.
std::map<std::string, std::set<std::string>>
allowedIncludes(const std::vector<std::pair<std::string, Layer>>& layers) {
    const std::map<std::string, Layer> table(layers.begin(), layers.end());
    std::map<std::string, std::set<std::string>> out;
    for (const auto& [name, layer] : layers) {
        std::set<std::string>& allowed = out[name];
        for (const std::string& link : layer.links) addPublicClosure(table, link, allowed);
    }
    return out;
}

const std::vector<std::pair<std::string, Layer>>& layerTable() {
    static const std::vector<std::pair<std::string, Layer>> table = [] {
        std::ifstream in(FLOODLIGHT_LAYERS_FILE);
        if (!in) throw std::runtime_error("cannot read " FLOODLIGHT_LAYERS_FILE);
        std::stringstream text;
        text << in.rdbuf();
        return parseLayers(text.str());
    }();
    return table;
}

const std::map<std::string, std::set<std::string>>& layers() {
    static const auto table = allowedIncludes(layerTable());
    return table;
}

// The libraries that must build without GL: no GL, EGL, GLFW or epoxy header.
const std::set<std::string>& cpuLibraries() {
    static const std::set<std::string> cpu = [] {
        std::set<std::string> out;
        for (const auto& [name, layer] : layerTable())
            if (layer.cpu) out.insert(name);
        return out;
    }();
    return cpu;
}

// The renderer's folders, bottom to top: a folder includes only those before it (and the files
// at the renderer's top, Renderer.h, sit between methods and overlays).
const std::vector<std::string> kRendererOrder = {
    "context", "io", "scene", "passes", "metrics", "soft", "methods", "", "overlays", "run"};

struct Include {
    int line = 0;
    std::string path;   // as written
    bool angled = true; // <...> rather than "..."
};

std::vector<Include> includesOf(const std::string& text) {
    static const std::regex re(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
    std::vector<Include> out;
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        std::smatch m;
        if (std::regex_search(line, m, re)) out.push_back({n, m[2].str(), m[1].str() == "<"});
    }
    return out;
}

// The renderer folder of a renderer source or header ("" for its top: Renderer.h/.cpp).
std::string rendererFolder(const std::string& relative) {
    for (const std::string prefix : {"renderer/src/", "renderer/include/renderer/"}) {
        if (relative.rfind(prefix, 0) != 0) continue;
        const std::string rest = relative.substr(prefix.size());
        const auto slash = rest.find('/');
        return slash == std::string::npos ? "" : rest.substr(0, slash);
    }
    return "";
}

int rendererRank(const std::string& folder) {
    const auto it = std::find(kRendererOrder.begin(), kRendererOrder.end(), folder);
    return it == kRendererOrder.end() ? -1 : int(it - kRendererOrder.begin());
}

} // namespace

/// The problems of one file (`relative`: its path from the source root; `library`: the folder
/// it belongs to, or "" for tests, benches, fuzz targets and main), one line each.
std::vector<std::string> layerProblems(const std::string& relative, const std::string& library,
                                       const std::string& text) {
    std::vector<std::string> problems;
    const auto& table = layers();
    for (const Include& inc : includesOf(text)) {
        const std::string where = relative + ":" + std::to_string(inc.line) + ": ";
        if (inc.path.find("../") != std::string::npos ||
            inc.path.find("/src/") != std::string::npos)
            problems.push_back(where + "\"" + inc.path +
                               "\" reaches into another folder's sources");
        if (!inc.angled) continue;
        const auto slash = inc.path.find('/');
        const std::string prefix = slash == std::string::npos ? "" : inc.path.substr(0, slash);
        if (cpuLibraries().count(library) &&
            (prefix == "epoxy" || prefix == "GL" || prefix == "EGL" || prefix == "GLFW"))
            problems.push_back(where + "<" + inc.path + "> is GL in the CPU library " + library);
        if (library.empty() || !table.count(prefix) || prefix == library) {
            if (library == "renderer" && prefix == "renderer") {
                const std::string rest = inc.path.substr(slash + 1);
                const auto s2 = rest.find('/');
                const std::string to = s2 == std::string::npos ? "" : rest.substr(0, s2);
                const std::string from = rendererFolder(relative);
                if (rendererRank(to) > rendererRank(from))
                    problems.push_back(where + "<" + inc.path + "> runs up the renderer from " +
                                       (from.empty() ? "its top" : from + "/") + " to " +
                                       (to.empty() ? "its top" : to + "/"));
            }
            continue;
        }
        if (!table.at(library).count(prefix))
            problems.push_back(where + "<" + inc.path + "> runs up from " + library + " to " +
                               prefix);
    }
    return problems;
}

TEST(IncludeLayers, TheCheckFindsEachKindOfProblem) {
    EXPECT_EQ(layerProblems("scene/src/A.cpp", "scene", "#include <renderer/Renderer.h>\n").size(),
              1u);
    EXPECT_EQ(layerProblems("jfa/src/A.cpp", "jfa", "#include <epoxy/gl.h>\n").size(), 1u);
    EXPECT_EQ(layerProblems("tests/a_test.cpp", "", "#include \"../geometry/src/X.h\"\n").size(),
              1u);
    EXPECT_EQ(layerProblems("renderer/include/renderer/io/A.h", "renderer",
                            "#include <renderer/Renderer.h>\n")
                  .size(),
              1u);
    EXPECT_EQ(layerProblems("renderer/src/soft/A.cpp", "renderer",
                            "#include <renderer/methods/ShadowMethod.h>\n")
                  .size(),
              1u);
    // Downward and sideways-within-a-library includes are fine.
    EXPECT_TRUE(layerProblems("renderer/src/methods/A.cpp", "renderer",
                              "#include <renderer/soft/PenumbraMap.h>\n#include <scene/Scene.h>\n"
                              "#include <glm/glm.hpp>\n#include \"LightLookup.h\"\n")
                    .empty());
    EXPECT_TRUE(layerProblems("app/src/A.cpp", "app", "#include <renderer/Renderer.h>\n").empty());
}

TEST(IncludeLayers, TheTableIsReadAsCMakeLinksIt) {
    // A library sees what it links and what those link PUBLIC; a [PRIVATE] link is its own.
    const auto allowed = allowedIncludes(parseLayers("# comment\n\na cpu:\nb  cpu: a\n"
                                                     "c cpu: [b]\nd gl:  c a\n"));
    EXPECT_EQ(allowed.at("a"), std::set<std::string>{});
    EXPECT_EQ(allowed.at("c"), (std::set<std::string>{"a", "b"}));
    EXPECT_EQ(allowed.at("d"), (std::set<std::string>{"a", "c"}));
    EXPECT_THROW(parseLayers("a: b\n"), std::runtime_error);
    // The real table: the ray tracer links geometry (disk sampling), not the scene, and the
    // scene needs none of the Delaunay pipeline (its boxes and framing are base's).
    EXPECT_FALSE(layers().at("raytrace").count("scene"));
    EXPECT_TRUE(layers().at("raytrace").count("geometry"));
    EXPECT_FALSE(layers().at("scene").count("geometry"));
    EXPECT_TRUE(layers().at("app").count("base"));
    EXPECT_EQ(cpuLibraries(),
              (std::set<std::string>{"base", "io", "jfa", "geometry", "scene", "raytrace"}));
}

TEST(IncludeLayers, TheTableNamesEveryLibraryFolder) {
    std::set<std::string> folders(fl::test::kLibraryFolders.begin(),
                                  fl::test::kLibraryFolders.end());
    std::set<std::string> inTable;
    for (const auto& [library, uses] : layers()) inTable.insert(library);
    EXPECT_EQ(folders, inTable);
}

TEST(IncludeLayers, EverySourceOfTheTreeIncludesDownward) {
    const fs::path root = FLOODLIGHT_SOURCE_DIR;
    std::vector<std::string> problems;
    std::size_t files = 0;
    std::vector<std::string> tops(fl::test::kLibraryFolders.begin(),
                                  fl::test::kLibraryFolders.end());
    tops.insert(tops.end(), {"tests", "bench", "fuzz"}); // above every library
    for (const std::string& top : tops) {
        ASSERT_TRUE(fs::is_directory(root / top)) << top;
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string();
            if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
            const std::string relative = fs::relative(e.path(), root).generic_string();
            // main.cpp, tests, benches and fuzz targets sit above every library.
            const bool library = layers().count(top) && relative != "app/main.cpp";
            std::ifstream in(e.path());
            std::stringstream text;
            text << in.rdbuf();
            const auto found = layerProblems(relative, library ? top : "", text.str());
            problems.insert(problems.end(), found.begin(), found.end());
            ++files;
        }
    }
    EXPECT_GT(files, 300u); // the scan saw the tree
    std::string all;
    for (const auto& p : problems) all += p + "\n";
    EXPECT_TRUE(problems.empty()) << problems.size() << " include(s) run up a layer:\n" << all;
}
