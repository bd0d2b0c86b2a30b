#include <jfa/Plan.h>

#include <base/Text.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <ostream>
#include <stdexcept>
#include <utility>

namespace fl::jfa {

namespace {

// Largest K of JFA+K: its first extra step 2^(K-1) must fit in an int.
constexpr int kMaxExtraPasses = 30;

// Runs of at least this many equal steps print as "1*63" instead of 63 ones.
constexpr std::size_t kMinRunToCompress = 4;

// The forms parsePlan takes, for its messages (kMaxFloodPasses from Plan.h, as the help shows).
std::string validPlans() {
    return fl::cat("valid plans (case-insensitive): jfa, jfa+1, jfa+2, jfa+K (K = 1..30), jfa2 "
                   "(or jfa^2), 1+jfa, 1+jfa+1, doubling, flood (until nothing changes), flood:N "
                   "(N step-1 passes, N <= ",
                   kMaxFloodPasses,
                   "), half:<plan> (e.g. half:jfa, half:jfa+2), and explicit step lists "
                   "before/after the body such as (2,1)+jfa+(1,1)");
}

[[noreturn]] void throwInvalidSpec(std::string_view spec, std::string_view reason) {
    std::string message = "invalid flood plan \"";
    message += spec;
    message += "\": ";
    message += reason;
    message += "; ";
    message += validPlans();
    throw std::invalid_argument(message);
}

void checkExtent(int width, int height) {
    if (width < 1 || height < 1 || width > kMaxGridExtent || height > kMaxGridExtent) {
        throw std::invalid_argument(fl::cat("flood plan grid ", width, "x", height,
                                            " is out of range: each side must be 1..",
                                            kMaxGridExtent));
    }
}

void checkSteps(const std::vector<int>& steps, std::string_view what) {
    if (steps.size() > static_cast<std::size_t>(kMaxFloodPasses)) {
        throw std::invalid_argument(fl::cat(what, " has more than ", kMaxFloodPasses, " steps"));
    }
    for (int step : steps) {
        if (step < 1 || step > kMaxGridExtent) {
            throw std::invalid_argument(
                fl::cat(what, " has step length ", step, "; steps must be 1..", kMaxGridExtent));
        }
    }
}

void append(std::vector<int>& to, const std::vector<int>& from) {
    to.insert(to.end(), from.begin(), from.end());
}

std::string listText(const std::vector<int>& steps) {
    std::string text = "(";
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (i > 0) text += ',';
        text += std::to_string(steps[i]);
    }
    return text + ")";
}

// The "+K" form of `after` when it is JFA+K's tail, else the explicit "+(a,b)" list.
std::string afterText(const std::vector<int>& after) {
    if (after.empty()) return {};
    const int k = static_cast<int>(after.size());
    if (k <= kMaxExtraPasses && after == extraPasses(k)) return fl::cat("+", k);
    return fl::cat("+", listText(after));
}

std::string beforeText(const std::vector<int>& before) {
    if (before.empty()) return {};
    if (before == std::vector<int>{1}) return "1+";
    return listText(before) + "+";
}

// Name (display) and spec (parseable, lower case) of a recipe.
std::pair<std::string, std::string> recipeNames(const Recipe& recipe) {
    std::string body;
    std::string bodySpec;
    switch (recipe.body) {
    case Body::Jfa:
        body = "JFA";
        bodySpec = "jfa";
        break;
    case Body::JfaSquared:
        body = "JFA^2";
        bodySpec = "jfa2";
        break;
    case Body::Doubling:
        body = bodySpec = "doubling";
        break;
    case Body::Flood:
        body = bodySpec = fl::cat("flood:", recipe.floodPasses);
        break;
    case Body::FloodUntilUnchanged:
        body = bodySpec = "flood";
        break;
    }
    const std::string before = beforeText(recipe.before);
    const std::string after = afterText(recipe.after);
    std::string name = before + body + after;
    std::string spec = before + bodySpec + after;
    if (recipe.halfResolution) {
        name = fl::cat("half-res ", name);
        spec = fl::cat("half:", spec);
    }
    return {name, spec};
}

std::string stepsText(const Stage& stage) {
    if (stage.untilUnchanged) return "1 until unchanged";
    if (stage.steps.empty()) return "none";
    std::string text;
    for (std::size_t i = 0; i < stage.steps.size();) {
        std::size_t run = 1;
        while (i + run < stage.steps.size() && stage.steps[i + run] == stage.steps[i]) ++run;
        if (!text.empty()) text += ' ';
        if (run >= kMinRunToCompress) {
            text += fl::cat(stage.steps[i], "*", run);
        } else {
            for (std::size_t j = 0; j < run; ++j) {
                if (j > 0) text += ' ';
                text += std::to_string(stage.steps[i]);
            }
        }
        i += run;
    }
    return text;
}

std::string sizeText(int width, int height) {
    return fl::cat(width, "x", height);
}

// Parses a non-negative decimal integer that is the whole of `text`.
bool parseInt(std::string_view text, int& value) {
    if (text.empty()) return false;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc{} && end == text.data() + text.size() && value >= 0;
}

// Parses "(a,b,...)" at the start of `rest`, consuming it; steps must be >= 1.
std::vector<int> parseList(std::string_view& rest, std::string_view spec) {
    const std::size_t close = rest.find(')');
    if (close == std::string_view::npos) throwInvalidSpec(spec, "missing ')' in step list");
    std::string_view inner = rest.substr(1, close - 1);
    rest.remove_prefix(close + 1);
    std::vector<int> steps;
    while (true) {
        const std::size_t comma = inner.find(',');
        int step = 0;
        if (!parseInt(inner.substr(0, comma), step) || step < 1 || step > kMaxGridExtent) {
            throwInvalidSpec(spec, "step lists hold positive integers separated by commas");
        }
        steps.push_back(step);
        if (comma == std::string_view::npos) break;
        inner.remove_prefix(comma + 1);
    }
    return steps;
}

bool consume(std::string_view& rest, std::string_view prefix) {
    if (!rest.starts_with(prefix)) return false;
    rest.remove_prefix(prefix.size());
    return true;
}

} // namespace

