// CapturePipeline (app/CapturePipeline.h): a frame's ordered tasks run after its parallel
// ones and after every earlier frame's, in frame order, whatever the workers; a failed task
// keeps the frames before it and drops the rest, and the failure reaches the caller; the frames
// in flight stay within the limit; without workers every task runs inside submit().

#include <app/CapturePipeline.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fl::app {
namespace {

using Task = CapturePipeline::Task;

// A log of events from every thread.
struct Log {
    std::mutex m;
    std::vector<std::string> events;
    void add(std::string e) {
        std::lock_guard lock(m);
        events.push_back(std::move(e));
    }
    [[nodiscard]] std::size_t index(const std::string& e) {
        std::lock_guard lock(m);
        return static_cast<std::size_t>(std::find(events.begin(), events.end(), e) -
                                        events.begin());
    }
};

// Frame i: three file tasks (the later frames' shorter, so that they could overtake) and two
// ordered tasks.
void submitFrame(CapturePipeline& p, Log& log, int i, int failAt = -1) {
    std::vector<Task> files;
    for (int l = 0; l < 3; ++l)
        files.push_back({&PhaseSplit::files, [&log, i, l, failAt] {
                             std::this_thread::sleep_for(std::chrono::milliseconds(8 - i % 8));
                             if (i == failAt && l == 1) throw std::runtime_error("disk full");
                             log.add("file " + std::to_string(i) + "." + std::to_string(l));
                         }});
    p.submit(std::move(files),
             {{&PhaseSplit::metrics, [&log, i] { log.add("metrics " + std::to_string(i)); }},
              {&PhaseSplit::progress, [&log, i] { log.add("journal " + std::to_string(i)); }}});
}

TEST(CapturePipeline, OrderedTasksRunInFrameOrderAfterTheFramesFiles) {
    for (const int threads : {0, 1, 3}) {
        Log log;
        PhaseSplit split;
        {
            CapturePipeline p(threads, 2, split);
            for (int i = 0; i < 12; ++i) submitFrame(p, log, i);
            p.drain();
        }
        EXPECT_EQ(split.threads, threads);
        ASSERT_EQ(log.events.size(), 12u * 5u) << threads << " threads";
        std::vector<std::string> journal;
        for (const std::string& e : log.events)
            if (e.starts_with("journal")) journal.push_back(e);
        for (int i = 0; i < 12; ++i) {
            EXPECT_EQ(journal[static_cast<std::size_t>(i)], "journal " + std::to_string(i));
            const std::size_t metrics = log.index("metrics " + std::to_string(i));
            EXPECT_LT(metrics, log.index("journal " + std::to_string(i)));
            for (int l = 0; l < 3; ++l)
                EXPECT_LT(log.index("file " + std::to_string(i) + "." + std::to_string(l)), metrics)
                    << "frame " << i << ": its metrics ran before its files were written";
        }
        EXPECT_GT(split.files, 0.0);
        EXPECT_GE(split.metrics, 0.0);
    }
}

TEST(CapturePipeline, AFailureKeepsTheFramesBeforeItAndReachesTheCaller) {
    for (const int threads : {0, 2}) {
        Log log;
        PhaseSplit split;
        CapturePipeline p(threads, 2, split);
        bool thrown = false;
        try {
            for (int i = 0; i < 12; ++i) submitFrame(p, log, i, 5);
            p.drain();
        } catch (const std::runtime_error& e) {
            thrown = true;
            EXPECT_STREQ(e.what(), "disk full");
        }
        EXPECT_TRUE(thrown) << threads << " threads";
        // No journal line after a failure; every frame before it has its line. (Frame 5's
        // files failed: its line, and any later one, must not be written.)
        EXPECT_THROW(p.drain(), std::runtime_error); // the failure stays
        for (int i = 0; i < 12; ++i)
            EXPECT_EQ(log.index("journal " + std::to_string(i)) < log.events.size(), i < 5)
                << "frame " << i << ", " << threads << " threads";
    }
}

TEST(CapturePipeline, TheFramesInFlightStayWithinTheLimit) {
    PhaseSplit split;
    std::atomic<int> inFlight{0}, most{0};
    {
        CapturePipeline p(4, 2, split);
        for (int i = 0; i < 10; ++i) {
            const int now = ++inFlight;
            most = std::max(most.load(), now);
            p.submit({{&PhaseSplit::files,
                       [] { std::this_thread::sleep_for(std::chrono::milliseconds(3)); }}},
                     {{&PhaseSplit::progress, [&inFlight] { --inFlight; }}});
        }
        p.drain();
    }
    // submit() returned with at most 2 frames queued, plus the one it was given.
    EXPECT_LE(most.load(), 3);
    EXPECT_EQ(inFlight.load(), 0);
}

TEST(CapturePipeline, WithoutWorkersEveryTaskRunsInSubmit) {
    PhaseSplit split;
    CapturePipeline p(0, 2, split);
    const std::thread::id caller = std::this_thread::get_id();
    bool ran = false;
    p.submit({{&PhaseSplit::files, [&] { EXPECT_EQ(std::this_thread::get_id(), caller); }}},
             {{&PhaseSplit::metrics, [&] { ran = true; }}});
    EXPECT_TRUE(ran);
    EXPECT_EQ(split.waiting, 0.0);
}

} // namespace
} // namespace fl::app
