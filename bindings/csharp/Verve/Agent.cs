// Nullable annotations on: Unity compiles these sources without the .csproj that enables them.
#nullable enable
using System;
using System.Runtime.InteropServices;
using System.Text;
using Verve.Native;

namespace Verve
{
    /// <summary>A reinforcement-learning agent living in native memory. Each <see cref="Update(float, ReadOnlySpan{int}, ReadOnlySpan{float}, float)"/>
    /// takes the reward earned by the previous action and the new observation, learns, and returns the next action.
    /// Use one agent from one thread at a time; different agents may run on different threads.
    /// Dispose it to free the native memory at once (otherwise the finalizer does).</summary>
    /// <remarks>Every failed call throws <see cref="VerveException"/> (with the native message) and leaves
    /// the agent unchanged; calls on a disposed agent throw <see cref="ObjectDisposedException"/>.</remarks>
    public sealed class Agent : IDisposable
    {
        private readonly AgentHandle _handle;

        /// <summary>Creates an agent described by <paramref name="options"/>.</summary>
        /// <exception cref="VerveException">The description is invalid (the message names the field).</exception>
        /// <exception cref="ArgumentException">The sensor groups do not fit the continuous sensors (one names a
        /// sensor the options lack, or a sensor is in none), or are given without <see cref="SensorGrouping.Custom"/>.</exception>
        public unsafe Agent(AgentOptions options)
        {
            if (options == null) throw new ArgumentNullException(nameof(options));
            verve_agent_desc desc = options.ToNative();
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_create(&desc, out IntPtr agent));
            _handle = new AgentHandle(agent);
        }

        internal Agent(IntPtr agent) => _handle = new AgentHandle(agent);

        /// <summary>Whether <see cref="Dispose"/> has been called.</summary>
        public bool IsDisposed => _handle.IsClosed;

        // Checked on every call so a disposed agent fails with a clear message, not a marshalling error.
        internal AgentHandle Handle => _handle.IsClosed ? throw new ObjectDisposedException(nameof(Agent)) : _handle;

        /// <summary>One step: learn from <paramref name="reward"/> (earned by the previous action, clamped
        /// to [-1, 1]) and the new observation, and choose the next action. Null arrays mean no sensors of that kind.</summary>
        /// <returns>The action to take, in [0, <see cref="AgentOptions.Actions"/>); continuous actions, if any, are then
        /// read with <see cref="GetContinuousAction(Span{float})"/>.</returns>
        public int Update(float reward, int[]? discrete, float[]? continuous, float dt) =>
            Update(reward, new ReadOnlySpan<int>(discrete), new ReadOnlySpan<float>(continuous), dt);

