using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using Verve.Native;
using Xunit;

namespace Verve.Tests
{
    // The C# mirrors must match the C compiler's layout byte for byte: layout_probe (built from
    // verve_c.h with the C compiler) prints sizes, offsets and constants.
    public class NativeLayoutTests
    {
        private static readonly Lazy<Dictionary<string, long>> Probe = new Lazy<Dictionary<string, long>>(RunProbe);

        private static Dictionary<string, long> RunProbe()
        {
            var start = new ProcessStartInfo(Path.Combine(AppContext.BaseDirectory, "layout_probe"))
            {
                RedirectStandardOutput = true,
            };
            using var process = Process.Start(start)!;
            string output = process.StandardOutput.ReadToEnd();
            process.WaitForExit();
            Assert.Equal(0, process.ExitCode);
            // "size T n", "offset T field n", "const NAME n": key is everything but the number.
            return output.Split('\n', StringSplitOptions.RemoveEmptyEntries)
                .Select(line => line.Split(' '))
                .ToDictionary(words => string.Join(' ', words.Take(words.Length - 1)), words => long.Parse(words[^1]));
        }

        [Theory]
        [InlineData(typeof(verve_agent_desc), "verve_agent_desc")]
        [InlineData(typeof(verve_agent_stats), "verve_agent_stats")]
        [InlineData(typeof(ValueAxis), "verve_value_axis")]
        [InlineData(typeof(verve_batch_desc), "verve_batch_desc")]
        [InlineData(typeof(verve_hooks), "verve_hooks")]
        public void StructMatchesC(Type mirror, string cName)
        {
            Assert.Equal(Probe.Value["size " + cName], Marshal.SizeOf(mirror));

            var fields = mirror.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic)
                .Select(f => f.Name).ToList();
            var cFields = Probe.Value.Keys.Where(k => k.StartsWith("offset " + cName + " ", StringComparison.Ordinal))
                .Select(k => k.Split(' ')[2]).ToList();
            Assert.Equal(cFields, fields); // same names, same order
            foreach (string field in cFields)
                Assert.True(Probe.Value[$"offset {cName} {field}"] == (long)Marshal.OffsetOf(mirror, field), $"offset of {cName}.{field}");
        }

        [Fact]
        public unsafe void StructsAreBlittable()
        {
            // sizeof in C# is the unmanaged size only for blittable types; equal to the marshalled size proves no copy.
            Assert.Equal(Marshal.SizeOf<verve_agent_desc>(), sizeof(verve_agent_desc));
            Assert.Equal(Marshal.SizeOf<verve_agent_stats>(), sizeof(verve_agent_stats));
            Assert.Equal(Marshal.SizeOf<ValueAxis>(), sizeof(ValueAxis));
            GCHandle.Alloc(new ValueAxis[1], GCHandleType.Pinned).Free(); // throws for non-blittable types
        }

        [Fact]
        public void ConstantsMatchC()
        {
            var c = Probe.Value;
            Assert.Equal(VerveLibrary.BindingVersionNumber, c["const VERVE_VERSION_NUMBER"]);
            Assert.Equal(verve_agent_desc.MaxDiscreteSensors, c["const VERVE_MAX_DISCRETE_SENSORS"]);
            Assert.Equal(verve_agent_desc.MaxContinuousSensors, c["const VERVE_MAX_CONTINUOUS_SENSORS"]);
            Assert.Equal(AgentOptions.MaxDiscreteSensors, c["const VERVE_MAX_SENSORS"]);
            Assert.Equal(AgentOptions.MaxContinuousSensors, c["const VERVE_MAX_SENSORS"]);
            Assert.Equal(AgentOptions.MaxLatticeSensors, c["const VERVE_MAX_LATTICE_SENSORS"]);
            Assert.Equal((long)RbfAllocation.Full, c["const VERVE_RBF_FULL"]);
            Assert.Equal((long)Curiosity.Progress, c["const VERVE_CURIOSITY_PROGRESS"]);
            Assert.Equal((long)SensorKind.Continuous, c["const VERVE_SENSOR_CONTINUOUS"]);
            Assert.Equal((long)ResultCode.Internal, c["const VERVE_ERROR_INTERNAL"]);
            Assert.Equal((long)ActionSelection.Greedy, c["const VERVE_GREEDY"]);
            Assert.Equal((long)Adaptation.All, c["const VERVE_ADAPT_ALL"]);
            Assert.Equal(AgentOptions.MaxSensorGroups, c["const VERVE_MAX_SENSOR_GROUPS"]);
            Assert.Equal(AgentOptions.MaxActionBranches, c["const VERVE_MAX_ACTION_BRANCHES"]);
            Assert.Equal(AgentOptions.MaxContinuousActions, c["const VERVE_MAX_CONTINUOUS_ACTIONS"]);
            Assert.Equal((long)SensorGrouping.Auto, c["const VERVE_GROUPING_AUTO"]);
            Assert.Equal((long)SensorGrouping.Joint, c["const VERVE_GROUPING_JOINT"]);
            Assert.Equal((long)SensorGrouping.Custom, c["const VERVE_GROUPING_CUSTOM"]);
            Assert.Equal(sizeof(ResultCode), c["const sizeof_enum"]);
        }

        [Fact]
        public unsafe void BindingUsesTheCurrentDescriptorVersion()
        {
            Assert.Equal(Probe.Value["const VERVE_AGENT_DESC_SIZE_V8"], sizeof(verve_agent_desc));
            // V7 ended where the V8 arrays begin, V6 where the V7 field begins, V5 where the V6 fields begin, V4 where the V5 fields begin.
            Assert.Equal(Probe.Value["const VERVE_AGENT_DESC_SIZE_V7"], (long)Marshal.OffsetOf<verve_agent_desc>("more_discrete_sensor_values"));
            Assert.Equal(Probe.Value["const VERVE_AGENT_DESC_SIZE_V6"], (long)Marshal.OffsetOf<verve_agent_desc>("num_continuous_actions"));
            Assert.Equal(Probe.Value["const VERVE_AGENT_DESC_SIZE_V5"], (long)Marshal.OffsetOf<verve_agent_desc>("num_action_branches"));
            Assert.Equal(Probe.Value["const VERVE_AGENT_DESC_SIZE_V4"], (long)Marshal.OffsetOf<verve_agent_desc>("sensor_grouping"));
        }

        [Fact]
        public unsafe void DescriptorDefaultsAgreeBetweenDefaultAndInit()
        {
            // verve_agent_desc_default writes the library's whole struct; give it room to spare.
            byte* scratch = stackalloc byte[2048];
            NativeMethods.verve_agent_desc_default(scratch);
            Assert.Equal(Probe.Value["size verve_agent_desc"], *(uint*)scratch);

            var init = new verve_agent_desc();
            Assert.Equal(ResultCode.Ok, NativeMethods.verve_agent_desc_init(&init, (uint)sizeof(verve_agent_desc)));
            Assert.True(new ReadOnlySpan<byte>(scratch, sizeof(verve_agent_desc)).SequenceEqual(
                new ReadOnlySpan<byte>(&init, sizeof(verve_agent_desc))));
        }

        [Fact]
        public unsafe void DescriptorInitRefusesUnknownSizes()
        {
            var d = new verve_agent_desc();
            Assert.Equal(ResultCode.InvalidArgument, NativeMethods.verve_agent_desc_init(&d, 3));
            Assert.Equal(0u, d.struct_size); // nothing written
        }
    }
}
