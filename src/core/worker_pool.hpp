// A small fork-join pool: run() hands ranges of a task to its threads and to the caller, and
// returns when every item is done. Idle threads sleep (no spinning on a shared machine).
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "verve/batch.hpp"

namespace verve::core {

class WorkerPool {
public:
    // threads - 1 are started; the caller is worker 0. If one cannot be started (out of memory,
    // the system's thread limit), those already running are stopped and joined and the error is
    // rethrown (std::bad_alloc or std::system_error): never std::terminate.
    explicit WorkerPool(std::uint32_t threads);
    ~WorkerPool();  // joins them
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // Returns when every item is done. It waits only for the threads that joined this run (took a
    // range or looked for one), never for a thread that was not scheduled in time: the run closes
    // to latecomers once the caller has run out of ranges.
    void run(TaskFunction task, std::uint32_t count, std::uint32_t minRange, void* context);

private:
    void loop(std::uint32_t worker);
    void work(std::uint32_t worker);
    void stop() noexcept;

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::uint64_t generation_ = 0;  // one per run(): wakes the threads
    bool open_ = false;             // the current run still takes helpers
    std::uint32_t busy_ = 0;        // threads that joined the current run and have not left it
    bool stopping_ = false;

    TaskFunction task_ = nullptr;
    void* context_ = nullptr;
    std::uint32_t count_ = 0, chunk_ = 1;
    std::atomic<std::uint32_t> next_{0};
};

}  // namespace verve::core
