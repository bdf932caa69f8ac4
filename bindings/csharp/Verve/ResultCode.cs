namespace Verve
{
    /// <summary>Mirror of <c>verve_result</c>: why a native call failed.</summary>
    public enum ResultCode
    {
        /// <summary>Success.</summary>
        Ok = 0,
        /// <summary>A wrong count, NaN/infinity or an out-of-range value.</summary>
        InvalidArgument = 1,
        /// <summary>The call does not fit the agent's state.</summary>
        InvalidState = 2,
        /// <summary>A file could not be read, written or renamed.</summary>
        Io = 3,
        /// <summary>A save is corrupt, truncated or inconsistent.</summary>
        Format = 4,
        /// <summary>A save written by a newer format version.</summary>
        Version = 5,
        /// <summary>The native library ran out of memory.</summary>
        OutOfMemory = 6,
        /// <summary>An output buffer was too small.</summary>
        BufferTooSmall = 7,
        /// <summary>A bug in the native library.</summary>
        Internal = 8,
    }
}
