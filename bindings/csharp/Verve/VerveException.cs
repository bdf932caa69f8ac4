using System;
using System.Runtime.InteropServices;
using Verve.Native;

namespace Verve
{
    /// <summary>A native Verve call failed. Nothing was changed by the failed call.</summary>
    public sealed class VerveException : Exception
    {
        /// <summary>The result code the C ABI returned.</summary>
        public ResultCode Code { get; }

        /// <summary>Creates an exception for <paramref name="code"/> with the native message.</summary>
        public VerveException(ResultCode code, string message) : base(message) => Code = code;

        // Reads verve_last_error() right after the failed call, on the same thread (it is thread-local).
        internal static void ThrowIfFailed(ResultCode code)
        {
            if (code != ResultCode.Ok) throw FromLastError(code);
        }

        private static VerveException FromLastError(ResultCode code)
        {
            string detail = Marshal.PtrToStringUTF8(NativeMethods.verve_last_error()) ?? "";
            string name = Marshal.PtrToStringUTF8(NativeMethods.verve_result_name(code)) ?? code.ToString();
            return new VerveException(code, detail.Length == 0 ? name : name + ": " + detail);
        }
    }
}
