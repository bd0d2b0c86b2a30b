#include <base/Process.h>

#include <fstream>
#include <unistd.h>

namespace fl {

std::size_t residentKiB() {
    // statm: size resident shared ... in pages. Current, not peak (getrusage's ru_maxrss): a
    // soak needs to see memory come back as well as go.
    std::ifstream in("/proc/self/statm");
    std::size_t size = 0, resident = 0;
    if (!(in >> size >> resident)) return 0;
    return resident * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)) / 1024;
}

} // namespace fl
