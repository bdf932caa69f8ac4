using System;
using System.Runtime.InteropServices;

namespace Verve.Native
{
    // Exact mirrors of the structs in include/verve_c.h. Field names keep the C spelling so the layout
    // test can compare every offset with the C compiler's (Verve.Tests/NativeLayoutTests.cs).
    // All fields are blittable: the runtime passes a pointer to these, never a marshalled copy.
#pragma warning disable IDE1006 // C names on purpose

    [StructLayout(LayoutKind.Sequential)]
    internal unsafe struct verve_agent_desc
    {
        public const int MaxDiscreteSensors = 16;   // VERVE_MAX_DISCRETE_SENSORS (the V1-V7 arrays)
        public const int MaxContinuousSensors = 16; // VERVE_MAX_CONTINUOUS_SENSORS (the V1-V7 arrays)
        public const int MaxSensors = 64;           // VERVE_MAX_SENSORS (of each kind, with V8)
        public const int MaxLatticeSensors = 16;    // VERVE_MAX_LATTICE_SENSORS
        public const int MaxSensorGroups = 64;      // VERVE_MAX_SENSOR_GROUPS
        public const int MaxActionBranches = 8;     // VERVE_MAX_ACTION_BRANCHES
        public const int MaxContinuousActions = 8;  // VERVE_MAX_CONTINUOUS_ACTIONS

        public uint struct_size;
        public uint num_discrete_sensors;
        public fixed uint discrete_sensor_values[MaxDiscreteSensors];
        public uint num_continuous_sensors;
        public fixed byte continuous_sensor_circular[MaxContinuousSensors];
        public uint resolution;
        public uint num_actions;
        public uint rbf_allocation;

        public float tau_value;
        public float tau_discount;
        public float tau_eligibility;
        public float policy_multiplier;
        public float trace_threshold;
        public ulong seed;

        public uint planning;
        public float tau_model;
        public uint max_planning_steps;
        public float planning_uncertainty_threshold;
        public uint curiosity;
        public float curiosity_factor;
        public uint planning_accumulates_uncertainty;
        public uint learn_from_real_steps;
        public uint discrete_prediction;
        public ulong max_rbfs; // V3
        public float policy_weight_bound;
        public ulong adaptation; // V4
        public uint sensor_grouping; // V5
        public uint num_sensor_groups;
        public fixed ulong sensor_groups[MaxSensorGroups]; // bit i: continuous sensor i
        public uint num_action_branches; // V6
        public fixed uint action_branches[MaxActionBranches]; // choices per branch
        public ulong num_continuous_actions; // V7: 64 bits so it starts where V6 ended (V6's tail padding)
        public fixed uint more_discrete_sensor_values[MaxSensors - MaxDiscreteSensors]; // V8: sensors 16..63
        public fixed byte more_continuous_sensor_circular[MaxSensors - MaxContinuousSensors];
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct verve_agent_stats
    {
        public uint struct_size;
        public ulong steps;
        public uint rbf_count;
        public uint live_traces;
        public float value;
        public float td_error;
        public float model_error;
        public float predicted_uncertainty;
        public uint planning_steps;
        public float curiosity_reward;
        public ulong rbf_budget_hits; // V2
        public ulong clamped_rewards;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct verve_batch_desc
    {
        public uint struct_size;
        public uint worker_count;
        public IntPtr enqueue_task; // host job-system callbacks: always NULL from C#
        public IntPtr finish_task;
        public IntPtr user_context;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct verve_hooks
    {
        public uint struct_size;
        public IntPtr malloc_fn; // the allocator hooks: always NULL from C# (the C library's)
        public IntPtr realloc_fn;
        public IntPtr free_fn;
        public IntPtr alloc_user;
        public IntPtr log_fn;    // WarningLog.OnWarning
        public IntPtr log_user;
    }

#pragma warning restore IDE1006
}
