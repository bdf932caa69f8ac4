using System;
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>Owns one native <c>verve_agent*</c>; destroys it exactly once, even if the
    /// <see cref="Agent"/> is never disposed (the runtime then finalizes the handle).</summary>
    internal sealed class AgentHandle : SafeHandle
    {
        private AgentHandle() : base(IntPtr.Zero, ownsHandle: true) { }

        internal AgentHandle(IntPtr agent) : this() => SetHandle(agent);

        public override bool IsInvalid => handle == IntPtr.Zero;

        protected override bool ReleaseHandle()
        {
            NativeMethods.verve_agent_destroy(handle);
            return true;
        }
    }
}
