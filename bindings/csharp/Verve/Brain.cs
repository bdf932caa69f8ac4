using System;
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>One brain, many bodies: a learner (RBFs, weights, model) shared by many NPCs of one kind.
    /// Each body made by <see cref="CreateBody"/> is an <see cref="Agent"/> with its own short-term memory
    /// (traces, previous step, random stream) that trains the brain's shared weights, so what one NPC
    /// learns, all of them know.</summary>
    /// <remarks>A brain and all its bodies count as one agent for threads: use them from one thread at a
    /// time (a <see cref="Batch"/> updates a brain's bodies in parallel, in phases whose result depends only on
    /// their order: docs/crowds.md); an overlapping call from
    /// another thread throws <see cref="VerveException"/> with <see cref="ResultCode.InvalidState"/>. A body
    /// keeps its brain alive: disposing the brain first is fine.</remarks>
    public sealed class Brain : IDisposable
    {
        private readonly BrainHandle _handle;

        /// <summary>Creates a brain described by <paramref name="options"/>.</summary>
        /// <exception cref="VerveException">The description is invalid (the message names the field).</exception>
        /// <exception cref="ArgumentException">The sensor groups do not fit the continuous sensors (one names a
        /// sensor the options lack, or a sensor is in none), or are given without <see cref="SensorGrouping.Custom"/>.</exception>
        public unsafe Brain(AgentOptions options)
        {
            if (options == null) throw new ArgumentNullException(nameof(options));
            verve_agent_desc desc = options.ToNative();
            VerveException.ThrowIfFailed(NativeMethods.verve_brain_create(&desc, out IntPtr brain));
            _handle = new BrainHandle(brain);
        }

        private Brain(IntPtr brain) => _handle = new BrainHandle(brain);

        /// <summary>Whether <see cref="Dispose"/> has been called.</summary>
        public bool IsDisposed => _handle.IsClosed;

        private BrainHandle Handle => _handle.IsClosed ? throw new ObjectDisposedException(nameof(Brain)) : _handle;

        /// <summary>A new body. Body k of a brain draws its actions from a random stream of the seed and k.</summary>
        public Agent CreateBody()
        {
            VerveException.ThrowIfFailed(NativeMethods.verve_brain_create_body(Handle, out IntPtr body));
            return new Agent(body);
        }

        /// <summary>RBFs allocated so far, by all bodies.</summary>
        public int RbfCount
        {
            get
            {
                VerveException.ThrowIfFailed(NativeMethods.verve_brain_get_rbf_count(Handle, out uint count));
                return (int)count;
            }
        }

        /// <summary>Saves the brain as XML, atomically, as an agent save without short-term memory: it
        /// loads with <see cref="Load"/> or <see cref="Agent.Load"/>.</summary>
        public void Save(string path) => SaveFile(path, binary: false);

        /// <summary>As <see cref="Save(string)"/>, in the compact binary format: about half the size,
        /// and faster to save and to load. <see cref="Load"/> and <see cref="Agent.Load"/> read both.</summary>
        public void SaveBinary(string path) => SaveFile(path, binary: true);

        private unsafe void SaveFile(string path, bool binary)
        {
            BrainHandle handle = Handle;
            fixed (byte* p = Agent.NulTerminatedUtf8(path))
                VerveException.ThrowIfFailed(binary ? NativeMethods.verve_brain_save_binary(handle, p)
                                                    : NativeMethods.verve_brain_save(handle, p));
        }

        /// <summary>Loads a brain from a brain's or an agent's save, XML or binary (its RBFs and weights).</summary>
        public static unsafe Brain Load(string path)
        {
            VerveLibrary.EnsureCompatible();
            IntPtr brain;
            fixed (byte* p = Agent.NulTerminatedUtf8(path))
                VerveException.ThrowIfFailed(NativeMethods.verve_brain_load(p, out brain));
            return new Brain(brain);
        }

        /// <summary>The brain's save (the same XML as <see cref="Save(string)"/>) as bytes.</summary>
        public byte[] SaveToBytes() => SaveMemory(binary: false);

        /// <summary>The brain's binary save (the same bytes as <see cref="SaveBinary(string)"/>).</summary>
        public byte[] SaveToBinaryBytes() => SaveMemory(binary: true);

        private unsafe byte[] SaveMemory(bool binary)
        {
            BrainHandle handle = Handle;
            return MemorySave.ToBytes(binary
                ? (MemorySave.Call)((byte* b, ref UIntPtr size) => NativeMethods.verve_brain_save_memory_binary(handle, b, ref size))
                : (byte* b, ref UIntPtr size) => NativeMethods.verve_brain_save_memory(handle, b, ref size));
        }

        /// <summary>Loads a brain from bytes of <see cref="SaveToBytes"/>, <see cref="SaveToBinaryBytes"/>,
        /// <see cref="Agent.SaveToBytes"/> or <see cref="Agent.SaveToBinaryBytes"/>.</summary>
        /// <exception cref="VerveException"><see cref="ResultCode.Format"/> when the bytes are corrupt or truncated.</exception>
        public static unsafe Brain LoadFromBytes(ReadOnlySpan<byte> data)
        {
            VerveLibrary.EnsureCompatible();
            IntPtr brain;
            fixed (byte* d = &MemoryMarshal.GetReference(data))
                VerveException.ThrowIfFailed(NativeMethods.verve_brain_load_memory(d, (UIntPtr)data.Length, out brain));
            return new Brain(brain);
        }

        /// <summary>Releases the brain; bodies still alive keep its data.</summary>
        public void Dispose() => _handle.Dispose();
    }
}
