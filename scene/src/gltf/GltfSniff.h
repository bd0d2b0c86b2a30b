#pragma once
// What a file that is not a loadable glTF 2.0 file is, in a user's words: tinygltf's
// and the JSON parser's own messages quoted raw bytes ("last read: '\x89'") and named nothing a
// user could act on ("\"asset\" object not found" for a glTF 1.0 file). These checks run before
// tinygltf (the bytes' kind, the .glb header) and after it fails (the JSON, the asset).

#include <cstddef>
#include <string>
#include <vector>

namespace fl::gltf {

/// The problem with `size` bytes as a glTF file, found without parsing: empty, another format's
/// signature ("not a glTF file (it starts like a PNG image)"), a .glb header of another version
/// or a length past the end ("truncated: ..."). Empty when nothing is found.
std::string sniffProblem(const std::vector<unsigned char>& bytes, std::size_t size);

/// The problem with the JSON in bytes [begin, end) where tinygltf could not load the file: not
/// JSON (where, by line and column), truncated, not an object, or not glTF 2.0 (no "asset", or
/// glTF 1.0's objects by name). Empty when the JSON looks like glTF 2.0 (tinygltf's own message
/// is then the one to show).
std::string jsonProblem(const std::vector<unsigned char>& bytes, std::size_t begin,
                        std::size_t end);

/// The problem with a parsed file's asset.version: "" for 2.x, else that it is not supported.
std::string versionProblem(const std::string& version);

} // namespace fl::gltf
