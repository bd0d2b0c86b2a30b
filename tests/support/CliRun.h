#pragma once
// Running a command line from a test (the floodlight binary, a browser) and collecting what it
// printed and how it ended.

#include <string>

namespace fl::test {

struct Outcome {
    int code;           // exit status; 128 + signal if it was killed
    std::string output; // stdout and stderr together
};

/// Runs `commandLine` through the shell with stderr joined to stdout.
Outcome runCommand(const std::string& commandLine);

} // namespace fl::test
