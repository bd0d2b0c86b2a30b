#include <gpu/ShaderLibrary.h>

#include "ProgramPool.h"

#include <base/InputFile.h>

#include <sstream>
#include <stdexcept>

namespace fl::gl {

ShaderLibrary::ShaderLibrary(std::optional<std::filesystem::path> dir)
    : dir_(std::move(dir)), pool_(std::make_shared<ProgramPool>()) {
    if (dir_ && !std::filesystem::is_directory(*dir_))
        throw std::runtime_error("--shader-dir " + dir_->string() + ": not a directory");
}

std::string ShaderLibrary::read(const std::string& name) const {
    if (dir_) {
        // Regular files within the text limit only (base/InputFile.h), as every user file.
        return readInputFile(*dir_ / name, "--shader-dir", kTextInputLimitMiB);
    }
    const auto& shaders = embeddedShaders();
    const auto it = shaders.find(name);
    if (it == shaders.end()) throw std::runtime_error(name + ": no such embedded shader");
    return std::string(it->second);
}

std::string ShaderLibrary::expand(const std::string& name,
                                  std::vector<std::string>& fileNames) const {
    fileNames.clear();
    std::string out;
    expandInto(name, out, fileNames, 0);
    return out;
}

void ShaderLibrary::expandInto(const std::string& name, std::string& out,
                               std::vector<std::string>& files, int depth) const {
    if (depth > 16) throw std::runtime_error(name + ": #include nested too deeply (a cycle?)");
    const int index = static_cast<int>(files.size());
    files.push_back(name);
    std::istringstream in(read(name));
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        const size_t start = line.find_first_not_of(" \t");
        if (start != std::string::npos && line.compare(start, 8, "#include") == 0) {
            const size_t open = line.find('"', start);
            const size_t close = open == std::string::npos ? open : line.find('"', open + 1);
            if (close == std::string::npos)
                throw std::runtime_error(name + ":" + std::to_string(lineNo) +
                                         ": malformed #include (expected \"file.glsl\")");
            out += "#line 1 " + std::to_string(files.size()) + "\n";
            expandInto(line.substr(open + 1, close - open - 1), out, files, depth + 1);
            out += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(index) + "\n";
            continue;
        }
        out += line;
        out += '\n';
        // After the #version line of the top file, pin numbering to this file's source number.
        if (depth == 0 && lineNo == 1 && line.rfind("#version", 0) == 0)
            out += "#line 2 " + std::to_string(index) + "\n";
    }
}

} // namespace fl::gl
