using System;
using System.Collections.Generic;
using Verve.Native;

namespace Verve
{
    /// <summary>Describes an agent: its sensors, actions and learning constants
    /// (<c>verve_agent_desc</c>). A new instance holds the native library's defaults; the native
    /// library validates the whole description when an <see cref="Agent"/> is created.</summary>
    /// <example><code>
    /// var options = new AgentOptions { Actions = 3, Seed = 42 }
    ///     .AddDiscreteSensor(2)
    ///     .AddContinuousSensor(circular: true);
    /// </code></example>
    public sealed class AgentOptions
    {
        /// <summary>Most discrete sensors an agent can have.</summary>
        public const int MaxDiscreteSensors = verve_agent_desc.MaxDiscreteSensors;
        /// <summary>Most continuous sensors an agent can have.</summary>
        public const int MaxContinuousSensors = verve_agent_desc.MaxContinuousSensors;

        private readonly List<int> _discreteSensors = new List<int>();
        private readonly List<bool> _continuousCircular = new List<bool>();
        private int _actions;
        private int _resolution;
        private int _maxPlanningSteps;

        /// <summary>Options with the library's defaults (<c>verve_agent_desc_init</c>) and no sensors.</summary>
        public AgentOptions() : this(DefaultDescriptor()) { }

        internal unsafe AgentOptions(in verve_agent_desc d)
        {
            fixed (verve_agent_desc* p = &d)
            {
                for (int i = 0; i < Math.Min(d.num_discrete_sensors, MaxDiscreteSensors); i++)
                    _discreteSensors.Add((int)p->discrete_sensor_values[i]);
                for (int i = 0; i < Math.Min(d.num_continuous_sensors, MaxContinuousSensors); i++)
                    _continuousCircular.Add(p->continuous_sensor_circular[i] != 0);
            }
            _resolution = (int)d.resolution;
            _actions = (int)d.num_actions;
            RbfAllocation = (RbfAllocation)d.rbf_allocation;
            TauValue = d.tau_value;
            TauDiscount = d.tau_discount;
            TauEligibility = d.tau_eligibility;
            PolicyMultiplier = d.policy_multiplier;
            TraceThreshold = d.trace_threshold;
            Seed = d.seed;
            Planning = d.planning != 0;
            TauModel = d.tau_model;
            _maxPlanningSteps = (int)d.max_planning_steps;
            PlanningUncertaintyThreshold = d.planning_uncertainty_threshold;
            Curiosity = (Curiosity)d.curiosity;
            CuriosityFactor = d.curiosity_factor;
            PlanningAccumulatesUncertainty = d.planning_accumulates_uncertainty != 0;
            LearnFromRealSteps = d.learn_from_real_steps != 0;
            DiscretePrediction = (DiscretePrediction)d.discrete_prediction;
            MaxRbfs = (long)d.max_rbfs;
            PolicyWeightBound = d.policy_weight_bound;
            Adaptation = (Adaptation)d.adaptation;
        }

        /// <summary>Value count of each discrete sensor, in observation order.</summary>
        public IReadOnlyList<int> DiscreteSensors => _discreteSensors.AsReadOnly();

        /// <summary>Whether each continuous sensor wraps around (angles), in observation order.</summary>
        public IReadOnlyList<bool> ContinuousSensorCircular => _continuousCircular.AsReadOnly();

        /// <summary>Number of actions the agent chooses from.</summary>
        public int Actions { get => _actions; set => _actions = NonNegative(value, nameof(Actions)); }

        /// <summary>RBFs across [-1, 1] per continuous sensor (RBF width 2 / resolution).</summary>
        public int Resolution { get => _resolution; set => _resolution = NonNegative(value, nameof(Resolution)); }

        /// <summary>Whether continuous-sensor RBFs are created on demand or all up front.</summary>
        public RbfAllocation RbfAllocation { get; set; }

        /// <summary>Critic learning time constant, seconds.</summary>
        public float TauValue { get; set; }

        /// <summary>Discount time constant, seconds (gamma = e^(-dt/tau)).</summary>
        public float TauDiscount { get; set; }

        /// <summary>Eligibility-trace time constant, seconds (lambda = e^(-dt/tau)).</summary>
        public float TauEligibility { get; set; }

        /// <summary>Actor learning rate as a multiple of the critic's.</summary>
        public float PolicyMultiplier { get; set; }

        /// <summary>Eligibility traces below this are dropped.</summary>
        public float TraceThreshold { get; set; }

        /// <summary>Seed of the agent's own random stream: same seed and inputs, same actions.</summary>
        public ulong Seed { get; set; }

        /// <summary>Learn a predictive model and plan imagined steps after each real step.</summary>
        public bool Planning { get; set; }

        /// <summary>Model learning time constant, seconds (0: learning rate 1).</summary>
        public float TauModel { get; set; }

        /// <summary>Cap on imagined steps per real step.</summary>
        public int MaxPlanningSteps { get => _maxPlanningSteps; set => _maxPlanningSteps = NonNegative(value, nameof(MaxPlanningSteps)); }