// ---- step rules ---------------------------------------------------------------------------------

int jfaMaxPasses(int n) {
    int k = 0;
    while (k < 30 && (2 << k) <= n) ++k; // 2 << 30 would overflow an int
    return k;
}

int jfaFirstStep(int n) {
    if (n < 1) throw std::invalid_argument("jfaFirstStep: extent must be >= 1");
    int step = 0;
    for (int candidate = 1; candidate <= n - 1; candidate *= 2) {
        step = candidate;
        if (candidate > (n - 1) / 2) break; // the next doubling would exceed n - 1 (or overflow)
    }
    return step;
}

std::vector<int> jfaSteps(int n) {
    std::vector<int> steps;
    for (int step = jfaFirstStep(n); step >= 1; step /= 2) steps.push_back(step);
    return steps;
}

std::vector<int> extraPasses(int k) {
    if (k < 1 || k > kMaxExtraPasses) {
        throw std::invalid_argument(fl::cat("extraPasses: k must be 1..", kMaxExtraPasses));
    }
    std::vector<int> steps;
    for (int step = 1 << (k - 1); step >= 1; step /= 2) steps.push_back(step);
    return steps;
}

// ---- Plan ---------------------------------------------------------------------------------------

Plan::Plan(std::string name, std::vector<Stage> stages, std::string spec)
    : name_(std::move(name)), stages_(std::move(stages)), spec_(std::move(spec)) {
    if (stages_.empty())
        throw std::invalid_argument(fl::cat("flood plan \"", name_, "\" has no stages"));
    for (std::size_t i = 0; i < stages_.size(); ++i) {
        const Stage& stage = stages_[i];
        const std::string what = fl::cat("flood plan \"", name_, "\" stage ", i);
        checkExtent(stage.width, stage.height);
        checkSteps(stage.steps, what);
        if (i > 0) {
            const Stage& previous = stages_[i - 1];
            if (previous.width != (stage.width + 1) / 2 ||
                previous.height != (stage.height + 1) / 2) {
                throw std::invalid_argument(
                    fl::cat(what, ": an expansion goes from ceil(W/2)xceil(H/2) to WxH, not from ",
                            sizeText(previous.width, previous.height), " to ",
                            sizeText(stage.width, stage.height)));
            }
            if (stage.steps.empty()) {
                throw std::invalid_argument(what + ": a stage after an expansion needs a pass");
            }
        }
        if (stage.untilUnchanged &&
            (stage.steps.empty() ||
             std::any_of(stage.steps.begin(), stage.steps.end(), [](int s) { return s != 1; }))) {
            throw std::invalid_argument(what +
                                        ": an until-unchanged stage holds step-1 passes only");
        }
    }
}

