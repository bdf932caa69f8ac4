using System;
using System.Runtime.InteropServices;

namespace Verve.Native
{
    // The C ABI, one declaration per function of include/verve_c.h. Pointers rather than marshalled
    // arrays so a call never copies or allocates; the agent travels as a SafeHandle so it cannot be
    // freed by another thread while a call runs.
    internal static unsafe class NativeMethods
    {
#if VERVE_STATIC_LINK
        // IL2CPP platforms that link native code into the game itself (iOS, WebGL): the symbols are
        // looked up in the executable. Define VERVE_STATIC_LINK for those platforms (docs/csharp.md).
        private const string Library = "__Internal";
#else
        private const string Library = "verve";
#endif

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern uint verve_version();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr verve_last_error();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr verve_result_name(ResultCode result);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_set_hooks(verve_hooks* hooks);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void verve_agent_desc_default(void* desc);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_desc_init(verve_agent_desc* desc, uint structSize);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_create(verve_agent_desc* desc, out IntPtr agent);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void verve_agent_destroy(IntPtr agent);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_update(AgentHandle agent, float reward,
            int* discrete, uint nDiscrete, float* continuous, uint nContinuous, float dt, out uint action);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_update_masked(AgentHandle agent, float reward,
            int* discrete, uint nDiscrete, float* continuous, uint nContinuous, float dt,
            byte* actionMask, uint nActions, out uint action);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_update_demonstrated(AgentHandle agent, float reward,
            int* discrete, uint nDiscrete, float* continuous, uint nContinuous, float dt,
            byte* actionMask, uint nActions, uint action);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_update_demonstrated_continuous(AgentHandle agent, float reward,
            int* discrete, uint nDiscrete, float* continuous, uint nContinuous, float dt,
            byte* actionMask, uint nActions, uint action, float* continuousAction, uint nContinuousActions);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_teach(AgentHandle agent, float praise);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_create(AgentHandle shapedLike, out IntPtr recording);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void verve_recording_destroy(IntPtr recording);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_add_step(RecordingHandle recording, float reward,
            int* discrete, uint nDiscrete, float* continuous, uint nContinuous, float dt, uint action);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_add_step_continuous(RecordingHandle recording, float reward,
            int* discrete, uint nDiscrete, float* continuous, uint nContinuous, float dt, uint action,
            float* continuousAction, uint nContinuousActions);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_add_end_episode(RecordingHandle recording, float finalReward);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_add_truncation(RecordingHandle recording, float reward);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_get_size(RecordingHandle recording, out ulong entries);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_save(RecordingHandle recording, byte* path);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_save_memory(RecordingHandle recording, byte* buffer, ref UIntPtr size);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_load(byte* path, out IntPtr recording);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_recording_load_memory(byte* data, UIntPtr size, out IntPtr recording);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_replay(AgentHandle agent, RecordingHandle recording);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_end_episode(AgentHandle agent, float finalReward);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_truncate_episode(AgentHandle agent, float reward);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_set_action_selection(AgentHandle agent, uint mode);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_action_selection(AgentHandle agent, out uint mode);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_action_probabilities(AgentHandle agent, float* probabilities,
            uint count);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_continuous_action(AgentHandle agent, float* values,
            uint count);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_split_action(AgentHandle agent, uint action, uint* choices,
            uint branches);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_join_action(AgentHandle agent, uint* choices, uint branches,
            out uint action);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_reset_short_term_memory(AgentHandle agent);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_set_learning(AgentHandle agent, int enabled);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_learning(AgentHandle agent, out int enabled);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_desc(AgentHandle agent, verve_agent_desc* desc);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_value(AgentHandle agent, out float value);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_td_error(AgentHandle agent, out float tdError);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_rbf_count(AgentHandle agent, out uint count);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_get_stats(AgentHandle agent, verve_agent_stats* stats);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_sample_values(AgentHandle agent, ValueAxis* axes, uint nAxes,
            int* baseDiscrete, uint nDiscrete, float* baseContinuous, uint nContinuous, float* output, uint outputCount);

        // Paths are NUL-terminated UTF-8 bytes, encoded by the caller (portable across Mono/IL2CPP).
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_save(AgentHandle agent, byte* path);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_load(byte* path, out IntPtr agent);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_save_memory(AgentHandle agent, byte* buffer, ref UIntPtr size);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_load_memory(byte* data, UIntPtr size, out IntPtr agent);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_save_binary(AgentHandle agent, byte* path);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_agent_save_memory_binary(AgentHandle agent, byte* buffer, ref UIntPtr size);

        // One brain, many bodies.
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_create(verve_agent_desc* desc, out IntPtr brain);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void verve_brain_destroy(IntPtr brain);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_create_body(BrainHandle brain, out IntPtr body);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_get_rbf_count(BrainHandle brain, out uint count);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_save(BrainHandle brain, byte* path);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_load(byte* path, out IntPtr brain);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_save_memory(BrainHandle brain, byte* buffer, ref UIntPtr size);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_load_memory(byte* data, UIntPtr size, out IntPtr brain);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_save_binary(BrainHandle brain, byte* path);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_brain_save_memory_binary(BrainHandle brain, byte* buffer, ref UIntPtr size);

        // Many agents in one call (Verve's own thread pool: host callbacks are not bound here).
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_batch_desc_default(verve_batch_desc* desc);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_batch_create(verve_batch_desc* desc, out IntPtr batch);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern void verve_batch_destroy(IntPtr batch);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_batch_get_worker_count(BatchHandle batch, out uint count);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_batch_update(BatchHandle batch, IntPtr* agents, uint n, float* rewards,
            int* discrete, uint* discreteOffsets, uint discreteTotal, float* continuous, uint* continuousOffsets,
            uint continuousTotal, float dt, uint* actions, ResultCode* results);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_batch_update_demonstrated(BatchHandle batch, IntPtr* agents, uint n,
            float* rewards, int* discrete, uint* discreteOffsets, uint discreteTotal, float* continuous,
            uint* continuousOffsets, uint continuousTotal, float dt, uint* demonstrated, uint* actions, ResultCode* results);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ResultCode verve_batch_update_demonstrated_continuous(BatchHandle batch, IntPtr* agents,
            uint n, float* rewards, int* discrete, uint* discreteOffsets, uint discreteTotal, float* continuous,
            uint* continuousOffsets, uint continuousTotal, float dt, uint* demonstrated, float* continuousActions,
            uint* continuousActionOffsets, uint continuousActionsTotal, uint* actions, ResultCode* results);
    }
}
