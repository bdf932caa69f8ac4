using System;
using Xunit;

namespace Verve.Tests
{
    public class DisposeTests
    {
        public static TheoryData<string, Action<Agent>> Calls => new TheoryData<string, Action<Agent>>
        {
            { "Update(arrays)", a => a.Update(0f, new[] { 0, 0 }, new[] { 0f, 0f }, TestAgents.Dt) },
            { "Update(spans)", a => a.Update(0f, new ReadOnlySpan<int>(new[] { 0, 0 }), new ReadOnlySpan<float>(new[] { 0f, 0f }), TestAgents.Dt) },
            { "EndEpisode", a => a.EndEpisode(0f) },
            { "ResetShortTermMemory", a => a.ResetShortTermMemory() },
            { "Learning get", a => _ = a.Learning },
            { "Learning set", a => a.Learning = false },
            { "Options", a => _ = a.Options },
            { "Value", a => _ = a.Value },
            { "TdError", a => _ = a.TdError },
            { "RbfCount", a => _ = a.RbfCount },
            { "Stats", a => _ = a.Stats },
            { "SampleValues", a => a.SampleValues(ValueAxis.Discrete(0, 4), new[] { 0, 0 }, new[] { 0f, 0f }) },
            { "Save", a => a.Save("never-written.xml") },
            { "SaveToBytes", a => a.SaveToBytes() },
            { "SaveBinary", a => a.SaveBinary("never-written.xml") },
            { "SaveToBinaryBytes", a => a.SaveToBinaryBytes() },
        };

        [Theory]
        [MemberData(nameof(Calls))]
        public void EveryCallOnADisposedAgentThrows(string name, Action<Agent> call)
        {
            var agent = TestAgents.Mixed();
            agent.Dispose();
            Assert.True(agent.IsDisposed);
            var e = Assert.Throws<ObjectDisposedException>(() => call(agent));
            Assert.Equal(nameof(Agent), e.ObjectName);
            Assert.False(System.IO.File.Exists("never-written.xml"), name);
        }

        [Fact]
        public void DisposeTwiceIsHarmless()
        {
            var agent = TestAgents.Mixed();
            Assert.False(agent.IsDisposed);
            agent.Dispose();
            agent.Dispose();
            Assert.True(agent.IsDisposed);
        }

        [Fact]
        public void UndisposedAgentsAreFinalized()
        {
            // Many abandoned agents: the SafeHandle finalizer frees them (a leak would still pass,
            // but a double free or a free of garbage would crash the test host).
            for (int i = 0; i < 200; i++) TestAgents.Run(TestAgents.Mixed((ulong)i), 5);
            GC.Collect();
            GC.WaitForPendingFinalizers();
            GC.Collect();
        }
    }
}