        /// <summary>One step without allocation; see <see cref="Update(float, int[], float[], float)"/>.</summary>
        /// <param name="reward">What the previous action earned.</param>
        /// <param name="discrete">One value per discrete sensor, each in [0, its value count).</param>
        /// <param name="continuous">One value per continuous sensor, in [-1, 1] (clamped, or wrapped when circular).</param>
        /// <param name="dt">Seconds since the previous step, &gt; 0.</param>
        /// <exception cref="VerveException">Wrong counts, NaN/infinity, out-of-range discrete values or dt &lt;= 0.</exception>
        public unsafe int Update(float reward, ReadOnlySpan<int> discrete, ReadOnlySpan<float> continuous, float dt)
        {
            AgentHandle handle = Handle;
            uint action;
            // Pinned through MemoryMarshal.GetReference, not `fixed (int* d = discrete)`: that form calls
            // ReadOnlySpan<T>.GetPinnableReference, whose netstandard2.1 signature (ref readonly) Mono's
            // corlib, and so Unity's, does not have (MissingMethodException). A default span pins to null.
            fixed (int* d = &MemoryMarshal.GetReference(discrete))
            fixed (float* c = &MemoryMarshal.GetReference(continuous))
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_update(handle, reward,
                    d, (uint)discrete.Length, c, (uint)continuous.Length, dt, out action));
            }
            return (int)action;
        }

        /// <summary>One step choosing only among the actions <paramref name="allowed"/> permits
        /// (one flag per action, 1 allowed, 0 not, at least one 1; with <see cref="AgentOptions.ActionBranches"/>
        /// one flag per choice of each branch, branch after branch, at least one 1 in each). A masked action is
        /// never chosen and gets no credit.</summary>
        /// <exception cref="VerveException">As <see cref="Update(float, ReadOnlySpan{int}, ReadOnlySpan{float}, float)"/>,
        /// or a mask of the wrong length, with a flag other than 0/1, or allowing nothing.</exception>
        public unsafe int Update(float reward, ReadOnlySpan<int> discrete, ReadOnlySpan<float> continuous, float dt,
            ReadOnlySpan<byte> allowed)
        {
            AgentHandle handle = Handle;
            uint action;
            fixed (int* d = &MemoryMarshal.GetReference(discrete))
            fixed (float* c = &MemoryMarshal.GetReference(continuous))
            fixed (byte* m = &MemoryMarshal.GetReference(allowed))
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_update_masked(handle, reward,
                    d, (uint)discrete.Length, c, (uint)continuous.Length, dt, m, (uint)allowed.Length, out action));
            }
            return (int)action;
        }

        /// <summary>A demonstrated step (docs/teaching.md): as <see cref="Update(float, ReadOnlySpan{int}, ReadOnlySpan{float}, float)"/>,
        /// but the host took <paramref name="action"/> (a player or a scripted AI drove the NPC). The agent learns from it as
        /// from its own choice and is pulled towards it; the next <c>Update</c> acts on its own again. A demonstration names
        /// the discrete action only: the continuous actions of that step are the policy's mean.</summary>
        /// <param name="reward">What the previous action earned.</param>
        /// <param name="discrete">One value per discrete sensor, each in [0, its value count).</param>
        /// <param name="continuous">One value per continuous sensor, in [-1, 1].</param>
        /// <param name="dt">Seconds since the previous step, &gt; 0.</param>
        /// <param name="action">The action the host took, in [0, <see cref="AgentOptions.Actions"/>).</param>
        /// <param name="allowed">Empty for every action, or one flag per action as in the masked <c>Update</c>;
        /// the action must be one it allows.</param>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="action"/> is negative.</exception>
        /// <exception cref="VerveException">As <c>Update</c>, or an action out of range or forbidden by the mask.</exception>
        public unsafe void UpdateDemonstrated(float reward, ReadOnlySpan<int> discrete, ReadOnlySpan<float> continuous, float dt,
            int action, ReadOnlySpan<byte> allowed = default)
        {
            if (action < 0) throw new ArgumentOutOfRangeException(nameof(action), action, "an action is an index from 0");
            AgentHandle handle = Handle;
            fixed (int* d = &MemoryMarshal.GetReference(discrete))
            fixed (float* c = &MemoryMarshal.GetReference(continuous))
            fixed (byte* m = &MemoryMarshal.GetReference(allowed))
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_update_demonstrated(handle, reward,
                    d, (uint)discrete.Length, c, (uint)continuous.Length, dt, m, (uint)allowed.Length, (uint)action));
            }
        }

        /// <summary>As <see cref="UpdateDemonstrated"/>, with the continuous actions the host played too (docs/teaching.md):
        /// the agent learns from them as from values it drew itself and is pulled towards them;
        /// <see cref="GetContinuousAction(Span{float})"/> then reads them back.</summary>
        /// <param name="reward">What the previous action earned.</param>
        /// <param name="discrete">One value per discrete sensor, each in [0, its value count).</param>
        /// <param name="continuous">One value per continuous sensor, in [-1, 1].</param>
        /// <param name="dt">Seconds since the previous step, &gt; 0.</param>
        /// <param name="action">The action the host took, in [0, <see cref="AgentOptions.Actions"/>).</param>
        /// <param name="continuousAction">One value per continuous action (<see cref="AgentOptions.ContinuousActions"/>),
        /// each in [-1, 1].</param>
        /// <param name="allowed">Empty for every action, or one flag per action as in the masked <c>Update</c>.</param>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="action"/> is negative.</exception>
        /// <exception cref="VerveException">As <see cref="UpdateDemonstrated"/>, or a wrong count of continuous values,
        /// NaN or a value outside [-1, 1] (nothing changes).</exception>
        public unsafe void UpdateDemonstratedContinuous(float reward, ReadOnlySpan<int> discrete, ReadOnlySpan<float> continuous,
            float dt, int action, ReadOnlySpan<float> continuousAction, ReadOnlySpan<byte> allowed = default)
        {
            if (action < 0) throw new ArgumentOutOfRangeException(nameof(action), action, "an action is an index from 0");
            AgentHandle handle = Handle;
            fixed (int* d = &MemoryMarshal.GetReference(discrete))
            fixed (float* c = &MemoryMarshal.GetReference(continuous))
            fixed (byte* m = &MemoryMarshal.GetReference(allowed))
            fixed (float* v = &MemoryMarshal.GetReference(continuousAction))
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_update_demonstrated_continuous(handle, reward,
                    d, (uint)discrete.Length, c, (uint)continuous.Length, dt, m, (uint)allowed.Length, (uint)action,
                    v, (uint)continuousAction.Length));
            }
        }

        /// <summary>A teacher's judgement (docs/teaching.md): <paramref name="praise"/> in [-1, 1] (1 good, -1 bad) of
        /// what the agent did over the last 2.5 s; it moves the actor's preferences for those acts and is not a reward.
        /// The agent remembers its acts from its first judgement on (0 arms the memory without judging); not saved.</summary>
        /// <exception cref="VerveException">NaN or praise outside [-1, 1].</exception>
        public void Teach(float praise) => VerveException.ThrowIfFailed(NativeMethods.verve_agent_teach(Handle, praise));

        /// <summary>Every entry of <paramref name="recording"/> into this agent, in order, as demonstrated steps and trial
        /// ends (docs/teaching.md, "Recordings").</summary>
        /// <exception cref="VerveException">The agent's sensors or actions are not the recording's (nothing is replayed).</exception>
        public void Replay(Recording recording)
        {
            if (recording == null) throw new ArgumentNullException(nameof(recording));
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_replay(Handle, recording.Handle));
        }

        /// <summary>Ends a trial that really ended (goal reached, NPC died): <paramref name="finalReward"/> is the
        /// last reward there is; nothing is expected after it.</summary>
        public void EndEpisode(float finalReward) =>
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_end_episode(Handle, finalReward));

        /// <summary>Ends a trial that was cut off (a time limit, a level reset) where the world would have gone on:
        /// <paramref name="reward"/> (what the last action earned) is learned, and the last state's value stands in
        /// for what would have followed.</summary>
        public void TruncateEpisode(float reward) =>
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_truncate_episode(Handle, reward));

        /// <summary>How <see cref="Update(float, int[], float[], float)"/> picks its action; per agent, not saved.</summary>
        public ActionSelection ActionSelection
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_action_selection(Handle, out uint mode));
                return (ActionSelection)mode;
            }
            set => VerveException.ThrowIfFailed(NativeMethods.verve_agent_set_action_selection(Handle, (uint)value));
        }

        /// <summary>The policy's probability of each action at the latest update (summing to 1; 0 for masked
        /// actions); uniform before any update. With <see cref="AgentOptions.ActionBranches"/>, one per choice
        /// of each branch, branch after branch, each branch summing to 1.</summary>
        public unsafe float[] ActionProbabilities
        {
            get
            {
                AgentHandle handle = Handle;
                var desc = new verve_agent_desc { struct_size = (uint)sizeof(verve_agent_desc) };
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_desc(handle, &desc));
                uint count = desc.num_actions;
                if (desc.num_action_branches > 0)
                {
                    count = 0;
                    for (int i = 0; i < Math.Min(desc.num_action_branches, AgentOptions.MaxActionBranches); i++)
                        count += desc.action_branches[i];
                }
                var probabilities = new float[count];
                fixed (float* p = probabilities)
                {
                    VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_action_probabilities(handle, p,
                        (uint)probabilities.Length));
                }
                return probabilities;
            }
        }

        /// <summary>The continuous actions chosen at the latest update (<see cref="AgentOptions.ContinuousActions"/>
        /// values, each in [-1, 1]: drawn around the policy's mean, or the mean itself with
        /// <see cref="ActionSelection.Greedy"/> and on a demonstrated step); 0s before any update. A new array on
        /// every read: in a game loop use <see cref="GetContinuousAction(Span{float})"/>.</summary>
        public unsafe float[] ContinuousAction
        {
            get
            {
                AgentHandle handle = Handle;
                var desc = new verve_agent_desc { struct_size = (uint)sizeof(verve_agent_desc) };
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_desc(handle, &desc));
                if (desc.num_continuous_actions == 0) return Array.Empty<float>();
                var values = new float[Math.Min(desc.num_continuous_actions, (ulong)AgentOptions.MaxContinuousActions)];
                GetContinuousAction(values);
                return values;
            }
        }

        /// <summary>As <see cref="ContinuousAction"/>, without allocation: writes the latest update's continuous actions
        /// into <paramref name="destination"/>, which must hold exactly <see cref="AgentOptions.ContinuousActions"/> floats
        /// (e.g. <c>stackalloc float[2]</c>, or an array kept per agent).</summary>
        /// <exception cref="VerveException"><paramref name="destination"/> is not the agent's number of continuous actions long.</exception>
        public unsafe void GetContinuousAction(Span<float> destination)
        {
            AgentHandle handle = Handle;
            float none;
            fixed (float* d = &MemoryMarshal.GetReference(destination))
            {
                // An empty span pins to null, which the library refuses even when the agent has no continuous
                // actions: point it at a dummy so the count alone decides.
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_continuous_action(handle,
                    destination.IsEmpty ? &none : d, (uint)destination.Length));
            }
        }

        /// <summary>The choice of each action branch (from 0) within a combined <paramref name="action"/>
        /// (branch 0 varies fastest); one choice, the action itself, without branches.</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="action"/> is negative.</exception>
        /// <exception cref="VerveException">The action is not one of the agent's.</exception>
        public unsafe int[] SplitAction(int action)
        {
            if (action < 0) throw new ArgumentOutOfRangeException(nameof(action), action, "an action is an index from 0");
            AgentHandle handle = Handle;
            var desc = new verve_agent_desc { struct_size = (uint)sizeof(verve_agent_desc) };
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_desc(handle, &desc));
            uint branches = Math.Max(desc.num_action_branches, 1u);
            uint* choices = stackalloc uint[AgentOptions.MaxActionBranches];
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_split_action(handle, (uint)action, choices,
                Math.Min(branches, (uint)AgentOptions.MaxActionBranches)));
            var result = new int[branches];
            for (int i = 0; i < result.Length; i++) result[i] = (int)choices[i];
            return result;
        }

        /// <summary>The combined action of one choice per action branch (each from 0), as <c>Update</c> returns it.</summary>
        /// <exception cref="ArgumentException">No choice.</exception>
        /// <exception cref="ArgumentOutOfRangeException">A choice is negative.</exception>
        /// <exception cref="VerveException">Not one choice per branch, or a choice out of its branch's range.</exception>
        public unsafe int JoinAction(params int[] choices)
        {
            if (choices == null) throw new ArgumentNullException(nameof(choices));
            if (choices.Length == 0) throw new ArgumentException("an action is one choice per branch (none given)", nameof(choices));
            foreach (int choice in choices)
                if (choice < 0) throw new ArgumentOutOfRangeException(nameof(choices), choice, "a choice is an index from 0");
            AgentHandle handle = Handle;
            uint action;
            fixed (int* c = choices)
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_join_action(handle, (uint*)c, (uint)choices.Length,
                    out action));
            }
            return (int)action;
        }

        /// <summary>Forgets the current trial (traces, previous observation) but keeps everything learned.</summary>
        public void ResetShortTermMemory() =>
            VerveException.ThrowIfFailed(NativeMethods.verve_agent_reset_short_term_memory(Handle));

        /// <summary>Whether updates change the agent's weights; off, it only acts.</summary>
        public bool Learning
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_learning(Handle, out int enabled));
                return enabled != 0;
            }
            set => VerveException.ThrowIfFailed(NativeMethods.verve_agent_set_learning(Handle, value ? 1 : 0));
        }

        /// <summary>A copy of the description this agent was created with (changing it changes nothing).</summary>
        public unsafe AgentOptions Options
        {
            get
            {
                var desc = new verve_agent_desc { struct_size = (uint)sizeof(verve_agent_desc) };
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_desc(Handle, &desc));
                return new AgentOptions(desc);
            }
        }

        /// <summary>V(s) of the latest observation.</summary>
        public float Value
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_value(Handle, out float value));
                return value;
            }
        }

        /// <summary>TD error of the latest real step.</summary>
        public float TdError
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_td_error(Handle, out float tdError));
                return tdError;
            }
        }

        /// <summary>RBFs allocated so far.</summary>
        public int RbfCount
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_rbf_count(Handle, out uint count));
                return (int)count;
            }
        }

        /// <summary>Counters and latest learning signals.</summary>
        public unsafe AgentStats Stats
        {
            get
            {
                var stats = new verve_agent_stats { struct_size = (uint)sizeof(verve_agent_stats) };
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_get_stats(Handle, &stats));
                return new AgentStats(stats);
            }
        }

        /// <summary>V over one swept sensor, the other sensors held at the base observation.</summary>
        /// <returns><c>axis.Samples</c> values.</returns>
        public float[] SampleValues(ValueAxis axis, ReadOnlySpan<int> baseDiscrete, ReadOnlySpan<float> baseContinuous)
        {
            Span<ValueAxis> axes = stackalloc ValueAxis[] { axis };
            return SampleValues(axes, axis.Samples, baseDiscrete, baseContinuous);
        }

        /// <summary>V over two swept sensors, the other sensors held at the base observation.</summary>
        /// <returns><c>axis0.Samples * axis1.Samples</c> values, axis 0 fastest.</returns>
        public float[] SampleValues(ValueAxis axis0, ValueAxis axis1, ReadOnlySpan<int> baseDiscrete, ReadOnlySpan<float> baseContinuous)
        {
            Span<ValueAxis> axes = stackalloc ValueAxis[] { axis0, axis1 };
            return SampleValues(axes, (long)axis0.Samples * axis1.Samples, baseDiscrete, baseContinuous);
        }

        /// <summary>V over one or two swept sensors into the start of <paramref name="destination"/>, which must
        /// hold at least the product of the axes' sample counts (axis 0 fastest). The base observation gives
        /// the values of the sensors not swept (the swept entries are ignored).</summary>
        public unsafe void SampleValues(ReadOnlySpan<ValueAxis> axes, ReadOnlySpan<int> baseDiscrete,
            ReadOnlySpan<float> baseContinuous, Span<float> destination)
        {
            AgentHandle handle = Handle;
            fixed (ValueAxis* a = &MemoryMarshal.GetReference(axes))
            fixed (int* d = &MemoryMarshal.GetReference(baseDiscrete))
            fixed (float* c = &MemoryMarshal.GetReference(baseContinuous))
            fixed (float* o = &MemoryMarshal.GetReference(destination))
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_sample_values(handle, a, (uint)axes.Length,
                    d, (uint)baseDiscrete.Length, c, (uint)baseContinuous.Length, o, (uint)destination.Length));
            }
        }

        // The count comes from the caller: reading a ReadOnlySpan's elements (indexer, foreach) fails on
        // Mono for the same reason as GetPinnableReference (see Update).
        private float[] SampleValues(ReadOnlySpan<ValueAxis> axes, long count, ReadOnlySpan<int> baseDiscrete, ReadOnlySpan<float> baseContinuous)
        {
            if (count > int.MaxValue) throw new ArgumentOutOfRangeException(nameof(axes), count, "too many samples");
            var values = new float[count];
            SampleValues(axes, baseDiscrete, baseContinuous, values);
            return values;
        }

        /// <summary>Saves the agent as XML to <paramref name="path"/>, atomically: the previous file
        /// survives a crash mid-save.</summary>
        public void Save(string path) => SaveFile(path, binary: false);

        /// <summary>As <see cref="Save(string)"/>, in the compact binary format: about half the size,
        /// and faster to save and to load. <see cref="Load(string)"/> reads both.</summary>
        public void SaveBinary(string path) => SaveFile(path, binary: true);

        private unsafe void SaveFile(string path, bool binary)
        {
            AgentHandle handle = Handle;
            fixed (byte* p = NulTerminatedUtf8(path))
                VerveException.ThrowIfFailed(binary ? NativeMethods.verve_agent_save_binary(handle, p)
                                                    : NativeMethods.verve_agent_save(handle, p));
        }

        /// <summary>Loads an agent saved by <see cref="Save(string)"/> or <see cref="SaveBinary(string)"/>.</summary>
        /// <exception cref="VerveException"><see cref="ResultCode.Io"/>, <see cref="ResultCode.Format"/> or <see cref="ResultCode.Version"/>.</exception>
        public static unsafe Agent Load(string path)
        {
            VerveLibrary.EnsureCompatible();
            IntPtr agent;
            fixed (byte* p = NulTerminatedUtf8(path))
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_load(p, out agent));
            return new Agent(agent);
        }

        /// <summary>The agent's save (the same XML as <see cref="Save(string)"/>) as bytes.</summary>
        public byte[] SaveToBytes() => SaveMemory(binary: false);

        /// <summary>The agent's binary save (the same bytes as <see cref="SaveBinary(string)"/>).</summary>
        public byte[] SaveToBinaryBytes() => SaveMemory(binary: true);

        private unsafe byte[] SaveMemory(bool binary)
        {
            AgentHandle handle = Handle;
            return MemorySave.ToBytes(binary
                ? (MemorySave.Call)((byte* b, ref UIntPtr size) => NativeMethods.verve_agent_save_memory_binary(handle, b, ref size))
                : (byte* b, ref UIntPtr size) => NativeMethods.verve_agent_save_memory(handle, b, ref size));
        }

        /// <summary>Loads an agent from bytes made by <see cref="SaveToBytes"/> or <see cref="SaveToBinaryBytes"/>.</summary>
        public static Agent LoadFromBytes(byte[] data) =>
            LoadFromBytes(new ReadOnlySpan<byte>(data ?? throw new ArgumentNullException(nameof(data))));

        /// <summary>Loads an agent from bytes made by <see cref="SaveToBytes"/> or <see cref="SaveToBinaryBytes"/>.</summary>
        /// <exception cref="VerveException"><see cref="ResultCode.Format"/> when the bytes are corrupt or truncated.</exception>
        public static unsafe Agent LoadFromBytes(ReadOnlySpan<byte> data)
        {
            VerveLibrary.EnsureCompatible();
            IntPtr agent;
            fixed (byte* d = &MemoryMarshal.GetReference(data))
                VerveException.ThrowIfFailed(NativeMethods.verve_agent_load_memory(d, (UIntPtr)data.Length, out agent));
            return new Agent(agent);
        }

        /// <summary>Frees the native agent. Further calls throw <see cref="ObjectDisposedException"/>.</summary>
        public void Dispose() => _handle.Dispose();

        internal static byte[] NulTerminatedUtf8(string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            if (path.IndexOf('\0') >= 0) throw new ArgumentException("path contains a NUL character", nameof(path));
            var bytes = new byte[Encoding.UTF8.GetByteCount(path) + 1];
            Encoding.UTF8.GetBytes(path, 0, path.Length, bytes, 0);
            return bytes;
        }
    }
}
