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
    explicit WorkerPool(std::uint32_t threads);  // threads - 1 are started; the caller is worker 0
    ~WorkerPool();                               // joins them
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    void run(TaskFunction task, std::uint32_t count, std::uint32_t minRange, void* context);

private:
    void loop(std::uint32_t worker);
    void work(std::uint32_t worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::uint64_t generation_ = 0;  // one per run(): wakes the threads
    std::uint32_t busy_ = 0;        // threads still inside the current run
    bool stopping_ = false;

    TaskFunction task_ = nullptr;
    void* context_ = nullptr;
    std::uint32_t count_ = 0, chunk_ = 1;
    std::atomic<std::uint32_t> next_{0};
};

}  // namespace verve::core
