using System;

namespace Verve
{
    // The C ABI's two-call memory save (the size, then the bytes), shared by Agent and Brain. The
    // library serialises once for both calls.
    internal static class MemorySave
    {
        internal unsafe delegate ResultCode Call(byte* buffer, ref UIntPtr size);

        internal static unsafe byte[] ToBytes(Call save)
        {
            var size = UIntPtr.Zero;
            VerveException.ThrowIfFailed(save(null, ref size));
            var bytes = new byte[checked((int)size.ToUInt64())];
            fixed (byte* b = bytes)
                VerveException.ThrowIfFailed(save(b, ref size));
            if (size.ToUInt64() != (ulong)bytes.Length) Array.Resize(ref bytes, (int)size.ToUInt64());
            return bytes;
        }
    }
}
