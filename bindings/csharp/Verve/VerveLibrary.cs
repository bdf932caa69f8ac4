using System;
using Verve.Native;

namespace Verve
{
    /// <summary>Facts about the loaded native library.</summary>
    public static class VerveLibrary
    {
        /// <summary>The C ABI version this binding mirrors: (major &lt;&lt; 16) | (minor &lt;&lt; 8) | patch,
        /// as VERVE_VERSION_NUMBER in verve_c.h.</summary>
        public const int BindingVersionNumber = (0 << 16) | (1 << 8) | 0;

        private static volatile bool s_checked;

        /// <summary>VERVE_VERSION_NUMBER of the loaded libverve.</summary>
        public static int NativeVersionNumber => (int)NativeMethods.verve_version();

        /// <summary>Version of the loaded libverve.</summary>
        public static Version NativeVersion => ToVersion(NativeVersionNumber);

        /// <summary>Version of the C ABI this binding was written against.</summary>
        public static Version BindingVersion => ToVersion(BindingVersionNumber);

        /// <summary>Whether a library of <paramref name="nativeVersionNumber"/> can serve this binding:
        /// same major, and while major is 0 also the same minor (0.x minors may change the ABI).</summary>
        public static bool IsCompatible(int nativeVersionNumber)
        {
            Version native = ToVersion(nativeVersionNumber), binding = BindingVersion;
            return native.Major == binding.Major && (binding.Major > 0 || native.Minor == binding.Minor);
        }

        // Called before the first struct crosses the boundary: a mismatched library would misread it.
        internal static void EnsureCompatible()
        {
            WarningLog.Install(); // before any agent exists, or libverve refuses the hook
            if (s_checked) return;
            int native = NativeVersionNumber;
            if (!IsCompatible(native))
                throw new VerveException(ResultCode.Version,
                    $"libverve {ToVersion(native)} does not match the Verve C# binding {BindingVersion}");
            s_checked = true;
        }

        /// <summary>libverve's warnings since the previous call, oldest first (usually none): a reward
        /// clamped to [-1, 1] or an agent's RBF budget reached, each reported once per agent and also
        /// counted in <see cref="AgentStats.ClampedRewards"/> and <see cref="AgentStats.RbfBudgetHits"/>.
        /// At most 64 are kept between calls; a last entry then says how many more came. The binding
        /// installs libverve's log hook (verve_set_hooks) before its first agent, brain or batch; if
        /// libverve already held memory then (another binding's agents in the same process), none are
        /// collected.</summary>
        public static string[] TakeWarnings() => WarningLog.Take();

        private static Version ToVersion(int number) => new Version((number >> 16) & 0xff, (number >> 8) & 0xff, number & 0xff);
    }
}
