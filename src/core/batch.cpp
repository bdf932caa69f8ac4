// verve::Batch: validate every input, group the agents by brain, update the groups in parallel.
#include "verve/batch.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "core/agent_impl.hpp"
#include "core/observation_check.hpp"
#include "core/prefetch.hpp"
#include "core/worker_pool.hpp"

namespace verve {
namespace {

[[noreturn]] void refuse(const std::string& message) { throw Error(ErrorCode::InvalidArgument, message); }

// Which group of the current call each brain is in: an open-addressing table of the call's own
// (kept in the Batch for its memory, used by one call at a time), so that nothing is written into
// the brains a call reads. Two concurrent calls that share a brain (a misuse of the C++ API, which
// the C ABI refuses) can race on the brain's weights, but never on the grouping.
class BrainGroups {
public:
    // Empties the table, with room for `agents` brains at most.
    void reset(std::size_t agents) {
        std::size_t size = 16;
        while (size < 2 * agents) size *= 2;
        slots_.assign(size, Slot{});
        last_ = nullptr;
        groups_ = 0;
    }
    // The group of `brain`, a new one the first time the call meets it.
    std::uint32_t of(const BrainState* brain) {
        if (brain == last_) return lastGroup_;  // a crowd's bodies usually come together
        const std::size_t mask = slots_.size() - 1;
        const std::uint64_t key = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(brain) >> 4);
        std::size_t at = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
        while (slots_[at].brain != nullptr && slots_[at].brain != brain) at = (at + 1) & mask;
        if (slots_[at].brain == nullptr) slots_[at] = Slot{brain, groups_++};
        last_ = brain;
        lastGroup_ = slots_[at].group;
        return lastGroup_;
    }
    std::uint32_t count() const { return groups_; }

private:
    struct Slot {
        const BrainState* brain = nullptr;
        std::uint32_t group = 0;
    };
    std::vector<Slot> slots_;
    const BrainState* last_ = nullptr;
    std::uint32_t lastGroup_ = 0;
    std::uint32_t groups_ = 0;
};

// The failure of the lowest-numbered agent, whichever worker saw it first.
struct FirstFailure {
    std::mutex mutex;
    std::size_t index = SIZE_MAX;
    ErrorCode code = ErrorCode::Internal;
    std::string message;

    void record(std::size_t i, ErrorCode c, const char* what) noexcept {
        std::lock_guard<std::mutex> lock(mutex);
        if (i >= index) return;
        index = i;
        code = c;
        try {
            message = what;
        } catch (...) {
            message.clear();  // out of memory while reporting: the code still says it
        }
    }
    void rethrow() const {
        if (index != SIZE_MAX) throw Error(code, "agents[" + std::to_string(index) + "]: " + message);
    }
};

}  // namespace

struct Batch::Impl {
    explicit Impl(const BatchOptions& o) : options(o) {}

    void updateGroups(std::uint32_t begin, std::uint32_t end) noexcept;
    void runOverGroups();

    BatchOptions options;
    std::unique_ptr<core::WorkerPool> pool;  // started on the first update (own pool only)

    // The call in progress, and scratch reused from call to call.
    const BatchStep* step = nullptr;
    std::vector<std::uint32_t> groupOf;     // per agent
    std::vector<std::uint32_t> groupStart;  // per group: first entry in `order`, plus an end
    std::vector<std::uint32_t> order;       // agent indices grouped, each group in array order
    std::vector<ObservationView> views;    // per agent, into the packed arrays
    BrainGroups brainGroups;
    FirstFailure failure;
};

Batch::Batch(const BatchOptions& options) : impl_(std::make_unique<Impl>(options)) {
    const TaskScheduler& s = options.scheduler;
    if ((s.enqueueTask == nullptr) != (s.finishTask == nullptr)) {
        refuse("a task scheduler needs both enqueueTask and finishTask (or neither, for Verve's own pool)");
    }
    if (s.enqueueTask != nullptr && options.workerCount == 0) refuse("a task scheduler needs its workerCount (>= 1)");
    if (options.workerCount > 1024) refuse("workerCount " + std::to_string(options.workerCount) + " is above 1024");
    if (s.enqueueTask == nullptr && impl_->options.workerCount == 0) {
        impl_->options.workerCount = std::max(1u, std::thread::hardware_concurrency());
    }
}

Batch::~Batch() = default;

std::uint32_t Batch::workerCount() const { return impl_->options.workerCount; }

