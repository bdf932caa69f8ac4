using System;
using Xunit;

namespace Verve.Tests
{
    public class AgentOptionsTests
    {
        [Fact]
        public void DefaultsAreTheLibrarys()
        {
            var o = new AgentOptions();
            Assert.Empty(o.DiscreteSensors);
            Assert.Empty(o.ContinuousSensorCircular);
            Assert.Equal(10, o.Resolution);
            Assert.Equal(RbfAllocation.Dynamic, o.RbfAllocation);
            Assert.Equal(0.1f, o.TauValue);
            Assert.Equal(1.0f, o.TauDiscount);
            Assert.Equal(0.1f, o.TauEligibility);
            Assert.Equal(5f, o.PolicyMultiplier);
            Assert.Equal(0.01f, o.TraceThreshold);
            Assert.False(o.Planning);
            Assert.Equal(0f, o.TauModel);
            Assert.Equal(10, o.MaxPlanningSteps);
            Assert.Equal(0.5f, o.PlanningUncertaintyThreshold);
            Assert.Equal(Curiosity.None, o.Curiosity);
            Assert.Equal(5f, o.CuriosityFactor);
            Assert.True(o.PlanningAccumulatesUncertainty);
            Assert.True(o.LearnFromRealSteps);
            Assert.Equal(DiscretePrediction.Categorical, o.DiscretePrediction);
            Assert.Equal(1_000_000L, o.MaxRbfs);
            Assert.True(o.Actions > 0);
        }

        [Fact]
        public void EveryFieldSurvivesTheTripThroughTheLibrary()
        {
            var sent = new AgentOptions
            {
                Actions = 4, Resolution = 7, RbfAllocation = RbfAllocation.Full,
                TauValue = 0.2f, TauDiscount = 1.5f, TauEligibility = 0.3f, PolicyMultiplier = 2.5f,
                TraceThreshold = 0.02f, Seed = 0x1234_5678_9abc_def0UL, Planning = true, TauModel = 0.05f,
                MaxPlanningSteps = 17, PlanningUncertaintyThreshold = 0.25f, Curiosity = Curiosity.Progress,
                CuriosityFactor = 1.5f, MaxRbfs = 5000,
            }.AddDiscreteSensor(5).AddDiscreteSensor(2).AddContinuousSensor(circular: true).AddContinuousSensor();

            using var agent = new Agent(sent);
            AgentOptions got = agent.Options;

            Assert.Equal(new[] { 5, 2 }, got.DiscreteSensors);
            Assert.Equal(new[] { true, false }, got.ContinuousSensorCircular);
            Assert.Equal(4, got.Actions);
            Assert.Equal(7, got.Resolution);
            Assert.Equal(RbfAllocation.Full, got.RbfAllocation);
            Assert.Equal(0.2f, got.TauValue);
            Assert.Equal(1.5f, got.TauDiscount);
            Assert.Equal(0.3f, got.TauEligibility);
            Assert.Equal(2.5f, got.PolicyMultiplier);
            Assert.Equal(0.02f, got.TraceThreshold);
            Assert.Equal(0x1234_5678_9abc_def0UL, got.Seed);
            Assert.True(got.Planning);
            Assert.Equal(0.05f, got.TauModel);
            Assert.Equal(17, got.MaxPlanningSteps);
            Assert.Equal(0.25f, got.PlanningUncertaintyThreshold);
            Assert.Equal(Curiosity.Progress, got.Curiosity);
            Assert.Equal(1.5f, got.CuriosityFactor);
            Assert.Equal(5000L, got.MaxRbfs);
        }

        [Fact]
        public void AgentKeepsItsOwnCopy()
        {
            var options = TestAgents.MixedOptions();
            using var agent = new Agent(options);
            options.Actions = 9;
            options.AddDiscreteSensor(2);
            Assert.Equal(TestAgents.Actions, agent.Options.Actions);
            Assert.Equal(TestAgents.DiscreteValues, agent.Options.DiscreteSensors);
        }

        [Fact]
        public void NegativeCountsAreRefusedAtOnce()
        {
            var o = new AgentOptions();
            Assert.Throws<ArgumentOutOfRangeException>(() => o.Actions = -1);
            Assert.Throws<ArgumentOutOfRangeException>(() => o.Resolution = -1);
            Assert.Throws<ArgumentOutOfRangeException>(() => o.MaxPlanningSteps = -1);
            Assert.Throws<ArgumentOutOfRangeException>(() => o.AddDiscreteSensor(-3));
            Assert.True(o.Actions > 0);
            Assert.Empty(o.DiscreteSensors);
        }

        [Fact]
        public void SensorLimitsAreEnforced()
        {
            var o = new AgentOptions();
            for (int i = 0; i < AgentOptions.MaxDiscreteSensors; i++) o.AddDiscreteSensor(2);
            for (int i = 0; i < AgentOptions.MaxContinuousSensors; i++) o.AddContinuousSensor();
            Assert.Throws<InvalidOperationException>(() => o.AddDiscreteSensor(2));
            Assert.Throws<InvalidOperationException>(() => o.AddContinuousSensor());
            Assert.Equal(AgentOptions.MaxDiscreteSensors, o.DiscreteSensors.Count);
            o.ClearSensors();
            Assert.Empty(o.DiscreteSensors);
            Assert.Empty(o.ContinuousSensorCircular);
        }

        public static TheoryData<string, Action<AgentOptions>> InvalidDescriptions => new TheoryData<string, Action<AgentOptions>>
        {
            { "no actions", o => o.Actions = 0 },
            { "discrete sensor with no values", o => o.AddDiscreteSensor(0) },
            { "zero resolution", o => { o.AddContinuousSensor(); o.Resolution = 0; } },
            { "NaN time constant", o => o.TauValue = float.NaN },
            { "negative time constant", o => o.TauDiscount = -1f },
            { "infinite multiplier", o => o.PolicyMultiplier = float.PositiveInfinity },
            { "unknown allocation", o => o.RbfAllocation = (RbfAllocation)9 },
            { "unknown curiosity", o => o.Curiosity = (Curiosity)9 },
        };

        [Theory]
        [MemberData(nameof(InvalidDescriptions))]
        public void InvalidDescriptionsThrowWithTheNativeMessage(string why, Action<AgentOptions> spoil)
        {
            var options = new AgentOptions { Actions = 2 };
            spoil(options);
            var e = Assert.Throws<VerveException>(() => new Agent(options));
            Assert.True(e.Code == ResultCode.InvalidArgument, why);
            Assert.False(string.IsNullOrWhiteSpace(e.Message));
        }

        [Fact]
        public void NullOptionsAreRefused() =>
            Assert.Throws<ArgumentNullException>(() => new Agent(null!));
    }
}
