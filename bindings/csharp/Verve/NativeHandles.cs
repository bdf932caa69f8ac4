using System;
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>Owns one native object; destroys it exactly once, even if its owner is never
    /// disposed (the runtime then finalizes the handle). Each kind names only its destroy call.</summary>
    internal abstract class NativeHandle : SafeHandle
    {
        protected NativeHandle() : base(IntPtr.Zero, ownsHandle: true) { }

        protected NativeHandle(IntPtr native) : this() => SetHandle(native);

        public override bool IsInvalid => handle == IntPtr.Zero;
    }

    /// <summary>A <c>verve_agent*</c>, owned by an <see cref="Agent"/>.</summary>
    internal sealed class AgentHandle : NativeHandle
    {
        private AgentHandle() { }

        internal AgentHandle(IntPtr agent) : base(agent) { }

        protected override bool ReleaseHandle()
        {
            NativeMethods.verve_agent_destroy(handle);
            return true;
        }
    }

    /// <summary>A <c>verve_brain*</c>, owned by a <see cref="Brain"/>.</summary>
    internal sealed class BrainHandle : NativeHandle
    {
        private BrainHandle() { }

        internal BrainHandle(IntPtr brain) : base(brain) { }

        protected override bool ReleaseHandle()
        {
            NativeMethods.verve_brain_destroy(handle);
            return true;
        }
    }

    /// <summary>A <c>verve_recording*</c>, owned by a <see cref="Recording"/>.</summary>
    internal sealed class RecordingHandle : NativeHandle
    {
        private RecordingHandle() { }

        internal RecordingHandle(IntPtr recording) : base(recording) { }

        protected override bool ReleaseHandle()
        {
            NativeMethods.verve_recording_destroy(handle);
            return true;
        }
    }

    /// <summary>A <c>verve_batch*</c>, owned by a <see cref="Batch"/>.</summary>
    internal sealed class BatchHandle : NativeHandle
    {
        private BatchHandle() { }

        internal BatchHandle(IntPtr batch) : base(batch) { }

        protected override bool ReleaseHandle()
        {
            NativeMethods.verve_batch_destroy(handle);
            return true;
        }
    }
}
