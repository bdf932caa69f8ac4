using System;

namespace Verve
{
    /// <summary>How RBFs of continuous sensors are created (<c>verve_rbf_allocation</c>).</summary>
    public enum RbfAllocation : uint
    {
        /// <summary>RBFs are created where observations land (default).</summary>
        Dynamic = 0,
        /// <summary>The whole lattice is created up front.</summary>
        Full = 1,
    }

    /// <summary>Which continuous sensors share an RBF lattice (<c>verve_sensor_grouping</c>). One lattice over
    /// n sensors needs resolution^n RBFs; several lattices over small groups, their features summed, need far
    /// fewer and let an agent with many sensors learn.</summary>
    public enum SensorGrouping : uint
    {
        /// <summary>One lattice over up to 4 continuous sensors; beyond that one per sensor and one per
        /// neighbouring pair (sensors i and i + 1), so list related sensors next to each other (default).</summary>
        Auto = 0,
        /// <summary>One lattice over all continuous sensors (the thesis): resolution^n RBFs.</summary>
        Joint = 1,
        /// <summary>The lattices given by <see cref="AgentOptions.AddSensorGroup(int[])"/>.</summary>
        Custom = 2,
    }

    /// <summary>Settings an agent sets for itself from what it experiences (<c>VERVE_ADAPT_*</c> bits).</summary>
    [Flags]
    public enum Adaptation : ulong
    {
        /// <summary>Every setting as given (as the thesis ran its experiments).</summary>
        None = 0,
        /// <summary>The discount horizon follows how long trials last; <c>TauDiscount</c> is its shortest.</summary>
        Horizon = 1,
        /// <summary>The actor's steps stay reward-sized when TD errors grow with a long horizon.</summary>
        ActorScale = 2,
        /// <summary>An update less than 0.1 s after the previous one learns as much as a 0.1 s decision.</summary>
        DecisionRate = 4,
        /// <summary>With <c>PolicyWeightBound</c> 0, actor weights stay at or below +10, so a habit a
        /// changed world makes wrong can be unlearned.</summary>
        HabitBound = 8,
        /// <summary>One or two continuous sensors get a second RBF lattice at twice the resolution
        /// beside the first: wide RBFs learn the broad shape fast, narrow ones the detail.</summary>
        FineLattice = 16,
        /// <summary>Three or four continuous sensors under automatic grouping get, beside their
        /// lattice, one over each neighbouring pair: what two sensors decide is learned across the
        /// others.</summary>
        PairsBeside = 32,
        /// <summary>Two or more sensor groups learn at rates of their own, learned from the TD
        /// errors: the groups that predict them take more of each step.</summary>
        GroupRates = 64,
        /// <summary>All of them (the default).</summary>
        All = Horizon | ActorScale | DecisionRate | HabitBound | FineLattice | PairsBeside | GroupRates,
    }

    /// <summary>Intrinsic reward added during planning (<c>verve_curiosity</c>).</summary>
    public enum Curiosity : uint
    {
        /// <summary>No curiosity reward.</summary>
        None = 0,
        /// <summary>Reward proportional to predicted uncertainty (the thesis).</summary>
        Novelty = 1,
        /// <summary>Reward for a falling prediction error (ignores pure noise).</summary>
        Progress = 2,
    }

    /// <summary>How <see cref="Agent.Update(float, int[], float[], float)"/> picks its action (<c>verve_action_selection</c>).</summary>
    public enum ActionSelection : uint
    {
        /// <summary>Each action with its probability: explores while learning (default).</summary>
        Sample = 0,
        /// <summary>Always the most probable action: deterministic play for a shipped NPC.</summary>
        Greedy = 1,
    }

    /// <summary>How the predictive model predicts a discrete sensor (<c>verve_discrete_prediction</c>).</summary>
    public enum DiscretePrediction : uint
    {
        /// <summary>One output per value; the largest wins (default).</summary>
        Categorical = 0,
        /// <summary>The original library's single scalar, rounded to the nearest value.</summary>
        Ordinal = 1,
    }

    /// <summary>Which kind of sensor a <see cref="ValueAxis"/> sweeps (<c>verve_sensor_kind</c>).</summary>
    public enum SensorKind : uint
    {
        /// <summary>A sensor reading one of N integer values.</summary>
        Discrete = 0,
        /// <summary>A sensor reading a float in [-1, 1].</summary>
        Continuous = 1,
    }
}
