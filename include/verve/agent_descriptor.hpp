// What an agent looks like: its sensors, actions and learning constants.
// Defaults are the original library's (docs/algorithm.md lists them and why).
#pragma once
#include <cstdint>
#include <vector>

namespace verve {

enum class RbfAllocation : std::uint8_t {
    Dynamic = 0,  // an RBF is created where an observation lands far from all others
    Full = 1,     // the whole resolution^n lattice of every discrete combination at creation
};

enum class CuriosityMode : std::uint8_t {
    None = 0,
    Novelty = 1,   // thesis: reward proportional to predicted uncertainty
    Progress = 2,  // learning progress: reward for a falling prediction error
};

// How the predictive model predicts a discrete sensor's next value.
enum class DiscretePrediction : std::uint8_t {
    Categorical = 0,  // one output per value, the largest wins (no false order between values)
    Ordinal = 1,      // the original's single scalar output, rounded to the nearest value
};

// Which continuous sensors share an RBF lattice (docs/algorithm.md, "Many sensors"). One lattice
// over n sensors needs resolution^n RBFs; several over small groups, summed, need far fewer.
enum class SensorGrouping : std::uint8_t {
    Auto = 0,    // one lattice over up to 4 continuous sensors; beyond that a lattice per sensor and
                 // one per neighbouring pair (sensors i and i + 1): list related sensors together
    Joint = 1,   // one lattice over all continuous sensors (the thesis)
    Custom = 2,  // the lattices listed in sensorGroups
};

// What an agent may set for itself (AgentDescriptor::adaptation): bits.
struct Adaptation {
    // The discount horizon follows how long trials last, or rather their longest stretches of an
    // unchanged step reward: tauDiscount is then its shortest (docs/algorithm.md, "A horizon that
    // follows the trials" and "... the rewards").
    static constexpr std::uint32_t Horizon = 1u << 0;
    // The actor's steps stay reward-sized when TD errors grow with a long horizon.
    static constexpr std::uint32_t ActorScale = 1u << 1;
    // An update less than 0.1 s after the previous one learns as much as a 0.1 s decision (its
    // learning rates and trace decay), so hosts calling 50-60 times a second learn as fast per
    // decision as the thesis's 10 decisions a second (core/decision_rate.hpp).
    static constexpr std::uint32_t DecisionRate = 1u << 2;
    // With no policyWeightBound, actor weights stay at or below +10 (a sigmoid of 0.99995): a habit
    // a changed world makes wrong can be unlearned (core/habit_bound.hpp).
    static constexpr std::uint32_t HabitBound = 1u << 3;
    // One or two continuous sensors (one lattice) get a second lattice at twice the resolution,
    // its features summed with the first's: wide RBFs learn the broad shape fast, narrow ones the
    // detail a task needs (docs/algorithm.md, "A finer lattice beside a small one"). Saves made
    // without it keep their one lattice.
    static constexpr std::uint32_t FineLattice = 1u << 4;
    // Three or four continuous sensors under Auto grouping (one lattice) get, beside it, a lattice
    // over each neighbouring pair of sensors, features summed: what two sensors decide is learned
    // across the others (docs/algorithm.md, "Pairs beside a lattice of three or four sensors").
    // Saves made without it keep their one lattice.
    static constexpr std::uint32_t PairsBeside = 1u << 5;
    // With two or more sensor groups, each group's lattice learns at a rate of its own, learned from
    // the TD errors: the groups that predict them take more of each step, the others less
    // (docs/algorithm.md, "Which sensors matter"; core/group_rates.hpp). Saves made without it
    // keep one rate for all.
    static constexpr std::uint32_t GroupRates = 1u << 6;
    static constexpr std::uint32_t All = Horizon | ActorScale | DecisionRate | HabitBound | FineLattice | PairsBeside | GroupRates;
};

// Bounds on every size an agent derives from its descriptor, so that no descriptor or save can ask
// for more memory or work per update than these allow (docs/c-api.md "Limits").
struct DescriptorLimits {
    static constexpr std::uint32_t kMaxActions = 4096;
    // Sensors an agent may have, of each kind: a sensor group is a 64-bit mask of continuous sensors.
    static constexpr std::uint32_t kMaxSensors = 64;
    // Continuous sensors one RBF lattice may span: its lookup scratch is inline arrays of this size
    // (core/rbf_lattice.hpp). More sensors are read by several lattices (Auto or Custom groups).
    static constexpr std::uint32_t kMaxLatticeSensors = 16;
    static constexpr std::uint32_t kMaxResolution = 4096;
    static constexpr std::uint64_t kMaxDiscreteValues = 1ull << 31;  // per sensor: readings are int32
    static constexpr std::uint64_t kMaxDiscreteCombinations = 1ull << 53;
    static constexpr std::uint64_t kMaxModelOutputs = 65536;    // per action, with planning
    static constexpr std::uint64_t kMaxWeightsPerRbf = 1ull << 20;  // one RBF's row: 4 MiB of floats
    static constexpr std::uint64_t kMaxFullLattice = 20000000;  // RBFs created up front (Full)
    static constexpr std::uint32_t kMaxPlanningSteps = 100000;
    static constexpr std::uint64_t kDefaultMaxRbfs = 1000000;
    static constexpr std::uint64_t kMaxRbfs = 0xFFFFFFFEull;  // feature indices are 32-bit; also "unlimited"
    static constexpr std::uint32_t kMaxSensorGroups = 64;
    static constexpr std::uint32_t kMaxActionBranches = 8;
    static constexpr std::uint32_t kMaxContinuousActions = 8;
};

// Which names validate() gives the fields in its messages: the C++ members or the C ABI's.
enum class FieldNaming : std::uint8_t { Cpp, CAbi };

struct ContinuousSensor {
    bool circular = false;  // the range wraps: -1 and 1 are the same point (angles)
};

struct AgentDescriptor {
    std::vector<std::uint32_t> discreteSensors;       // number of values of each discrete sensor
    std::vector<ContinuousSensor> continuousSensors;  // each reads a value in [-1, 1]
    std::uint32_t resolution = 10;                    // RBFs across [-1, 1]; width sigma = 2 / resolution
    std::uint32_t numActions = 2;
    // Action branches (docs/algorithm.md, "Action branches"): several independent choices made on
    // every step, e.g. {3, 3, 2} for move x turn x use, each by an actor head of its own, all
    // credited by the one TD error. Empty: one set of numActions actions. With branches numActions
    // is their product and an action is the combined index a0 + n0 * (a1 + n1 * (a2 + ...)):
    // setActionBranches() sets both, branchChoice() and actionOf() convert. Masks and the policy's
    // probabilities then hold one flag or value per choice of each branch, branch after branch.
    std::vector<std::uint32_t> actionBranches;
    // Continuous actions (docs/algorithm.md, "Continuous actions"): this many bounded values in
    // [-1, 1] chosen on every step beside the discrete action (a steering angle, a throttle, a
    // torque), read with Agent::continuousAction(). Each is learned as a Gaussian whose mean and
    // spread follow the state; greedy play takes the mean. An agent that only steers keeps one
    // discrete action (numActions 1). At most DescriptorLimits::kMaxContinuousActions.
    std::uint32_t continuousActions = 0;
    RbfAllocation allocation = RbfAllocation::Dynamic;
    SensorGrouping grouping = SensorGrouping::Auto;
    // Custom grouping: one lattice per entry, a bitmask of continuous sensors (bit i: sensor i).
    // Every continuous sensor must be in at least one group. Empty otherwise.
    std::vector<std::uint64_t> sensorGroups;

