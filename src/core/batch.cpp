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

// What a call does with each agent (Batch::Impl::mode).
enum class Mode : std::uint8_t {
    InGroup,   // updated whole by its group's worker, in array order (updateGroups)
    Prepared,  // a body whose group runs in phases (shared_step.cpp), prepared for them
    Later,     // such a body whose step would grow the brain: made whole after the phases, in order
    Failed,    // its preparation failed: left as it was
};

// The phases of a call, each a parallel run over its items.
enum class Phase : std::uint8_t { Groups, Prepare, Train, Later };

struct Batch::Impl {
    explicit Impl(const BatchOptions& o) : options(o) {}

    void updateGroups(std::uint32_t begin, std::uint32_t end) noexcept;
    void updateOne(std::uint32_t i) noexcept;  // a whole step, its failure recorded
    // Asks for the memory of the agents list[k + 1...] (of list[..last)) that the updates after
    // agent list[k] read.
    void prefetchAhead(const std::uint32_t* list, std::uint32_t k, std::uint32_t last) const noexcept;
    // Which groups run in phases: those of two or more bodies of a brain that does not plan, none
    // of them listed twice or shown an action.
    void choosePhasedGroups(const BatchStep& s);
    void runPhase(Phase phase, std::uint32_t items, std::uint32_t minRange);
    void runPhaseItems(Phase phase, std::uint32_t begin, std::uint32_t end, std::uint32_t worker) noexcept;
    void recordFailure(std::uint32_t i) noexcept;  // of the exception being handled

    BatchOptions options;
    std::unique_ptr<core::WorkerPool> pool;  // started on the first update (own pool only)

    // The call in progress, and scratch reused from call to call.
    const BatchStep* step = nullptr;
    std::vector<std::uint32_t> groupOf;     // per agent
    std::vector<std::uint32_t> groupStart;  // per group: first entry in `order`, plus an end
    std::vector<std::uint32_t> order;       // agent indices grouped, each group in array order
    std::vector<ObservationView> views;    // per agent, into the packed arrays
    std::vector<const float*> shown;        // per agent: its demonstrated continuous action (with them)
    BrainGroups brainGroups;
    FirstFailure failure;

    // Groups in phases: their agents in `phased` (phasedStart per group, plus an end), each
    // agent's mode, a lookup scratch per worker, and the parts the features are trained in. The
    // training reads only what the bodies kept: their learners (per entry of `phased`, null when
    // not prepared) and each group's weights.
    std::vector<Mode> mode;                  // per agent
    std::vector<std::uint32_t> phased;
    std::vector<std::uint32_t> phasedStart;
    std::vector<const core::TdLearner*> staged;
    std::vector<Agent::Impl::SharedStep> seen;  // per entry of `phased`: what the brain's measures see
    std::vector<core::WeightTable*> groupWeights;
    std::vector<BrainState*> groupBrain;
    std::vector<core::LookupScratch> scratch;
    std::uint32_t parts = 1;
    Phase phase = Phase::Groups;
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
    // Each update asks for the next agent's arrays from inside its loops (Agent::Impl::ahead), when
    // the crowd's arrays together outgrow the caches, as the first agent's size times the crowd's
    // tells: from the caches (a 100-agent cart-pole crowd, 3 MB) the asking only costs, out of them
    // (1,000 agents, 32 MB) it pays (docs/performance.md).
    constexpr std::size_t kQueueFromCrowdBytes = std::size_t(8) << 20;
    core::PrefetchQueue ahead;
    if (first < last) s.agents[order[first]]->impl_->addArraysTo(ahead, true);
    const bool queues = ahead.bytes() * s.count >= kQueueFromCrowdBytes;
    for (std::uint32_t k = first; k < last; ++k) {
        const std::uint32_t i = order[k];
        if (mode[i] != Mode::InGroup) continue;  // a body of a group in phases: after this run
        prefetchAhead(order.data(), k, last);
        Agent::Impl& agent = *s.agents[i]->impl_;
        if (queues && k + 1 < last) {
            const Agent::Impl& next = *s.agents[order[k + 1]]->impl_;
            ahead.clear();
            next.addArraysTo(ahead, next.brain != agent.brain);
            agent.ahead = &ahead;
        }
        updateOne(i);
        agent.ahead = nullptr;
    }
}

void Batch::Impl::prefetchAhead(const std::uint32_t* list, std::uint32_t k, std::uint32_t last) const noexcept {
    const BatchStep& s = *step;
    constexpr unsigned kStages = Agent::Impl::kPrefetchStages;
    // Stage st for the agent kStages - st places ahead: each link of an agent's chain of pointers
    // is asked for a whole update before the stage that reads it, and all of them before the
    // agent's own update. The Agent, which leads to the rest, one update earlier.
    if (k + kStages + 1 < last) core::prefetchLine(s.agents[list[k + kStages + 1]]);
    for (unsigned st = 0; st < kStages; ++st) {
        if (k + kStages - st < last) s.agents[list[k + kStages - st]]->impl_->prefetch(st);
    }
}

