using System;
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>Owns one native <c>verve_batch*</c>; destroys it exactly once, even if the
    /// <see cref="Batch"/> is never disposed (the runtime then finalizes the handle).</summary>
    internal sealed class BatchHandle : SafeHandle
    {
        private BatchHandle() : base(IntPtr.Zero, ownsHandle: true) { }

        internal BatchHandle(IntPtr batch) : this() => SetHandle(batch);

        public override bool IsInvalid => handle == IntPtr.Zero;

        protected override bool ReleaseHandle()
        {
            NativeMethods.verve_batch_destroy(handle);
            return true;
        }
    }
}