    // Learning constants as time constants in seconds (thesis chapter 4).
    float tauValue = 0.1f;        // critic learning rate eta = (1 - e^(-dt/tau)) / sum
    float tauDiscount = 1.0f;     // gamma = e^(-dt/tau)
    float tauEligibility = 0.1f;  // lambda = e^(-dt/tau)
    float policyMultiplier = 5.0f;  // eta_policy = k * eta_value
    float traceThreshold = 0.01f;   // traces below this are dropped
    // > 0: each actor weight is kept within +-policyWeightBound, so a habit can be unlearned when
    // the world changes (docs/algorithm.md, "A changing world"); 0: unbounded, as in the thesis.
    float policyWeightBound = 0.0f;
    // Settings the agent sets for itself from what it experiences (Adaptation bits; default all).
    // 0 keeps every setting as given, as the thesis did: its experiments run so.
    std::uint32_t adaptation = Adaptation::All;
    std::uint64_t seed = 1;

    // Predictive model, planning and curiosity (thesis chapter 2 "Efficient learning", chapter 4).
    bool planning = false;                     // learn a model and plan after each real step
    float tauModel = 0.0f;                     // model learning time constant (0: rate 1)
    std::uint32_t maxPlanningSteps = 10;       // cap on imagined steps per real step (with continuous
                                               // sensors and no curiosity also tauDiscount / dt: docs/planning.md)
    // Uncertainty is a normalised squared error in [0, 1] per predicted quantity (docs/planning.md),
    // a different scale from the original's raw error: its 0.1 and 3 were re-measured here.
    float planningUncertaintyThreshold = 0.5f; // a plan stops once accumulated uncertainty exceeds it
    CuriosityMode curiosity = CuriosityMode::None;
    float curiosityFactor = 5.0f;              // curiosity reward = factor * uncertainty (or progress)
    // Planning variants (docs/planning.md measures each against the original's choice).
    bool planningAccumulatesUncertainty = true;  // stop on the plan's summed uncertainty (original)
                                                  // rather than on one step's
    bool learnFromRealSteps = true;   // Dyna: the critic and actor also learn from real steps
                                      // (the original learned only inside plans)
    DiscretePrediction discretePrediction = DiscretePrediction::Categorical;

