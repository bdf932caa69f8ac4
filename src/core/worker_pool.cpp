#include "core/worker_pool.hpp"

#include <algorithm>

namespace verve::core {

WorkerPool::WorkerPool(std::uint32_t threads) {
    for (std::uint32_t w = 1; w < threads; ++w) threads_.emplace_back([this, w] { loop(w); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
}

void WorkerPool::work(std::uint32_t worker) {
    for (;;) {
        const std::uint32_t begin = next_.fetch_add(chunk_);
        if (begin >= count_) return;
        task_(begin, std::min(count_, begin + chunk_), worker, context_);
    }
}

void WorkerPool::loop(std::uint32_t worker) {
    std::uint64_t seen = 0;
    for (;;) {
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
        }
        work(worker);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            --busy_;
        }
        idle_.notify_one();
    }
}

void WorkerPool::run(TaskFunction task, std::uint32_t count, std::uint32_t minRange, void* context) {
    if (count == 0) return;
    const auto threads = static_cast<std::uint32_t>(threads_.size() + 1);
    // A few ranges per thread balance uneven items; minRange keeps ranges worth a hand-off.
    const std::uint32_t chunk = std::max({1u, minRange, count / (4 * threads)});
    if (threads == 1 || chunk >= count) {
        task(0, count, 0, context);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        task_ = task;
        context_ = context;
        count_ = count;
        chunk_ = chunk;
        next_.store(0);
        busy_ = static_cast<std::uint32_t>(threads_.size());
        ++generation_;
    }
    wake_.notify_all();
    work(0);
    // Every thread must have left this run before the next one resets the shared fields.
    std::unique_lock<std::mutex> lock(mutex_);
    idle_.wait(lock, [&] { return busy_ == 0; });
}

}  // namespace verve::core