Plan Plan::jfa(int width, int height) {
    return compose({}, width, height);
}

// The named variants are one-field recipes (designated initializers leave the rest default).
Plan Plan::jfaPlus(int k, int width, int height) {
    return compose({.after = extraPasses(k)}, width, height);
}

Plan Plan::jfaSquared(int width, int height) {
    return compose({.body = Body::JfaSquared}, width, height);
}

Plan Plan::onePlusJfa(int width, int height) {
    return compose({.before = {1}}, width, height);
}

Plan Plan::doubling(int width, int height) {
    return compose({.body = Body::Doubling}, width, height);
}

Plan Plan::flood(int passes, int width, int height) {
    return compose({.body = Body::Flood, .floodPasses = passes}, width, height);
}

Plan Plan::floodUntilUnchanged(int width, int height) {
    return compose({.body = Body::FloodUntilUnchanged}, width, height);
}

Plan Plan::halfResolution(int width, int height) {
    return compose({.halfResolution = true}, width, height);
}

Plan Plan::compose(const Recipe& recipe, int width, int height) {
    checkExtent(width, height);
    checkSteps(recipe.before, "flood plan steps before the body");
    checkSteps(recipe.after, "flood plan steps after the body");
    if (recipe.body == Body::FloodUntilUnchanged &&
        !(recipe.before.empty() && recipe.after.empty())) {
        throw std::invalid_argument("flood until unchanged takes no steps before or after it");
    }
    if (recipe.body == Body::Flood &&
        (recipe.floodPasses < 1 || recipe.floodPasses > kMaxFloodPasses)) {
        throw std::invalid_argument(
            fl::cat("flood:N needs N in 1..", kMaxFloodPasses, ", got ", recipe.floodPasses));
    }

    Stage first;
    first.width = recipe.halfResolution ? (width + 1) / 2 : width;
    first.height = recipe.halfResolution ? (height + 1) / 2 : height;
    const int n = std::max(first.width, first.height);

    first.steps = recipe.before;
    switch (recipe.body) {
    case Body::Jfa:
        append(first.steps, jfaSteps(n));
        break;
    case Body::JfaSquared:
        append(first.steps, jfaSteps(n));
        append(first.steps, jfaSteps(n));
        break;
    case Body::Doubling: {
        std::vector<int> steps = jfaSteps(n);
        std::reverse(steps.begin(), steps.end());
        append(first.steps, steps);
        break;
    }
    case Body::Flood:
        first.steps.insert(first.steps.end(), static_cast<std::size_t>(recipe.floodPasses), 1);
        break;
    case Body::FloodUntilUnchanged:
        first.steps.assign(static_cast<std::size_t>(first.width + first.height), 1);
        first.untilUnchanged = true;
        break;
    }
    append(first.steps, recipe.after);

    std::vector<Stage> stages{std::move(first)};
    if (recipe.halfResolution) stages.push_back(Stage{width, height, {1}, false});
    auto [name, spec] = recipeNames(recipe);
    return Plan(std::move(name), std::move(stages), std::move(spec));
}

std::vector<Pass> Plan::passes() const {
    std::vector<Pass> result;
    for (std::size_t i = 0; i < stages_.size(); ++i) {
        const Stage& stage = stages_[i];
        for (std::size_t j = 0; j < stage.steps.size(); ++j) {
            result.push_back(Pass{stage.steps[j], stage.width, stage.height, i > 0 && j == 0,
                                  stage.untilUnchanged});
        }
    }
    return result;
}

