#include "core/worker_pool.hpp"

#include <algorithm>

namespace verve::core {

WorkerPool::WorkerPool(std::uint32_t threads) {
    try {
        threads_.reserve(threads > 1 ? threads - 1 : 0);
        for (std::uint32_t w = 1; w < threads; ++w) threads_.emplace_back([this, w] { loop(w); });
    } catch (...) {
        // A running std::thread destroyed unjoined would call std::terminate: join them first.
        stop();
        throw;
    }
}

WorkerPool::~WorkerPool() { stop(); }

void WorkerPool::stop() noexcept {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) {
        if (t.joinable()) t.join();
    }
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
            // A run that closed before this thread woke is not joined: it is done without it.
            wake_.wait(lock, [&] { return stopping_ || (open_ && generation_ != seen); });
            if (stopping_) return;
            seen = generation_;
            ++busy_;
        }
        work(worker);
        bool last = false;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            last = --busy_ == 0 && !open_;
        }
        if (last) idle_.notify_one();
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
        open_ = true;
        ++generation_;
    }
    // Wake only as many threads as there are ranges for besides the caller's first.
    const std::uint32_t ranges = (count + chunk - 1) / chunk;
    const std::uint32_t helpers = std::min<std::uint32_t>(static_cast<std::uint32_t>(threads_.size()), ranges - 1);
    for (std::uint32_t h = 0; h < helpers; ++h) wake_.notify_one();
    work(0);
    // Every range is taken: close the run, then wait for the threads inside it to finish theirs
    // (they read the shared fields, which the next run resets).
    std::unique_lock<std::mutex> lock(mutex_);
    open_ = false;
    idle_.wait(lock, [&] { return busy_ == 0; });
}

}  // namespace verve::core
