using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    public class AgentUpdateTests
    {
        [Fact]
        public void ActionsAreInRangeAndStepsCounted()
        {
            using var agent = TestAgents.Mixed();
            int[] actions = TestAgents.Run(agent, 200);
            Assert.All(actions, a => Assert.InRange(a, 0, TestAgents.Actions - 1));
            Assert.True(actions.Distinct().Count() > 1, "an untrained agent explores");
            Assert.Equal(200, agent.Stats.Steps);
            Assert.True(agent.RbfCount > 0);
        }

        [Fact]
        public void SameSeedSameActions_SpanAndArrayOverloadsAgree()
        {
            using var withArrays = TestAgents.Mixed(seed: 3);
            using var withSpans = TestAgents.Mixed(seed: 3);
            Span<int> discrete = stackalloc int[2];
            Span<float> continuous = stackalloc float[2];
            for (int step = 0; step < 300; step++)
            {
                TestAgents.Discrete(step).CopyTo(discrete);
                TestAgents.Continuous(step).CopyTo(continuous);
                int fromSpans = withSpans.Update(TestAgents.Reward(step), discrete, continuous, TestAgents.Dt);
                int fromArrays = withArrays.Update(TestAgents.Reward(step), TestAgents.Discrete(step), TestAgents.Continuous(step), TestAgents.Dt);
                Assert.Equal(fromArrays, fromSpans);
            }
            Assert.Equal(withArrays.SaveToBytes(), withSpans.SaveToBytes());
        }

        [Fact]
        public void SpanUpdatesAllocateNoManagedMemory()
        {
            using var agent = TestAgents.Mixed();
            Span<int> discrete = stackalloc int[] { 1, 2 };
            Span<float> continuous = stackalloc float[] { 0.1f, -0.4f };
            for (int i = 0; i < 100; i++) agent.Update(0f, discrete, continuous, TestAgents.Dt); // warm up (JIT)

            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 1000; i++)
            {
                continuous[0] = (i % 21 - 10) / 10f;
                agent.Update(i % 3 - 1, discrete, continuous, TestAgents.Dt);
            }
            Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        }

        [Fact]
        public void DifferentSeedsDiverge()
        {
            using var a = TestAgents.Mixed(seed: 1);
            using var b = TestAgents.Mixed(seed: 2);
            Assert.NotEqual(TestAgents.Run(a, 100), TestAgents.Run(b, 100));
        }

        [Fact]
        public void AgentWithOnlyContinuousSensorsTakesNullDiscrete()
        {
            using var agent = new Agent(new AgentOptions { Actions = 2 }.AddContinuousSensor());
            int action = agent.Update(0f, null, new[] { 0.5f }, TestAgents.Dt);
            Assert.InRange(action, 0, 1);
            using var noSensors = new Agent(new AgentOptions { Actions = 4 }); // a bandit: one state
            Assert.InRange(noSensors.Update(0f, null, null, TestAgents.Dt), 0, 3);
        }

        public static TheoryData<string, int[]?, float[]?, float, float> BadSteps => new TheoryData<string, int[]?, float[]?, float, float>
        {
            { "too few discrete values", new[] { 1 }, new[] { 0f, 0f }, 0f, TestAgents.Dt },
            { "too many discrete values", new[] { 1, 1, 1 }, new[] { 0f, 0f }, 0f, TestAgents.Dt },
            { "missing discrete values", null, new[] { 0f, 0f }, 0f, TestAgents.Dt },
            { "too few continuous values", new[] { 1, 1 }, new[] { 0f }, 0f, TestAgents.Dt },
            { "too many continuous values", new[] { 1, 1 }, new[] { 0f, 0f, 0f }, 0f, TestAgents.Dt },
            { "discrete value too large", new[] { 4, 1 }, new[] { 0f, 0f }, 0f, TestAgents.Dt },
            { "negative discrete value", new[] { -1, 1 }, new[] { 0f, 0f }, 0f, TestAgents.Dt },
            { "NaN observation", new[] { 1, 1 }, new[] { float.NaN, 0f }, 0f, TestAgents.Dt },
            { "infinite observation", new[] { 1, 1 }, new[] { 0f, float.NegativeInfinity }, 0f, TestAgents.Dt },
            { "NaN reward", new[] { 1, 1 }, new[] { 0f, 0f }, float.NaN, TestAgents.Dt },
            { "infinite reward", new[] { 1, 1 }, new[] { 0f, 0f }, float.PositiveInfinity, TestAgents.Dt },
            { "zero dt", new[] { 1, 1 }, new[] { 0f, 0f }, 0f, 0f },
            { "negative dt", new[] { 1, 1 }, new[] { 0f, 0f }, 0f, -0.1f },
            { "NaN dt", new[] { 1, 1 }, new[] { 0f, 0f }, 0f, float.NaN },
        };

        [Theory]
        [MemberData(nameof(BadSteps))]
        public void BadStepsThrowAndChangeNothing(string why, int[]? discrete, float[]? continuous, float reward, float dt)
        {
            using var agent = TestAgents.Mixed();
            TestAgents.Run(agent, 50);
            byte[] before = agent.SaveToBytes();

            var e = Assert.Throws<VerveException>(() => agent.Update(reward, discrete, continuous, dt));
            Assert.True(e.Code == ResultCode.InvalidArgument, $"{why}: {e.Code}");
            Assert.Equal(before, agent.SaveToBytes());
            Assert.Equal(50, agent.Stats.Steps);

            // ...and the agent goes on exactly as an untouched twin does.
            using var twin = TestAgents.Mixed();
            TestAgents.Run(twin, 50);
            Assert.Equal(TestAgents.Run(twin, 50, first: 50), TestAgents.Run(agent, 50, first: 50));
        }

        [Fact]
        public void OutOfRangeContinuousValuesAreClampedNotRefused()
        {
            using var agent = TestAgents.Mixed();
            Assert.InRange(agent.Update(0f, new[] { 0, 0 }, new[] { 5f, -7f }, TestAgents.Dt), 0, TestAgents.Actions - 1);
        }

        [Fact]
        public void EndEpisodeAndResetShortTermMemory()
        {
            using var agent = TestAgents.Mixed();
            TestAgents.Run(agent, 20);
            agent.EndEpisode(1f);
            TestAgents.Run(agent, 20, first: 20);
            agent.ResetShortTermMemory();
            TestAgents.Run(agent, 20, first: 40);
            Assert.Equal(60, agent.Stats.Steps);
            Assert.Throws<VerveException>(() => agent.EndEpisode(float.NaN));
        }

        [Fact]
        public void LearningOffFreezesTheValues()
        {
            using var agent = TestAgents.Mixed();
            Assert.True(agent.Learning);
            TestAgents.Run(agent, 100);
            agent.Learning = false;
            Assert.False(agent.Learning);

            int[] probe = { 1, 2 };
            float[] at = { 0.25f, -0.5f };
            var axis = ValueAxis.Continuous(0, 9);
            float[] frozen = agent.SampleValues(axis, probe, at);
            TestAgents.Run(agent, 100, first: 100);
            Assert.Equal(frozen, agent.SampleValues(axis, probe, at));

            agent.Learning = true;
            TestAgents.Run(agent, 100, first: 200);
            Assert.NotEqual(frozen, agent.SampleValues(axis, probe, at));
        }

        [Fact]
        public void ReadOutsReportTheLatestStep()
        {
            using var agent = TestAgents.Mixed();
            TestAgents.Run(agent, 150);
            AgentStats stats = agent.Stats;
            Assert.Equal(150, stats.Steps);
            Assert.Equal(agent.Value, stats.Value);
            Assert.Equal(agent.TdError, stats.TdError);
            Assert.Equal(agent.RbfCount, stats.RbfCount);
            Assert.True(stats.LiveTraces > 0);
            Assert.True(float.IsFinite(stats.Value) && float.IsFinite(stats.TdError));
            Assert.Equal(0, stats.PlanningSteps); // planning is off
            Assert.Contains("steps=150", stats.ToString());
        }

        [Fact]
        public void PlanningAgentReportsModelSignals()
        {
            var options = new AgentOptions { Actions = 3, Planning = true, Curiosity = Curiosity.Novelty, MaxPlanningSteps = 5 }
                .AddDiscreteSensor(5);
            using var agent = new Agent(options);
            int mostPlanned = 0;
            for (int step = 0; step < 100; step++)
            {
                agent.Update(step % 7 == 0 ? 1f : 0f, new[] { step % 5 }, null, TestAgents.Dt);
                mostPlanned = Math.Max(mostPlanned, agent.Stats.PlanningSteps);
            }
            Assert.InRange(mostPlanned, 1, 5);
            AgentStats stats = agent.Stats;
            Assert.True(float.IsFinite(stats.ModelError) && stats.ModelError >= 0f);
            Assert.True(float.IsFinite(stats.PredictedUncertainty));
            Assert.True(float.IsFinite(stats.CuriosityReward));
        }
    }
}