std::vector<int> Plan::steps() const {
    std::vector<int> result;
    for (const Stage& stage : stages_) append(result, stage.steps);
    return result;
}

int Plan::passCount() const {
    std::size_t count = 0;
    for (const Stage& stage : stages_) count += stage.steps.size();
    return static_cast<int>(count);
}

bool Plan::untilUnchanged() const {
    return std::any_of(stages_.begin(), stages_.end(),
                       [](const Stage& stage) { return stage.untilUnchanged; });
}

long long Plan::maxReach() const {
    long long reach = 0;
    for (std::size_t i = 0; i < stages_.size(); ++i) {
        const long long scale = 1LL << (stages_.size() - 1 - i);
        for (int step : stages_[i].steps) reach += scale * step;
        if (i > 0) reach += 1;
    }
    return reach;
}

std::string Plan::describe() const {
    std::string text = fl::cat(name_, " on ", sizeText(width(), height()), ": ");
    for (std::size_t i = 0; i < stages_.size(); ++i) {
        if (i > 0) text += " | expand | ";
        if (stages_.size() > 1)
            text += fl::cat("[", sizeText(stages_[i].width, stages_[i].height), "] ");
        text += stepsText(stages_[i]);
    }
    const int count = passCount();
    text += untilUnchanged() ? " (at most " : " (";
    text += std::to_string(count) + (count == 1 ? " pass)" : " passes)");
    return text;
}

std::ostream& operator<<(std::ostream& os, const Plan& plan) {
    return os << plan.describe();
}

// ---- parsing ------------------------------------------------------------------------------------

Plan parsePlan(std::string_view spec, int width, int height) {
    std::string lowered(spec);
    std::transform(lowered.begin(), lowered.end(), lowered.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::string_view rest = lowered;
    while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.front()))) {
        rest.remove_prefix(1);
    }
    while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.back()))) {
        rest.remove_suffix(1);
    }
    if (rest.empty()) throwInvalidSpec(spec, "empty name");

    Recipe recipe;
    recipe.halfResolution = consume(rest, "half:");

    if (consume(rest, "1+")) {
        recipe.before = {1};
    } else if (rest.starts_with('(')) {
        recipe.before = parseList(rest, spec);
        if (!consume(rest, "+")) throwInvalidSpec(spec, "expected '+' after the step list");
    }

    if (consume(rest, "jfa^2") || consume(rest, "jfa2")) {
        recipe.body = Body::JfaSquared;
    } else if (consume(rest, "jfa")) {
        recipe.body = Body::Jfa;
    } else if (consume(rest, "doubling")) {
        recipe.body = Body::Doubling;
    } else if (consume(rest, "flood:")) {
        recipe.body = Body::Flood;
        const std::size_t end = std::min(rest.find('+'), rest.size());
        if (!parseInt(rest.substr(0, end), recipe.floodPasses) || recipe.floodPasses < 1 ||
            recipe.floodPasses > kMaxFloodPasses) {
            throwInvalidSpec(spec, fl::cat("N in flood:N must be 1..", kMaxFloodPasses));
        }
        rest.remove_prefix(end);
    } else if (consume(rest, "flood")) {
        recipe.body = Body::FloodUntilUnchanged;
    } else {
        throwInvalidSpec(spec, "unknown name");
    }

    if (consume(rest, "+")) {
        if (rest.starts_with('(')) {
            recipe.after = parseList(rest, spec);
        } else {
            int k = 0;
            if (!parseInt(rest, k) || k < 1 || k > kMaxExtraPasses) {
                throwInvalidSpec(spec, fl::cat("K in <plan>+K must be 1..", kMaxExtraPasses));
            }
            recipe.after = extraPasses(k);
            rest = {};
        }
    }
    if (!rest.empty()) throwInvalidSpec(spec, fl::cat("unexpected \"", rest, "\""));
    if (recipe.body == Body::FloodUntilUnchanged &&
        !(recipe.before.empty() && recipe.after.empty())) {
        throwInvalidSpec(spec, "flood (until unchanged) takes no steps before or after it; use "
                               "flood:N");
    }
    return Plan::compose(recipe, width, height);
}

} // namespace fl::jfa