void Batch::Impl::updateGroups(std::uint32_t begin, std::uint32_t end) noexcept {
    const BatchStep& s = *step;
    // The groups' agents lie together in `order`, each group in its update order.
    const std::uint32_t first = groupStart[begin], last = groupStart[end];
    constexpr unsigned kStages = Agent::Impl::kPrefetchStages;
    // Each update asks for the next agent's arrays from inside its loops (Agent::Impl::ahead), when
    // the crowd's arrays together outgrow the caches, as the first agent's size times the crowd's
    // tells: from the caches (a 100-agent cart-pole crowd, 3 MB) the asking only costs, out of them
    // (1,000 agents, 32 MB) it pays (docs/performance.md).
    constexpr std::size_t kQueueFromCrowdBytes = std::size_t(8) << 20;
    core::PrefetchQueue ahead;
    if (first < last) s.agents[order[first]]->impl_->addArraysTo(ahead, true);
    const bool queues = ahead.bytes() * s.count >= kQueueFromCrowdBytes;
    for (std::uint32_t k = first; k < last; ++k) {
        // Stage st for the agent kStages - st places ahead: each link of an agent's chain of
        // pointers is asked for a whole update before the stage that reads it, and all of them
        // before the agent's own update. The Agent, which leads to the rest, one update earlier.
        if (k + kStages + 1 < last) core::prefetchLine(s.agents[order[k + kStages + 1]]);
        for (unsigned st = 0; st < kStages; ++st) {
            if (k + kStages - st < last) s.agents[order[k + kStages - st]]->impl_->prefetch(st);
        }
        const std::uint32_t i = order[k];
        Agent::Impl& agent = *s.agents[i]->impl_;
        if (queues && k + 1 < last) {
            const Agent::Impl& next = *s.agents[order[k + 1]]->impl_;
            ahead.clear();
            next.addArraysTo(ahead, next.brain != agent.brain);
            agent.ahead = &ahead;
        }
        ErrorCode code = ErrorCode::Internal;
        const char* what = "unknown exception";
        try {
            if (s.demonstrated != nullptr && s.demonstrated[i] != kAgentChooses) {
                s.agents[i]->updateDemonstrated(s.rewards[i], views[i], s.dt, s.demonstrated[i]);
                s.actions[i] = s.demonstrated[i];
            } else {
                s.actions[i] = s.agents[i]->update(s.rewards[i], views[i], s.dt);
            }
            agent.ahead = nullptr;
            continue;
        } catch (const Error& e) {
            code = e.code();
            failure.record(i, code, e.what());
        } catch (const std::bad_alloc&) {
            code = ErrorCode::OutOfMemory;
            failure.record(i, code, "out of memory");
        } catch (const std::exception& e) {
            failure.record(i, code, e.what());
        } catch (...) {
            failure.record(i, code, what);
        }
        agent.ahead = nullptr;
        if (s.results != nullptr) s.results[i] = static_cast<int>(code);
    }
}

void Batch::Impl::runOverGroups() {
    const auto groups = static_cast<std::uint32_t>(groupStart.size() - 1);
    const TaskFunction task = [](std::uint32_t begin, std::uint32_t end, std::uint32_t, void* self) {
        static_cast<Impl*>(self)->updateGroups(begin, end);
    };
    // Ranges of about 32 agents: small enough to balance, large enough that a hand-off is cheap.
    const std::uint32_t minRange = std::max<std::uint32_t>(1, 32u * groups / std::max<std::uint32_t>(1, static_cast<std::uint32_t>(step->count)));
    const TaskScheduler& host = options.scheduler;
    if (host.enqueueTask != nullptr) {
        if (void* handle = host.enqueueTask(task, groups, minRange, this, host.userContext)) {
            host.finishTask(handle, host.userContext);
        }
        return;
    }
    pool->run(task, groups, minRange, this);
}

namespace {

// A refusal of the whole call (before any agent's own check) is every agent's verdict: none of
// them was updated, so none may read as fine (issue 32).
template <typename Body>
void refusingAll(const BatchStep& s, Body&& body) {
    try {
        body();
    } catch (...) {
        int code = static_cast<int>(ErrorCode::Internal);
        try {
            throw;
        } catch (const Error& e) {
            code = static_cast<int>(e.code());
        } catch (const std::bad_alloc&) {
            code = static_cast<int>(ErrorCode::OutOfMemory);
        } catch (...) {
        }
        if (s.results != nullptr) {
            for (std::size_t i = 0; i < s.count; ++i) s.results[i] = code;
        }
        throw;
    }
}

}  // namespace