    // Memory budget: at most this many RBFs (0: unlimited, i.e. DescriptorLimits::kMaxRbfs). At the
    // budget nothing more is allocated: an observation is represented by the existing RBFs within
    // reach, and AgentStats::rbfBudgetHits counts the updates that would have added one.
    std::uint64_t maxRbfs = DescriptorLimits::kDefaultMaxRbfs;
    std::uint64_t rbfBudget() const { return maxRbfs == 0 ? DescriptorLimits::kMaxRbfs : maxRbfs; }

    AgentDescriptor& addDiscreteSensor(std::uint32_t numValues) {
        discreteSensors.push_back(numValues);
        return *this;
    }
    AgentDescriptor& addContinuousSensor(bool circular = false) {
        continuousSensors.push_back(ContinuousSensor{circular});
        return *this;
    }
    // actionBranches = sizes, numActions = their product (validate() refuses a product beyond
    // DescriptorLimits::kMaxActions); no sizes: one action set of numActions again.
    AgentDescriptor& setActionBranches(std::vector<std::uint32_t> sizes);
    // Flags in an action mask, values in the policy's probabilities: the sum of the branches'
    // sizes, or numActions with one action set.
    std::uint32_t actionChoices() const;
    // Branch `branch`'s choice within the combined `action` (one action set: the action itself).
    std::uint32_t branchChoice(std::uint32_t action, std::size_t branch) const;
    // The combined action of one choice per branch (`count` = the number of branches, or 1 with one
    // action set). Throws Error(InvalidArgument) for a wrong count or a choice out of range.
    std::uint32_t actionOf(const std::uint32_t* choices, std::size_t count) const;

    // Throws verve::Error(InvalidArgument) naming the first bad field, or the fields whose derived
    // size (lattice, model outputs, weights per RBF) exceeds DescriptorLimits.
    void validate(FieldNaming naming = FieldNaming::Cpp) const;
};

}  // namespace verve
