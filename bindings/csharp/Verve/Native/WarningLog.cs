using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;

namespace AOT
{
    /// <summary>Marks a static method that native code calls back. IL2CPP looks for an attribute of this
    /// name (Unity's own lives in UnityEngine, which this assembly does not reference) and only then
    /// makes the method callable from native code; .NET and Mono ignore it.</summary>
    [AttributeUsage(AttributeTargets.Method)]
    internal sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public MonoPInvokeCallbackAttribute(Type type) { Type = type; }
        public Type Type { get; }
    }
}

namespace Verve.Native
{
    /// <summary>libverve's log hook: keeps the warnings until <see cref="VerveLibrary.TakeWarnings"/>.
    /// Called from whichever thread warns (batch workers too), so the queue is locked.</summary>
    internal static class WarningLog
    {
        internal const int Capacity = 64;

        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        internal delegate void LogFn(IntPtr user, int level, IntPtr message);

        private static readonly object s_lock = new object();
        private static readonly List<string> s_messages = new List<string>();
        private static long s_dropped;
        // Kept alive for the process: libverve holds its function pointer.
        private static readonly LogFn s_hook = OnWarning;
        private static volatile bool s_installed;

        [AOT.MonoPInvokeCallback(typeof(LogFn))]
        private static void OnWarning(IntPtr user, int level, IntPtr message)
        {
            string text = Marshal.PtrToStringAnsi(message) ?? "";
            lock (s_lock)
            {
                if (s_messages.Count < Capacity) s_messages.Add(text);
                else ++s_dropped;
            }
        }

        // Tried before each agent, brain or batch is made until it succeeds: libverve accepts the hook
        // only while it holds no memory.
        internal static unsafe void Install()
        {
            if (s_installed) return;
            lock (s_lock)
            {
                if (s_installed) return;
                var hooks = new verve_hooks
                {
                    struct_size = (uint)sizeof(verve_hooks),
                    log_fn = Marshal.GetFunctionPointerForDelegate(s_hook),
                };
                if (NativeMethods.verve_set_hooks(&hooks) == ResultCode.Ok) s_installed = true;
            }
        }

        internal static string[] Take()
        {
            lock (s_lock)
            {
                int extra = s_dropped > 0 ? 1 : 0;
                var taken = new string[s_messages.Count + extra];
                s_messages.CopyTo(taken);
                if (extra == 1)
                    taken[taken.Length - 1] = $"{s_dropped} more warnings were dropped (at most {Capacity} are kept between reads)";
                s_messages.Clear();
                s_dropped = 0;
                return taken;
            }
        }
    }
}