void Batch::update(const BatchStep& s) {
    Impl& b = *impl_;
    if (s.count == 0) return;
    refusingAll(s, [&] {
        if (s.count > UINT32_MAX - 1) refuse("count " + std::to_string(s.count) + " is too large");
        if (s.agents == nullptr || s.rewards == nullptr || s.actions == nullptr) {
            refuse("agents, rewards and actions must not be NULL");
        }
        core::checkTimeStep(s.dt);
        // The scratch, and the pool's threads on the first call: a failure to start them (out of
        // memory, the system's thread limit) refuses the call before anything changed.
        b.groupOf.resize(s.count);
        b.views.resize(s.count);
        b.order.resize(s.count);
        b.groupStart.reserve(s.count + 1);  // the sort below allocates nothing
        b.brainGroups.reset(s.count);
        if (b.options.scheduler.enqueueTask == nullptr && !b.pool) {
            try {
                b.pool = std::make_unique<core::WorkerPool>(b.options.workerCount);
            } catch (const std::system_error& e) {
                throw Error(ErrorCode::OutOfMemory, std::string("cannot start the batch's worker threads: ") + e.what());
            }
        }
    });

    // Check every agent's input and find its group (its brain) before anything changes.
    b.failure.index = SIZE_MAX;
    std::size_t packedDiscrete = 0, packedContinuous = 0;
    // The check reads little of each agent, so its links are asked for further ahead than the
    // update's: an agent's members 16 agents ahead, its brain 8 ahead.
    const auto prefetchCheck = [&s](std::size_t i, unsigned stage) {
        if (i < s.count && s.agents[i] != nullptr) s.agents[i]->impl_->prefetchCheck(stage);
    };
    for (std::size_t i = 0; i < s.count; ++i) {
        prefetchCheck(i + 16, 0);
        prefetchCheck(i + 8, 1);
        int code = 0;
        try {
            if (s.agents[i] == nullptr) refuse("agent is NULL");
            Agent::Impl& a = *s.agents[i]->impl_;
            const std::size_t nd = a.desc.discreteSensors.size(), nc = a.desc.continuousSensors.size();
            const std::size_t d = s.discreteOffsets != nullptr ? s.discreteOffsets[i] : packedDiscrete;
            const std::size_t c = s.continuousOffsets != nullptr ? s.continuousOffsets[i] : packedContinuous;
            packedDiscrete += nd;
            packedContinuous += nc;
            if (nd > 0 && (s.discrete == nullptr || d + nd > s.discreteTotal)) {
                refuse("its " + std::to_string(nd) + " discrete values at " + std::to_string(d) +
                       " lie outside the discrete array (" + std::to_string(s.discreteTotal) + " values)");
            }
            if (nc > 0 && (s.continuous == nullptr || c + nc > s.continuousTotal)) {
                refuse("its " + std::to_string(nc) + " continuous values at " + std::to_string(c) +
                       " lie outside the continuous array (" + std::to_string(s.continuousTotal) + " values)");
            }
            b.views[i] = ObservationView{nd > 0 ? s.discrete + d : nullptr, nd, nc > 0 ? s.continuous + c : nullptr, nc};
            core::checkObservation(a.desc, b.views[i]);
            core::checkFinite(s.rewards[i], "reward");
            if (s.demonstrated != nullptr && s.demonstrated[i] != kAgentChooses) {
                core::checkDemonstratedAction(a.desc, s.demonstrated[i], nullptr);
            }
            b.groupOf[i] = b.brainGroups.of(a.brain.get());
        } catch (const Error& e) {
            code = static_cast<int>(e.code());
            b.failure.record(i, e.code(), e.what());
        }
        if (s.results != nullptr) s.results[i] = code;
    }
    b.failure.rethrow();

    // Counting sort: each group's agents together, in array order.
    const std::uint32_t groups = b.brainGroups.count();
    b.groupStart.assign(std::size_t(groups) + 1, 0);
    for (std::size_t i = 0; i < s.count; ++i) ++b.groupStart[b.groupOf[i] + 1];
    for (std::uint32_t g = 0; g < groups; ++g) b.groupStart[g + 1] += b.groupStart[g];
    for (std::size_t i = 0; i < s.count; ++i) b.order[b.groupStart[b.groupOf[i]]++] = static_cast<std::uint32_t>(i);
    for (std::uint32_t g = groups; g > 0; --g) b.groupStart[g] = b.groupStart[g - 1];
    b.groupStart[0] = 0;

    b.step = &s;
    b.runOverGroups();
    b.step = nullptr;
    b.failure.rethrow();
}

}  // namespace verve
