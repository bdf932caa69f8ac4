using System;
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>Owns one native <c>verve_brain*</c>; destroys it exactly once, even if the
    /// <see cref="Brain"/> is never disposed (the runtime then finalizes the handle).</summary>
    internal sealed class BrainHandle : SafeHandle
    {
        private BrainHandle() : base(IntPtr.Zero, ownsHandle: true) { }

        internal BrainHandle(IntPtr brain) : this() => SetHandle(brain);

        public override bool IsInvalid => handle == IntPtr.Zero;

        protected override bool ReleaseHandle()
        {
            NativeMethods.verve_brain_destroy(handle);
            return true;
        }
    }
}