void Batch::Impl::updateOne(std::uint32_t i) noexcept {
    const BatchStep& s = *step;
    try {
        if (s.demonstrated != nullptr && s.demonstrated[i] != kAgentChooses) {
            if (s.demonstratedContinuous != nullptr) {
                const ContinuousActionView values{shown[i], s.agents[i]->descriptor().continuousActions};
                s.agents[i]->updateDemonstrated(s.rewards[i], views[i], s.dt, s.demonstrated[i], values);
            } else {
                s.agents[i]->updateDemonstrated(s.rewards[i], views[i], s.dt, s.demonstrated[i]);
            }
            s.actions[i] = s.demonstrated[i];
        } else {
            s.actions[i] = s.agents[i]->update(s.rewards[i], views[i], s.dt);
        }
    } catch (...) {
        recordFailure(i);
    }
}

void Batch::Impl::recordFailure(std::uint32_t i) noexcept {
    ErrorCode code = ErrorCode::Internal;
    try {
        throw;
    } catch (const Error& e) {
        code = e.code();
        failure.record(i, code, e.what());
    } catch (const std::bad_alloc&) {
        code = ErrorCode::OutOfMemory;
        failure.record(i, code, "out of memory");
    } catch (const std::exception& e) {
        failure.record(i, code, e.what());
    } catch (...) {
        failure.record(i, code, "unknown exception");
    }
    if (step->results != nullptr) step->results[i] = static_cast<int>(code);
}

void Batch::Impl::choosePhasedGroups(const BatchStep& s) {
    static std::atomic<std::uint64_t> calls{0};
    const std::uint64_t call = ++calls;  // marks the bodies this call has met (an agent listed twice)
    const auto groups = static_cast<std::uint32_t>(groupStart.size() - 1);
    phased.clear();
    phasedStart.clear();
    groupWeights.clear();
    groupBrain.clear();
    for (std::uint32_t g = 0; g < groups; ++g) {
        const std::uint32_t first = groupStart[g], last = groupStart[g + 1];
        const Agent::Impl& lead = *s.agents[order[first]]->impl_;
        if (last - first < 2 || !lead.sharesBrain || lead.desc.planning) continue;
        // A body listed twice, or shown an action, keeps its group in array order on one worker.
        bool inOrder = false;
        for (std::uint32_t k = first; k < last && !inOrder; ++k) {
            const std::uint32_t i = order[k];
            Agent::Impl& body = *s.agents[i]->impl_;
            inOrder = (s.demonstrated != nullptr && s.demonstrated[i] != kAgentChooses) || body.batchCall == call;
            body.batchCall = call;
        }
        if (inOrder) continue;
        phasedStart.push_back(static_cast<std::uint32_t>(phased.size()));
        groupWeights.push_back(&s.agents[order[first]]->impl_->weights);
        groupBrain.push_back(s.agents[order[first]]->impl_->brain.get());
        for (std::uint32_t k = first; k < last; ++k) {
            mode[order[k]] = Mode::Prepared;
            phased.push_back(order[k]);
        }
    }
    phasedStart.push_back(static_cast<std::uint32_t>(phased.size()));
    staged.assign(phased.size(), nullptr);
    seen.resize(phased.size());
}

void Batch::Impl::runPhaseItems(Phase p, std::uint32_t begin, std::uint32_t end, std::uint32_t worker) noexcept {
    const BatchStep& s = *step;
    switch (p) {
        case Phase::Groups:
            updateGroups(begin, end);
            return;
        case Phase::Prepare: {
            core::LookupScratch& mine = scratch[worker % scratch.size()];
            for (std::uint32_t k = begin; k < end; ++k) {
                prefetchAhead(phased.data(), k, end);
                // A body's live trace rows, scattered over its traces: it reads them in its choice
                // (its own step) before it keeps them, the first read otherwise a miss each (one
                // brain, 10,000 bodies: 6% more updates a second). Separate agents' training asks
                // for its rows itself.
                if (k + 2 < end) s.agents[phased[k + 2]]->impl_->td.prefetchLiveRows();
                const std::uint32_t i = phased[k];
                Agent::Impl& body = *s.agents[i]->impl_;
                try {
                    if (body.prepareShared(s.rewards[i], views[i], s.dt, mine, parts, seen[k])) {
                        s.actions[i] = body.previousAction;
                        staged[k] = &body.td;
                    } else {
                        mode[i] = Mode::Later;
                    }
                } catch (...) {
                    mode[i] = Mode::Failed;
                    recordFailure(i);
                }
            }
            return;
        }
        case Phase::Train:
            // Item = (group, part): the part's weights take every prepared body's change, in order.
            // Only what the bodies kept is read, a few bodies ahead of its use.
            for (std::uint32_t t = begin; t < end; ++t) {
                const std::uint32_t g = t / parts, part = t % parts;
                core::WeightTable& weights = *groupWeights[g];
                const std::uint32_t first = phasedStart[g], last = phasedStart[g + 1];
                for (std::uint32_t k = first; k < last; ++k) {
                    if (k + 8 < last && staged[k + 8] != nullptr) staged[k + 8]->prefetchStaged(0);
                    if (k + 4 < last && staged[k + 4] != nullptr) staged[k + 4]->prefetchStaged(1);
                    if (staged[k] != nullptr) staged[k]->trainPart(weights, part);
                }
            }
            return;
        case Phase::Later:
            for (std::uint32_t g = begin; g < end; ++g) {
                for (std::uint32_t k = phasedStart[g]; k < phasedStart[g + 1]; ++k) {
                    if (mode[phased[k]] == Mode::Later) updateOne(phased[k]);
                }
            }
            return;
    }
}

