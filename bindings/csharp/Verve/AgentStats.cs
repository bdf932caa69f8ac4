using Verve.Native;

namespace Verve
{
    /// <summary>A snapshot of an agent's counters and latest signals (<c>verve_agent_stats</c>).</summary>
    public readonly struct AgentStats
    {
        internal AgentStats(in verve_agent_stats s)
        {
            Steps = (long)s.steps;
            RbfCount = (int)s.rbf_count;
            LiveTraces = (int)s.live_traces;
            Value = s.value;
            TdError = s.td_error;
            ModelError = s.model_error;
            PredictedUncertainty = s.predicted_uncertainty;
            PlanningSteps = (int)s.planning_steps;
            CuriosityReward = s.curiosity_reward;
            RbfBudgetHits = (long)s.rbf_budget_hits;
            ClampedRewards = (long)s.clamped_rewards;
        }

        /// <summary>Real updates since creation.</summary>
        public long Steps { get; }
        /// <summary>RBFs allocated so far.</summary>
        public int RbfCount { get; }
        /// <summary>Eligibility traces currently above the threshold.</summary>
        public int LiveTraces { get; }
        /// <summary>V(s) of the latest observation.</summary>
        public float Value { get; }
        /// <summary>TD error of the latest real step.</summary>
        public float TdError { get; }
        /// <summary>Running mean squared prediction error of the model.</summary>
        public float ModelError { get; }
        /// <summary>Uncertainty the model predicted for the latest step.</summary>
        public float PredictedUncertainty { get; }
        /// <summary>Imagined steps after the latest real step.</summary>
        public int PlanningSteps { get; }
        /// <summary>Curiosity reward summed over the latest plan.</summary>
        public float CuriosityReward { get; }
        /// <summary>Updates that would have added an RBF beyond <see cref="AgentOptions.MaxRbfs"/>.</summary>
        public long RbfBudgetHits { get; }
        /// <summary>Rewards outside [-1, 1] that were clamped.</summary>
        public long ClampedRewards { get; }

        /// <inheritdoc />
        public override string ToString() =>
            $"steps={Steps} rbfs={RbfCount} traces={LiveTraces} V={Value:G4} td={TdError:G4} " +
            $"modelError={ModelError:G4} uncertainty={PredictedUncertainty:G4} planned={PlanningSteps} curiosity={CuriosityReward:G4}";
    }
}
