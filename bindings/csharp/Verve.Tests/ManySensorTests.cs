using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // 32 sensors of each kind (up to 64; issue 30): the options round trip through the library's V8
    // descriptor, saves act the same, a batch acts as each agent alone, and the lattice limit.
    public class ManySensorTests
    {
        private const int N = 32;

        private static AgentOptions Options(ulong seed = 5)
        {
            var o = new AgentOptions { Actions = 4, Seed = seed };
            for (int i = 0; i < N; i++) o.AddDiscreteSensor(i % 8 == 0 ? 2 : 1);
            for (int i = 0; i < N; i++) o.AddContinuousSensor(circular: i % 5 == 0);
            return o;
        }

        private static (int[] discrete, float[] continuous) Observation(int step)
        {
            var d = new int[N];
            var c = new float[N];
            for (int i = 0; i < N; i++)
            {
                d[i] = i % 8 == 0 ? (step / 3 + i) % 2 : 0;
                c[i] = 0.9f * MathF.Sin(0.1f * step * (0.3f + 0.17f * i) + i);
            }
            return (d, c);
        }

        [Fact]
        public void ThirtyTwoSensorsRoundTripAndSavesActTheSame()
        {
            Assert.Equal(64, AgentOptions.MaxContinuousSensors);
            Assert.Equal(64, AgentOptions.MaxDiscreteSensors);
            using var agent = new Agent(Options());
            var back = agent.Options;
            Assert.Equal(Options().DiscreteSensors, back.DiscreteSensors);
            Assert.Equal(Options().ContinuousSensorCircular, back.ContinuousSensorCircular);
            for (int step = 0; step < 200; step++)
            {
                var (d, c) = Observation(step);
                int a = agent.Update(MathF.Sin(0.05f * step), d, c, 0.1f);
                Assert.InRange(a, 0, 3);
            }
            Assert.True(agent.RbfCount >= 63, $"{agent.RbfCount} RBFs"); // Auto: 32 singles + 31 pairs
            int step2 = 200;
            foreach (bool binary in new[] { false, true })
            {
                using var copy = Agent.LoadFromBytes(binary ? agent.SaveToBinaryBytes() : agent.SaveToBytes());
                Assert.Equal(N, copy.Options.ContinuousSensorCircular.Count);
                for (int k = 0; k < 60; k++, step2++)
                {
                    var (d, c) = Observation(step2);
                    Assert.Equal(agent.Update(0f, d, c, 0.1f), copy.Update(0f, d, c, 0.1f));
                }
            }
        }

        [Fact]
        public void ABatchOf32SensorAgentsActsAsEachAlone()
        {
            using var solo = new Agent(Options());
            using var a = new Agent(Options());
            using var b = new Agent(Options());
            using var batch = new Batch(workerCount: 2);
            var actions = new int[2];
            for (int step = 0; step < 100; step++)
            {
                var (d, c) = Observation(step);
                int expected = solo.Update(0.1f, d, c, 0.1f);
                batch.Update(new[] { a, b }, new[] { 0.1f, 0.1f }, d.Concat(d).ToArray(), c.Concat(c).ToArray(), 0.1f, actions);
                Assert.Equal(expected, actions[0]);
                Assert.Equal(expected, actions[1]);
            }
        }

        [Fact]
        public void OverSixtyFourSensorsOrOneLatticeOverSixteenIsRefused()
        {
            var o = new AgentOptions();
            for (int i = 0; i < AgentOptions.MaxContinuousSensors; i++) o.AddContinuousSensor();
            Assert.Throws<InvalidOperationException>(() => o.AddContinuousSensor());

            var joint = Options();
            joint.Grouping = SensorGrouping.Joint;
            var e = Assert.Throws<VerveException>(() => new Agent(joint));
            Assert.Equal(ResultCode.InvalidArgument, e.Code);
            Assert.Contains("which spans at most 16", e.Message);
            Assert.Equal(16, AgentOptions.MaxLatticeSensors);

            // Custom groups of 16 read 64 sensors.
            var custom = new AgentOptions { Actions = 2 };
            for (int i = 0; i < 64; i++) custom.AddContinuousSensor();
            for (int g = 0; g < 4; g++) custom.AddSensorGroup(Enumerable.Range(16 * g, 16).ToArray());
            using var agent = new Agent(custom);
            agent.Update(0f, Array.Empty<int>(), Enumerable.Repeat(0.5f, 64).ToArray(), 0.1f);
            Assert.Equal(4, agent.Options.SensorGroups.Count);
        }
    }
}
