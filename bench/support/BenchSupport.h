#pragma once
// What every benchmark's main shares: the command-line pieces they spell alike (frame and map
// sizes, the method table's options, --set FLAG=VALUE), the default scene, the lanes of the
// frame-loop runner (renderer/run/FrameRunner.h), and one error rule: an exception ends the
// bench with "error: WHAT" and exit 1.

#include <renderer/Renderer.h>
#include <renderer/run/FrameRunner.h>

#include <CLI/CLI.hpp>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fl::bench {

/// Runs a bench's body; an exception is printed as "error: WHAT" on stderr and exits 1.
int guarded(const std::function<int()>& body);

/// A bench's main after its options are registered on `app`: parses argv (CLI11's exit for
/// --help and usage errors), then runs `body` guarded.
int parseAndRun(CLI::App& app, int argc, char** argv, const std::function<int()>& body);

/// assets/default.glb, or the glTF file `path` when it is not empty.
Scene loadBenchScene(const std::string& path = {});

/// Registers --size (the square frame's side) and --shadow-map-size with their defaults shown.
void addFrameSizeOptions(CLI::App& app, int& size, int& shadowMap);

/// Every option of the method table (--jfa-passes, --pcss-preset, ...) on a bench's command
/// line, as the app registers them; apply() copies the given ones into a method's options,
/// checked by the table's own rules.
class MethodFlags {
  public:
    /// Registers every option of the table on `app`.
    void add(CLI::App& app);
    /// Sets the options given on `app` (after parsing) in `options`; throws on a bad value.
    void apply(const CLI::App& app, MethodOptions& options) const;

  private:
    std::map<std::string, std::string> text_;
    std::map<std::string, bool> flags_;
};

/// Parses --set's FLAG=VALUE pairs; returns the problem ("--set X: ...") or nothing.
std::optional<std::string> parseSets(const std::vector<std::string>& sets, MethodOptions& out);

/// One method of the table at one setting: its label ("pcss 16/24"), its row, and the option
/// its sweep sets ("" for none).
struct MethodEntry {
    std::string label;
    const MethodDescriptor* method = nullptr;
    std::string flag, value;
};

/// Every method of the table that is not a ground truth, in table order, at its defaults; a
/// method with a swept option (MethodOption::sweep: PCF's two kernels, PCSS's presets) once per
/// value, labelled "NAME ITEM". The standard-flooding references (flood-l, flood-e: the JFA
/// methods' own yardsticks) only `withFloodReferences`.
std::vector<MethodEntry> sweptMethods(bool withFloodReferences);

/// One lane per renderer for the frame-loop runner, labelled in order.
std::vector<Lane> lanesOf(const std::vector<std::string>& labels,
                          const std::vector<std::unique_ptr<Renderer>>& renderers);

} // namespace fl::bench
