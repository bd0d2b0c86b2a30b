#include <base/Parallel.h>

#include <algorithm>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fl {

int resolveThreads(int threads) {
    if (threads < 0) {
        throw std::invalid_argument("flood: thread count must be >= 0 (0 = all hardware threads), "
                                    "got " +
                                    std::to_string(threads));
    }
    if (threads > 0) return threads;
    const unsigned hardware = std::thread::hardware_concurrency();
    return hardware == 0 ? 1 : static_cast<int>(hardware);
}

int bandCount(int rows, int threads) {
    return std::max(1, std::min(resolveThreads(threads), rows));
}

void parallelRows(int rows, int threads, const std::function<void(int, int, int)>& body) {
    const int bands = bandCount(rows, threads);
    auto bandBegin = [&](int band) {
        return static_cast<int>(static_cast<long long>(rows) * band / bands);
    };
    if (bands == 1) {
        body(0, rows, 0);
        return;
    }
    std::mutex mutex;
    std::exception_ptr firstError;
    auto runBand = [&](int band) {
        try {
            body(bandBegin(band), bandBegin(band + 1), band);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mutex);
            if (!firstError) firstError = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> workers;
        workers.reserve(static_cast<std::size_t>(bands - 1));
        for (int band = 1; band < bands; ++band) workers.emplace_back(runBand, band);
        runBand(0);
    } // joins
    if (firstError) std::rethrow_exception(firstError);
}

} // namespace fl
