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
        /// <summary>Most discrete sensors an agent can have (64; 16 before issue 30).</summary>
        public const int MaxDiscreteSensors = verve_agent_desc.MaxSensors;
        /// <summary>Most continuous sensors an agent can have (64). Beyond 16 they need
        /// <see cref="SensorGrouping.Auto"/> (up to 32) or <see cref="SensorGrouping.Custom"/> groups.</summary>
        public const int MaxContinuousSensors = verve_agent_desc.MaxSensors;
        /// <summary>Most continuous sensors one RBF lattice spans: a <see cref="SensorGrouping.Joint"/>
        /// grouping or one <see cref="SensorGrouping.Custom"/> group over more is refused.</summary>
        public const int MaxLatticeSensors = verve_agent_desc.MaxLatticeSensors;
        /// <summary>Most sensor groups (lattices) a <see cref="SensorGrouping.Custom"/> grouping can list.</summary>
        public const int MaxSensorGroups = verve_agent_desc.MaxSensorGroups;
        /// <summary>Most action branches an agent can have.</summary>
        public const int MaxActionBranches = verve_agent_desc.MaxActionBranches;
        /// <summary>Most continuous actions an agent can have.</summary>
        public const int MaxContinuousActions = verve_agent_desc.MaxContinuousActions;

        private readonly List<int> _discreteSensors = new List<int>();
        private readonly List<bool> _continuousCircular = new List<bool>();
        private readonly List<IReadOnlyList<int>> _sensorGroups = new List<IReadOnlyList<int>>();
        private readonly List<int> _actionBranches = new List<int>();
        private int _actions;
        private int _resolution;
        private int _maxPlanningSteps;
        private int _continuousActions;

        /// <summary>Options with the library's defaults (<c>verve_agent_desc_init</c>) and no sensors.</summary>
        public AgentOptions() : this(DefaultDescriptor()) { }

        internal unsafe AgentOptions(in verve_agent_desc d)
        {
            fixed (verve_agent_desc* p = &d)
            {
                const int old = verve_agent_desc.MaxDiscreteSensors; // sensors beyond it: the V8 arrays
                for (int i = 0; i < Math.Min(d.num_discrete_sensors, MaxDiscreteSensors); i++)
                    _discreteSensors.Add((int)(i < old ? p->discrete_sensor_values[i] : p->more_discrete_sensor_values[i - old]));
                for (int i = 0; i < Math.Min(d.num_continuous_sensors, MaxContinuousSensors); i++)
                    _continuousCircular.Add((i < old ? p->continuous_sensor_circular[i] : p->more_continuous_sensor_circular[i - old]) != 0);
                for (int i = 0; i < Math.Min(d.num_sensor_groups, MaxSensorGroups); i++)
                    _sensorGroups.Add(SensorsOf(p->sensor_groups[i]));
                for (int i = 0; i < Math.Min(d.num_action_branches, MaxActionBranches); i++)
                    _actionBranches.Add((int)p->action_branches[i]);
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
            Grouping = (SensorGrouping)d.sensor_grouping;
            _continuousActions = (int)Math.Min(d.num_continuous_actions, (ulong)MaxContinuousActions);
        }

        /// <summary>Value count of each discrete sensor, in observation order.</summary>
        public IReadOnlyList<int> DiscreteSensors => _discreteSensors.AsReadOnly();

        /// <summary>Whether each continuous sensor wraps around (angles), in observation order.</summary>
        public IReadOnlyList<bool> ContinuousSensorCircular => _continuousCircular.AsReadOnly();

        /// <summary>Number of actions the agent chooses from. With <see cref="ActionBranches"/>, the number of
        /// combined actions: <see cref="SetActionBranches(int[])"/> sets it to their product, and any other
        /// value is refused when the agent is created. With <see cref="ContinuousActions"/> and no branches, 0 means 1.</summary>
        public int Actions { get => _actions; set => _actions = NonNegative(value, nameof(Actions)); }

        /// <summary>How many continuous actions (values in [-1, 1]: steering, throttle, a torque) the agent
        /// chooses on every step beside its discrete action, read after each update with
        /// <see cref="Agent.ContinuousAction"/> or <see cref="Agent.GetContinuousAction(Span{float})"/>
        /// (default 0: none). With continuous actions and no <see cref="ActionBranches"/>, <see cref="Actions"/>
        /// 0 means 1: an agent that only steers keeps one trivial discrete action. Not with planning.</summary>
        /// <exception cref="ArgumentOutOfRangeException">Below 0 or above <see cref="MaxContinuousActions"/>.</exception>
        public int ContinuousActions
        {
            get => _continuousActions;
            set => _continuousActions = value >= 0 && value <= MaxContinuousActions ? value
                : throw new ArgumentOutOfRangeException(nameof(ContinuousActions), value,
                    $"an agent has 0 to {MaxContinuousActions} continuous actions");
        }

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

        /// <summary>Which continuous sensors share an RBF lattice (default <see cref="SensorGrouping.Auto"/>: one
        /// lattice up to 4 continuous sensors, beyond that one per sensor and one per neighbouring pair, which
        /// suits an NPC with many sensors). <see cref="AddSensorGroup(int[])"/> sets it to
        /// <see cref="SensorGrouping.Custom"/>.</summary>
        public SensorGrouping Grouping { get; set; }

        /// <summary>The lattices of a <see cref="SensorGrouping.Custom"/> grouping: each the continuous sensors
        /// (indices from 0, ascending) one lattice spans. Empty for the other groupings.</summary>
        public IReadOnlyList<IReadOnlyList<int>> SensorGroups => _sensorGroups.AsReadOnly();

        /// <summary>Adds a lattice over the continuous sensors listed (indices from 0, in the order they were
        /// added) and sets <see cref="Grouping"/> to <see cref="SensorGrouping.Custom"/>. Every continuous
        /// sensor must end up in at least one group; a sensor may be in several.</summary>
        /// <example><code>
        /// // 12 sensors: a lattice per sensor, and one over the bearing and distance (sensors 0 and 1) together.
        /// for (int i = 0; i &lt; 12; i++) options.AddSensorGroup(i);
        /// options.AddSensorGroup(0, 1);
        /// </code></example>
        /// <exception cref="ArgumentException">No sensor, a sensor listed twice, or an index outside
        /// 0 .. <see cref="MaxContinuousSensors"/> - 1.</exception>
        /// <exception cref="InvalidOperationException"><see cref="MaxSensorGroups"/> groups are already listed.</exception>
        public AgentOptions AddSensorGroup(params int[] sensors)
        {
            if (sensors == null) throw new ArgumentNullException(nameof(sensors));
            if (sensors.Length == 0)
                throw new ArgumentException("a sensor group lists at least one continuous sensor", nameof(sensors));
            ulong mask = 0;
            foreach (int sensor in sensors)
            {
                if (sensor < 0 || sensor >= MaxContinuousSensors)
                    throw new ArgumentOutOfRangeException(nameof(sensors), sensor,
                        $"a sensor group lists continuous sensors by index, 0 to {MaxContinuousSensors - 1}");
                if ((mask & (1UL << sensor)) != 0)
                    throw new ArgumentException($"continuous sensor {sensor} is listed twice in one sensor group", nameof(sensors));
                mask |= 1UL << sensor;
            }
            if (_sensorGroups.Count == MaxSensorGroups)
                throw new InvalidOperationException($"an agent has at most {MaxSensorGroups} sensor groups");
            _sensorGroups.Add(SensorsOf(mask));
            Grouping = SensorGrouping.Custom;
            return this;
        }

        /// <summary>Removes all sensor groups (<see cref="Grouping"/> is left as it is).</summary>
        public AgentOptions ClearSensorGroups()
        {
            _sensorGroups.Clear();
            return this;
        }

        /// <summary>The choices of each action branch (empty: one set of <see cref="Actions"/> actions). With
        /// branches the agent chooses one choice per branch on every step, each by an actor head of its own;
        /// an action is then the combined index c0 + n0 * (c1 + n1 * (c2 + ...)) (branch 0 fastest), which
        /// <see cref="Agent.SplitAction(int)"/> and <see cref="Agent.JoinAction(int[])"/> convert. Masks and
        /// <see cref="Agent.ActionProbabilities"/> then hold one entry per choice of each branch, branch
        /// after branch. Planning needs one action set.</summary>
        public IReadOnlyList<int> ActionBranches => _actionBranches.AsReadOnly();

        /// <summary>Gives the agent action branches of these sizes (e.g. 3, 3, 2 for move x turn x use) and
        /// sets <see cref="Actions"/> to their product.</summary>
        /// <example><code>
        /// var options = new AgentOptions().AddContinuousSensor().SetActionBranches(3, 3, 2); // Actions == 18
        /// </code></example>
        /// <exception cref="ArgumentException">No branch, or more than <see cref="MaxActionBranches"/>.</exception>
        /// <exception cref="ArgumentOutOfRangeException">A branch with fewer than 1 choice.</exception>
        public AgentOptions SetActionBranches(params int[] sizes)
        {
            if (sizes == null) throw new ArgumentNullException(nameof(sizes));
            if (sizes.Length == 0)
                throw new ArgumentException("action branches need at least one branch (ClearActionBranches() for one action set)",
                    nameof(sizes));
            if (sizes.Length > MaxActionBranches)
                throw new ArgumentException($"an agent has at most {MaxActionBranches} action branches (got {sizes.Length})",
                    nameof(sizes));
            long product = 1;
            foreach (int size in sizes)
            {
                if (size < 1)
                    throw new ArgumentOutOfRangeException(nameof(sizes), size, "an action branch has at least 1 choice");
                product = Math.Min(product * size, int.MaxValue); // beyond the library's limit: it refuses
            }
            _actionBranches.Clear();
            _actionBranches.AddRange(sizes);
            _actions = (int)product;
            return this;
        }

        /// <summary>Removes the action branches: one set of <see cref="Actions"/> actions (left as it is).</summary>
        public AgentOptions ClearActionBranches()
        {
            _actionBranches.Clear();
            return this;
        }

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

        /// <summary>Removes all sensors, and the sensor groups, which name them.</summary>
        public AgentOptions ClearSensors()
        {
            _discreteSensors.Clear();
            _continuousCircular.Clear();
            _sensorGroups.Clear();
            return this;
        }

        internal unsafe verve_agent_desc ToNative()
        {
            var d = new verve_agent_desc { struct_size = (uint)sizeof(verve_agent_desc) };
            d.num_discrete_sensors = (uint)_discreteSensors.Count;
            const int old = verve_agent_desc.MaxDiscreteSensors; // sensors beyond it: the V8 arrays
            for (int i = 0; i < _discreteSensors.Count; i++)
            {
                if (i < old) d.discrete_sensor_values[i] = (uint)_discreteSensors[i];
                else d.more_discrete_sensor_values[i - old] = (uint)_discreteSensors[i];
            }
            d.num_continuous_sensors = (uint)_continuousCircular.Count;
            for (int i = 0; i < _continuousCircular.Count; i++)
            {
                byte circular = _continuousCircular[i] ? (byte)1 : (byte)0;
                if (i < old) d.continuous_sensor_circular[i] = circular;
                else d.more_continuous_sensor_circular[i - old] = circular;
            }
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
            d.sensor_grouping = (uint)Grouping; // an unknown value: refused by the library
            CheckSensorGroups();
            d.num_sensor_groups = (uint)_sensorGroups.Count;
            for (int i = 0; i < _sensorGroups.Count; i++) d.sensor_groups[i] = MaskOf(_sensorGroups[i]);
            d.num_action_branches = (uint)_actionBranches.Count; // SetActionBranches keeps it <= MaxActionBranches
            for (int i = 0; i < _actionBranches.Count; i++) d.action_branches[i] = (uint)_actionBranches[i];
            d.num_continuous_actions = (ulong)_continuousActions;
            return d;
        }

        // What only the sensor list and the groups together tell; the messages speak this class's terms
        // (the library's would name C fields and bits).
        private void CheckSensorGroups()
        {
            int n = _continuousCircular.Count;
            if (Grouping != SensorGrouping.Custom)
            {
                if (_sensorGroups.Count > 0)
                    throw new ArgumentException($"sensor groups are only used with Grouping = SensorGrouping.Custom (it is {Grouping}); " +
                                                "set Grouping to Custom or call ClearSensorGroups()", "options");
                return;
            }
            if (_sensorGroups.Count == 0 && n > 0)
                throw new ArgumentException("Grouping = SensorGrouping.Custom needs sensor groups (AddSensorGroup) " +
                                            "covering every continuous sensor", "options");
            ulong covered = 0;
            for (int g = 0; g < _sensorGroups.Count; g++)
            {
                foreach (int sensor in _sensorGroups[g])
                {
                    if (sensor >= n)
                        throw new ArgumentException($"sensor group {g} lists continuous sensor {sensor}, but the agent has " +
                                                    $"{n} continuous sensor{(n == 1 ? "" : "s")}", "options");
                }
                covered |= MaskOf(_sensorGroups[g]);
            }
            for (int sensor = 0; sensor < n; sensor++)
            {
                if ((covered & (1UL << sensor)) == 0)
                    throw new ArgumentException($"continuous sensor {sensor} is in no sensor group: its readings would be " +
                                                "ignored (with Grouping = SensorGrouping.Custom every continuous sensor " +
                                                "is in at least one group)", "options");
            }
        }

        private static IReadOnlyList<int> SensorsOf(ulong mask)
        {
            var sensors = new List<int>();
            for (int i = 0; i < 64; i++)
                if ((mask & (1UL << i)) != 0) sensors.Add(i);
            return sensors.AsReadOnly();
        }

        private static ulong MaskOf(IReadOnlyList<int> sensors)
        {
            ulong mask = 0;
            foreach (int sensor in sensors) mask |= 1UL << sensor;
            return mask;
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
