// Nullable annotations on: Unity compiles these sources without the .csproj that enables them.
#nullable enable
using System;
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>Demonstrated steps kept for replay (docs/teaching.md, "Recordings"): record what a player or a
    /// scripted AI did, save it, and <see cref="Agent.Replay"/> it into an agent before the game ships. Every entry
    /// is checked as the agent would check it when it is added (a refused one is not recorded). One thread at a
    /// time; dispose it to free the native memory at once.</summary>
    public sealed class Recording : IDisposable
    {
        private readonly RecordingHandle _handle;

        /// <summary>An empty recording with <paramref name="shapedLike"/>'s sensors and actions.</summary>
        public Recording(Agent shapedLike)
        {
            if (shapedLike == null) throw new ArgumentNullException(nameof(shapedLike));
            VerveException.ThrowIfFailed(NativeMethods.verve_recording_create(shapedLike.Handle, out IntPtr recording));
            _handle = new RecordingHandle(recording);
        }

        private Recording(IntPtr recording) => _handle = new RecordingHandle(recording);

        internal RecordingHandle Handle => _handle.IsClosed ? throw new ObjectDisposedException(nameof(Recording)) : _handle;

        /// <summary>One demonstrated step, as <see cref="Agent.UpdateDemonstrated"/> takes it (no mask).</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="action"/> is negative.</exception>
        /// <exception cref="VerveException">A value out of range or not finite, wrong counts, or a full recording.</exception>
        public unsafe void AddStep(float reward, ReadOnlySpan<int> discrete, ReadOnlySpan<float> continuous, float dt, int action)
        {
            if (action < 0) throw new ArgumentOutOfRangeException(nameof(action), action, "an action is an index from 0");
            RecordingHandle handle = Handle;
            fixed (int* d = &MemoryMarshal.GetReference(discrete))
            fixed (float* c = &MemoryMarshal.GetReference(continuous))
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_recording_add_step(handle, reward,
                    d, (uint)discrete.Length, c, (uint)continuous.Length, dt, (uint)action));
            }
        }

        /// <summary>One demonstrated step with the host's continuous actions, as
        /// <see cref="Agent.UpdateDemonstratedContinuous"/> takes it (no mask).</summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="action"/> is negative.</exception>
        /// <exception cref="VerveException">As <see cref="AddStep"/>, or a wrong count of continuous values, NaN or a
        /// value outside [-1, 1].</exception>
        public unsafe void AddStepContinuous(float reward, ReadOnlySpan<int> discrete, ReadOnlySpan<float> continuous, float dt,
            int action, ReadOnlySpan<float> continuousAction)
        {
            if (action < 0) throw new ArgumentOutOfRangeException(nameof(action), action, "an action is an index from 0");
            RecordingHandle handle = Handle;
            fixed (int* d = &MemoryMarshal.GetReference(discrete))
            fixed (float* c = &MemoryMarshal.GetReference(continuous))
            fixed (float* v = &MemoryMarshal.GetReference(continuousAction))
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_recording_add_step_continuous(handle, reward,
                    d, (uint)discrete.Length, c, (uint)continuous.Length, dt, (uint)action, v, (uint)continuousAction.Length));
            }
        }

        /// <summary>A trial's real end, as <see cref="Agent.EndEpisode"/> takes it.</summary>
        public void AddEndEpisode(float finalReward) =>
            VerveException.ThrowIfFailed(NativeMethods.verve_recording_add_end_episode(Handle, finalReward));

        /// <summary>A trial cut off, as <see cref="Agent.TruncateEpisode"/> takes it.</summary>
        public void AddTruncation(float reward) =>
            VerveException.ThrowIfFailed(NativeMethods.verve_recording_add_truncation(Handle, reward));

        /// <summary>Entries so far (steps and trial ends).</summary>
        public long Count
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_recording_get_size(Handle, out ulong entries));
                return (long)entries;
            }
        }

        /// <summary>Writes the recording's file atomically (a crash leaves the old file or the new one).</summary>
        public unsafe void Save(string path)
        {
            RecordingHandle handle = Handle;
            fixed (byte* p = Agent.NulTerminatedUtf8(path))
                VerveException.ThrowIfFailed(NativeMethods.verve_recording_save(handle, p));
        }

        /// <summary>The recording's file as bytes.</summary>
        public unsafe byte[] SaveToBytes()
        {
            RecordingHandle handle = Handle;
            return MemorySave.ToBytes((byte* b, ref UIntPtr size) => NativeMethods.verve_recording_save_memory(handle, b, ref size));
        }

        /// <summary>Loads a recording written by <see cref="Save"/>.</summary>
        /// <exception cref="VerveException"><see cref="ResultCode.Io"/>, <see cref="ResultCode.Format"/> or <see cref="ResultCode.Version"/>.</exception>
        public static unsafe Recording Load(string path)
        {
            VerveLibrary.EnsureCompatible();
            IntPtr recording;
            fixed (byte* p = Agent.NulTerminatedUtf8(path))
                VerveException.ThrowIfFailed(NativeMethods.verve_recording_load(p, out recording));
            return new Recording(recording);
        }

        /// <summary>Loads a recording from bytes made by <see cref="SaveToBytes"/>.</summary>
        public static unsafe Recording LoadFromBytes(ReadOnlySpan<byte> data)
        {
            VerveLibrary.EnsureCompatible();
            IntPtr recording;
            fixed (byte* d = &MemoryMarshal.GetReference(data))
                VerveException.ThrowIfFailed(NativeMethods.verve_recording_load_memory(d, (UIntPtr)data.Length, out recording));
            return new Recording(recording);
        }

        /// <summary>Frees the native recording. Further calls throw <see cref="ObjectDisposedException"/>.</summary>
        public void Dispose() => _handle.Dispose();
    }
}