void Batch::Impl::runPhase(Phase p, std::uint32_t items, std::uint32_t minRange) {
    if (items == 0) return;
    phase = p;
    const TaskFunction task = [](std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* self) {
        auto* impl = static_cast<Impl*>(self);
        impl->runPhaseItems(impl->phase, begin, end, worker);
    };
    const TaskScheduler& host = options.scheduler;
    if (host.enqueueTask != nullptr) {
        if (void* handle = host.enqueueTask(task, items, minRange, this, host.userContext)) {
            host.finishTask(handle, host.userContext);
        }
        return;
    }
    pool->run(task, items, minRange, this);
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
        if (s.demonstratedContinuous != nullptr) b.shown.resize(s.count);
        b.order.resize(s.count);
        b.groupStart.reserve(s.count + 1);  // the sort below allocates nothing
        b.brainGroups.reset(s.count);
        b.mode.assign(s.count, Mode::InGroup);
        b.phased.reserve(s.count);
        b.phasedStart.reserve(s.count + 1);
        b.staged.reserve(s.count);
        b.seen.reserve(s.count);
        b.groupBrain.reserve(s.count);
        b.groupWeights.reserve(s.count);
        b.parts = std::min<std::uint32_t>(64, std::max(1u, b.options.workerCount));
        b.scratch.resize(std::max(1u, b.options.workerCount));
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
    std::size_t packedDiscrete = 0, packedContinuous = 0, packedShown = 0;
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
            const std::uint32_t nca = a.desc.continuousActions;
            const std::size_t at = packedShown;
            packedShown += nca;
            if (s.demonstrated != nullptr && s.demonstrated[i] != kAgentChooses) {
                core::checkDemonstratedAction(a.desc, s.demonstrated[i], nullptr);
                if (s.demonstratedContinuous != nullptr) {
                    const std::size_t sc = s.demonstratedContinuousOffsets != nullptr ? s.demonstratedContinuousOffsets[i] : at;
                    if (nca > 0 && sc + nca > s.demonstratedContinuousTotal) {
                        refuse("its " + std::to_string(nca) + " demonstrated continuous values at " + std::to_string(sc) +
                               " lie outside the demonstrated continuous array (" +
                               std::to_string(s.demonstratedContinuousTotal) + " values)");
                    }
                    b.shown[i] = nca > 0 ? s.demonstratedContinuous + sc : nullptr;
                    core::checkDemonstratedContinuous(a.desc, b.shown[i], nca);
                }
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

    b.choosePhasedGroups(s);

    b.step = &s;
    // Ranges of about 32 agents: small enough to balance, large enough that a hand-off is cheap.
    const auto minRangeFor = [&s](std::uint32_t items) {
        return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(32u * std::uint64_t(items) / std::max<std::size_t>(1, s.count)));
    };
    b.runPhase(Phase::Groups, groups, minRangeFor(groups));
    if (!b.phased.empty()) {
        // The bodies of a brain in phases (shared_step.cpp, docs/crowds.md): each acts against the
        // brain as this call found it, then their changes are applied in array order.
        const auto bodies = static_cast<std::uint32_t>(b.phased.size());
        const auto phasedGroups = static_cast<std::uint32_t>(b.phasedStart.size() - 1);
        b.runPhase(Phase::Prepare, bodies, 32);
        for (std::uint32_t g = 0; g + 1 < b.phasedStart.size(); ++g) {
            for (std::uint32_t k = b.phasedStart[g]; k < b.phasedStart[g + 1]; ++k) {
                if (b.staged[k] != nullptr) Agent::Impl::commitShared(*b.groupBrain[g], b.seen[k], *s.agents[b.phased[k]]->impl_);
            }
        }
        b.runPhase(Phase::Train, phasedGroups * b.parts, 1);
        b.runPhase(Phase::Later, phasedGroups, 1);
    }
    b.step = nullptr;
    b.failure.rethrow();
}

}  // namespace verve
