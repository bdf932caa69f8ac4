using System;
#nullable enable
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>Updates many agents in one call on Verve's own worker threads: separate agents of any
    /// shapes and bodies of shared brains, mixed. The results are exactly those of calling
    /// <see cref="Agent.Update(float, ReadOnlySpan{int}, ReadOnlySpan{float}, float)"/> on each agent in
    /// order, for any number of threads. Dispose it to join its threads.</summary>
    public sealed class Batch : IDisposable
    {
        private readonly BatchHandle _handle;
        private IntPtr[] _agents = Array.Empty<IntPtr>(); // scratch: the native handles of a call

        /// <summary>Creates a batch working on <paramref name="workerCount"/> threads, the caller included;
        /// 0 uses one per hardware thread. The threads start at the first update.</summary>
        public unsafe Batch(int workerCount = 0)
        {
            if (workerCount < 0) throw new ArgumentOutOfRangeException(nameof(workerCount), workerCount, "must be >= 0");
            VerveLibrary.EnsureCompatible();
            verve_batch_desc desc;
            VerveException.ThrowIfFailed(NativeMethods.verve_batch_desc_default(&desc));
            desc.worker_count = (uint)workerCount;
            VerveException.ThrowIfFailed(NativeMethods.verve_batch_create(&desc, out IntPtr batch));
            _handle = new BatchHandle(batch);
        }

        private BatchHandle Handle => _handle.IsClosed ? throw new ObjectDisposedException(nameof(Batch)) : _handle;

        /// <summary>Threads working on a batch, the caller included.</summary>
        public int WorkerCount
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_batch_get_worker_count(Handle, out uint count));
                return (int)count;
            }
        }

        /// <summary>One step of every agent: agent i earned <c>rewards[i]</c>, and its sensor values are the
        /// next ones in <paramref name="discrete"/> and <paramref name="continuous"/> (agents packed one after
        /// another). Writes agent i's action to <c>actions[i]</c>, and, when <paramref name="results"/> is not
        /// empty, each agent's verdict to <c>results[i]</c>. Agents with continuous actions: read each one's afterwards
        /// with <see cref="Agent.GetContinuousAction(Span{float})"/>.</summary>
        /// <exception cref="VerveException">Any bad input (the message names the first bad agent): then no
        /// agent changed and no action was written.</exception>
        public unsafe void Update(Agent[] agents, ReadOnlySpan<float> rewards, ReadOnlySpan<int> discrete,
            ReadOnlySpan<float> continuous, float dt, Span<int> actions, Span<ResultCode> results = default) =>
            Step(agents, rewards, discrete, continuous, dt, null, null, 0, actions, results);

        /// <summary>In <see cref="UpdateDemonstrated"/>: the agent chooses its own action.</summary>
        public const int AgentChooses = -1;

        /// <summary>As <see cref="Update"/>, with demonstrated steps (docs/teaching.md): <c>demonstrated[i]</c> is the
        /// action the player or a scripted AI took for agent i (as <see cref="Agent.UpdateDemonstrated"/> takes it, and
        /// written back to <c>actions[i]</c>), or <see cref="AgentChooses"/> for the agent's own choice.</summary>
        /// <exception cref="VerveException">As <see cref="Update"/>, or a demonstrated action out of range.</exception>
        public unsafe void UpdateDemonstrated(Agent[] agents, ReadOnlySpan<float> rewards, ReadOnlySpan<int> discrete,
            ReadOnlySpan<float> continuous, float dt, ReadOnlySpan<int> demonstrated, Span<int> actions,
            Span<ResultCode> results = default)
        {
            if (agents != null && demonstrated.Length != agents.Length)
                throw new ArgumentException($"{agents.Length} agents need as many demonstrated actions ({demonstrated.Length})");
            // AgentChooses (-1) is VERVE_AGENT_CHOOSES (0xFFFFFFFF) as the library reads it.
            fixed (int* shown = &MemoryMarshal.GetReference(demonstrated))
                Step(agents!, rewards, discrete, continuous, dt, (uint*)shown, null, 0, actions, results);
        }

        /// <summary>As <see cref="UpdateDemonstrated"/>, with the continuous actions the player or a scripted AI played
        /// too (as <see cref="Agent.UpdateDemonstratedContinuous"/> takes them): agent i's values (its number of
        /// continuous actions, each in [-1, 1]) are the next ones in <paramref name="continuousActions"/>, every agent's
        /// packed one after another whether it is shown an action or not; they are read only for the agents shown one.
        /// Each agent reads the teacher's values back with <see cref="Agent.GetContinuousAction(Span{float})"/>.</summary>
        /// <exception cref="VerveException">As <see cref="UpdateDemonstrated"/>, or a value outside [-1, 1], NaN, or
        /// too few values.</exception>
        public unsafe void UpdateDemonstratedContinuous(Agent[] agents, ReadOnlySpan<float> rewards,
            ReadOnlySpan<int> discrete, ReadOnlySpan<float> continuous, float dt, ReadOnlySpan<int> demonstrated,
            ReadOnlySpan<float> continuousActions, Span<int> actions, Span<ResultCode> results = default)
        {
            if (agents != null && demonstrated.Length != agents.Length)
                throw new ArgumentException($"{agents.Length} agents need as many demonstrated actions ({demonstrated.Length})");
            // The library reads nothing through a null pointer with a total of 0: an empty span is no values.
            float none = 0;
            fixed (int* shown = &MemoryMarshal.GetReference(demonstrated))
            fixed (float* values = &MemoryMarshal.GetReference(continuousActions))
                Step(agents!, rewards, discrete, continuous, dt, (uint*)shown, values == null ? &none : values,
                    (uint)continuousActions.Length, actions, results);
        }

        private unsafe void Step(Agent[] agents, ReadOnlySpan<float> rewards, ReadOnlySpan<int> discrete,
            ReadOnlySpan<float> continuous, float dt, uint* demonstrated, float* shownValues, uint shownTotal,
            Span<int> actions, Span<ResultCode> results)
        {
            if (agents == null) throw new ArgumentNullException(nameof(agents));
            if (rewards.Length != agents.Length || actions.Length != agents.Length)
                throw new ArgumentException($"{agents.Length} agents need as many rewards ({rewards.Length}) and actions ({actions.Length})");
            if (results.Length != 0 && results.Length != agents.Length)
                throw new ArgumentException($"{agents.Length} agents need as many results ({results.Length}), or none");
            BatchHandle handle = Handle;
            if (_agents.Length < agents.Length) _agents = new IntPtr[agents.Length];
            var held = new AgentHandle?[agents.Length]; // kept alive (not freed by another thread) during the call
            int taken = 0;
            try
            {
                for (; taken < agents.Length; taken++)
                {
                    AgentHandle h = (agents[taken] ?? throw new ArgumentNullException($"agents[{taken}]")).Handle;
                    bool added = false;
                    h.DangerousAddRef(ref added);
                    held[taken] = h;
                    _agents[taken] = h.DangerousGetHandle();
                }
                fixed (IntPtr* a = _agents)
                fixed (float* r = &MemoryMarshal.GetReference(rewards))
                fixed (int* d = &MemoryMarshal.GetReference(discrete))
                fixed (float* c = &MemoryMarshal.GetReference(continuous))
                fixed (int* o = &MemoryMarshal.GetReference(actions))
                fixed (ResultCode* v = &MemoryMarshal.GetReference(results))
                {
                    VerveException.ThrowIfFailed(demonstrated == null
                        ? NativeMethods.verve_batch_update(handle, a, (uint)agents.Length, r, d, null, (uint)discrete.Length,
                            c, null, (uint)continuous.Length, dt, (uint*)o, results.Length == 0 ? null : v)
                        : shownValues == null
                        ? NativeMethods.verve_batch_update_demonstrated(handle, a, (uint)agents.Length, r, d, null,
                            (uint)discrete.Length, c, null, (uint)continuous.Length, dt, demonstrated, (uint*)o,
                            results.Length == 0 ? null : v)
                        : NativeMethods.verve_batch_update_demonstrated_continuous(handle, a, (uint)agents.Length, r, d,
                            null, (uint)discrete.Length, c, null, (uint)continuous.Length, dt, demonstrated, shownValues,
                            null, shownTotal, (uint*)o, results.Length == 0 ? null : v));
                }
            }
            finally
            {
                for (int i = 0; i < taken; i++) held[i]!.DangerousRelease();
            }
        }

        /// <summary>Joins the batch's threads and frees it.</summary>
        public void Dispose() => _handle.Dispose();
    }
}
