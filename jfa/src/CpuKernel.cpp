#include <jfa/CpuKernel.h>

#include <exception>
#include <mutex>
#include <thread>

namespace fl::jfa {

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

int stageScale(const Plan& plan, std::size_t stageIndex) {
    const std::size_t count = plan.stages().size();
    if (stageIndex >= count) throw std::out_of_range("stageScale: no such stage");
    const std::size_t shift = count - 1 - stageIndex;
    if (shift > 20) throw std::invalid_argument("stageScale: plan has too many stages");
    return 1 << shift;
}

Grid expand(const Grid& grid, int width, int height) {
    if (width < 1 || height < 1 || grid.width != (width + 1) / 2 ||
        grid.height != (height + 1) / 2) {
        throw std::invalid_argument("expand: a " + std::to_string(grid.width) + "x" +
                                    std::to_string(grid.height) + " grid does not expand to " +
                                    std::to_string(width) + "x" + std::to_string(height));
    }
    Grid out(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) out.at(x, y) = grid.at(x / 2, y / 2);
    }
    return out;
}

} // namespace fl::jfa