        /// <summary>A plan stops once accumulated predicted uncertainty exceeds this.</summary>
        public float PlanningUncertaintyThreshold { get; set; }

        /// <summary>Intrinsic reward used while planning.</summary>
        public Curiosity Curiosity { get; set; }

        /// <summary>Curiosity reward = factor * uncertainty (or progress).</summary>
        public float CuriosityFactor { get; set; }

        /// <summary>A plan stops on its summed uncertainty (true, the original's rule) or on one step's.</summary>
        public bool PlanningAccumulatesUncertainty { get; set; }

        /// <summary>Real steps train the critic and actor too, not only plans (Dyna; default true).</summary>
        public bool LearnFromRealSteps { get; set; }

        /// <summary>How the model predicts discrete sensors.</summary>
        public DiscretePrediction DiscretePrediction { get; set; }

        /// <summary>RBF budget (<c>max_rbfs</c>, default 1,000,000; 0: unlimited). At the budget the agent
        /// keeps working with the RBFs it has; <see cref="AgentStats.RbfBudgetHits"/> counts the misses.</summary>
        public long MaxRbfs { get; set; }
        /// <summary>Above 0, every actor weight stays within +-bound, so a habit can be unlearned when the
        /// world changes (with a slow critic and a large policy multiplier); 0 (default): unbounded.</summary>
        public float PolicyWeightBound { get; set; }
        /// <summary>Settings the agent sets for itself from what it experiences (default
        /// <see cref="Verve.Adaptation.All"/>); <see cref="Verve.Adaptation.None"/> keeps every setting as given.</summary>
        public Adaptation Adaptation { get; set; }

        /// <summary>Adds a discrete sensor reading integers 0 .. <paramref name="values"/> - 1.</summary>
        public AgentOptions AddDiscreteSensor(int values)
        {
            NonNegative(values, nameof(values));
            if (_discreteSensors.Count == MaxDiscreteSensors)
                throw new InvalidOperationException($"an agent has at most {MaxDiscreteSensors} discrete sensors");
            _discreteSensors.Add(values);
            return this;
        }

        /// <summary>Adds a continuous sensor reading floats in [-1, 1]; a circular one wraps
        /// (-1 and 1 are the same point), for angles.</summary>
        public AgentOptions AddContinuousSensor(bool circular = false)
        {
            if (_continuousCircular.Count == MaxContinuousSensors)
                throw new InvalidOperationException($"an agent has at most {MaxContinuousSensors} continuous sensors");
            _continuousCircular.Add(circular);
            return this;
        }

        /// <summary>Removes all sensors.</summary>
        public AgentOptions ClearSensors()
        {
            _discreteSensors.Clear();
            _continuousCircular.Clear();
            return this;
        }

        internal unsafe verve_agent_desc ToNative()
        {
            var d = new verve_agent_desc { struct_size = (uint)sizeof(verve_agent_desc) };
            d.num_discrete_sensors = (uint)_discreteSensors.Count;
            for (int i = 0; i < _discreteSensors.Count; i++) d.discrete_sensor_values[i] = (uint)_discreteSensors[i];
            d.num_continuous_sensors = (uint)_continuousCircular.Count;
            for (int i = 0; i < _continuousCircular.Count; i++) d.continuous_sensor_circular[i] = _continuousCircular[i] ? (byte)1 : (byte)0;
            d.resolution = (uint)_resolution;
            d.num_actions = (uint)_actions;
            d.rbf_allocation = (uint)RbfAllocation;
            d.tau_value = TauValue;
            d.tau_discount = TauDiscount;
            d.tau_eligibility = TauEligibility;
            d.policy_multiplier = PolicyMultiplier;
            d.trace_threshold = TraceThreshold;
            d.seed = Seed;
            d.planning = Planning ? 1u : 0u;
            d.tau_model = TauModel;
            d.max_planning_steps = (uint)_maxPlanningSteps;
            d.planning_uncertainty_threshold = PlanningUncertaintyThreshold;
            d.curiosity = (uint)Curiosity;
            d.curiosity_factor = CuriosityFactor;
            d.planning_accumulates_uncertainty = PlanningAccumulatesUncertainty ? 1u : 0u;
            d.learn_from_real_steps = LearnFromRealSteps ? 1u : 0u;
            d.discrete_prediction = (uint)DiscretePrediction;
            d.max_rbfs = MaxRbfs < 0 ? ulong.MaxValue : (ulong)MaxRbfs; // negative: refused by the library
            d.policy_weight_bound = PolicyWeightBound;
            d.adaptation = (ulong)Adaptation;
            return d;
        }

        // verve_agent_desc_init writes only sizeof(our struct) bytes, so this binding stays safe with a
        // newer library whose struct has grown.
        private static unsafe verve_agent_desc DefaultDescriptor()
        {
            VerveLibrary.EnsureCompatible();
            var d = new verve_agent_desc();
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_desc_init(&d, (uint)sizeof(verve_agent_desc)));
            return d;
        }

        private static int NonNegative(int value, string name) =>
            value >= 0 ? value : throw new ArgumentOutOfRangeException(name, value, "must be >= 0");
    }
}
