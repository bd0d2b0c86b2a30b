#pragma once
// What the running process holds, for soak runs and long captures: memory that keeps growing
// over thousands of frames is a leak that no single-frame test sees.

#include <cstddef>

namespace fl {

/// The process's resident memory now, in KiB (/proc/self/statm); 0 where it cannot be read.
std::size_t residentKiB();

} // namespace fl
