using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // Truncation, greedy play, action probabilities, action masks and the actor weight bound.
    public class PolicyTests
    {
        private static Agent Cue(float bound = 0f) =>
            new Agent(new AgentOptions { Actions = 3, PolicyMultiplier = 1f, Seed = 5, PolicyWeightBound = bound }
                .AddDiscreteSensor(2));

        private static readonly int[] StateA = { 0 };
        private static readonly int[] StateB = { 1 };

        private static void Teach(Agent agent, int best, int trials)
        {
            for (int t = 0; t < trials; t++)
            {
                int a = agent.Update(0f, StateA, null, 0.1f);
                agent.EndEpisode(a == best ? 1f : -1f);
            }
        }

        [Fact]
        public void ProbabilitiesStartUniformAndFollowWhatWasLearned()
        {
            using var agent = Cue();
            Assert.All(agent.ActionProbabilities, p => Assert.Equal(1f / 3f, p, 5));
            Teach(agent, 1, 300);
            agent.Update(0f, StateA, null, 0.1f);
            float[] p = agent.ActionProbabilities;
            Assert.Equal(3, p.Length);
            Assert.Equal(1f, p.Sum(), 4);
            Assert.True(p[1] > 0.9f, $"p[1] = {p[1]}");
        }

        [Fact]
        public void GreedyPlayIsDeterministic()
        {
            using var agent = Cue();
            Assert.Equal(ActionSelection.Sample, agent.ActionSelection);
            Teach(agent, 2, 200);
            agent.Learning = false;
            agent.ActionSelection = ActionSelection.Greedy;
            Assert.Equal(ActionSelection.Greedy, agent.ActionSelection);
            for (int i = 0; i < 50; i++) Assert.Equal(2, agent.Update(0f, StateA, null, 0.1f));
            Assert.Throws<VerveException>(() => agent.ActionSelection = (ActionSelection)9);
        }

        [Fact]
        public void MaskedActionsAreNeverChosenAndBadMasksAreRefused()
        {
            using var agent = Cue();
            ReadOnlySpan<byte> onlyFirst = stackalloc byte[] { 1, 0, 0 };
            for (int i = 0; i < 100; i++)
            {
                Assert.Equal(0, agent.Update(0f, StateA, default, 0.1f, onlyFirst));
                agent.EndEpisode(1f);
            }
            Assert.Equal(1f, agent.ActionProbabilities[0], 5);
            byte[] before = agent.SaveToBytes();
            Assert.Throws<VerveException>(() => agent.Update(0f, StateA, default, 0.1f, new byte[] { 0, 0, 0 }));
            Assert.Throws<VerveException>(() => agent.Update(0f, StateA, default, 0.1f, new byte[] { 1, 1 }));
            Assert.Throws<VerveException>(() => agent.Update(0f, StateA, default, 0.1f, new byte[] { 2, 1, 1 }));
            Assert.Equal(before, agent.SaveToBytes());
        }

        [Fact]
        public void DemonstratedActionsBecomeThePolicysAndBadOnesAreRefused()
        {
            using var agent = Cue();
            for (int i = 0; i < 10; i++) agent.UpdateDemonstrated(0f, StateA, default, 0.1f, 2);
            agent.Update(0f, StateA, null, 0.1f);
            Assert.True(agent.ActionProbabilities[2] > 0.6f, $"p[2] = {agent.ActionProbabilities[2]}");
            byte[] before = agent.SaveToBytes();
            Assert.Throws<ArgumentOutOfRangeException>(() => agent.UpdateDemonstrated(0f, StateA, default, 0.1f, -1));
            Assert.Throws<VerveException>(() => agent.UpdateDemonstrated(0f, StateA, default, 0.1f, 3));
            Assert.Throws<VerveException>(() => agent.UpdateDemonstrated(0f, StateA, default, 0.1f, 0, new byte[] { 0, 1, 1 }));
            Assert.Equal(before, agent.SaveToBytes());
        }

        [Fact]
        public void PraiseOfARecentAnswerBecomesThePolicysAndBadPraiseIsRefused()
        {
            using var agent = new Agent(new AgentOptions { Actions = 3, PolicyMultiplier = 1f, Seed = 5 }.AddDiscreteSensor(3));
            int[] cue = { 0 }, idle = { 2 };
            agent.Teach(0f);
            for (int t = 0; t < 40; t++)
            {
                int answer = agent.Update(0f, cue, null, 0.1f);
                for (int k = 0; k < 5; k++) agent.Update(0f, idle, null, 0.1f);
                agent.Teach(answer == 1 ? 1f : -1f);
                for (int k = 0; k < 20; k++) agent.Update(0f, idle, null, 0.1f);
            }
            agent.Update(0f, cue, null, 0.1f);
            Assert.True(agent.ActionProbabilities[1] > 0.6f, $"p[1] = {agent.ActionProbabilities[1]}");
            Assert.Throws<VerveException>(() => agent.Teach(1.5f));
            Assert.Throws<VerveException>(() => agent.Teach(float.NaN));
        }

        [Fact]
        public void TruncationBootstrapsFromTheLastState()
        {
            using var agent = Cue();
            agent.Update(0f, StateA, null, 0.1f);
            agent.Update(0f, StateB, null, 0.1f);
            agent.EndEpisode(1f);
            agent.Update(0f, StateB, null, 0.1f);
            float v = agent.Value;
            agent.TruncateEpisode(-0.5f);
            float gamma = MathF.Exp(-0.1f);
            Assert.Equal(-0.5f + gamma * v - v, agent.TdError, 5);
            Assert.Equal(0, agent.Stats.LiveTraces);
            Assert.Throws<VerveException>(() => agent.TruncateEpisode(float.NaN));
        }

        [Fact]
        public void PolicyWeightBoundRoundTripsAndIsValidated()
        {
            using var agent = Cue(bound: 4f);
            Assert.Equal(4f, agent.Options.PolicyWeightBound);
            Assert.Equal(0f, new AgentOptions().PolicyWeightBound);
            var ex = Assert.Throws<VerveException>(() => Cue(bound: -1f));
            Assert.Contains("policy_weight_bound", ex.Message);
        }

        [Fact]
        public void AdaptationIsOnByDefaultRoundTripsAndIsValidated()
        {
            Assert.Equal(Adaptation.All, new AgentOptions().Adaptation);
            var options = new AgentOptions { Actions = 2, Adaptation = Adaptation.None }.AddContinuousSensor(false);
            using (var agent = new Agent(options)) Assert.Equal(Adaptation.None, agent.Options.Adaptation);
            var ex = Assert.Throws<VerveException>(() => new Agent(new AgentOptions { Actions = 2, Adaptation = (Adaptation)128 }));
            Assert.Contains("adaptation", ex.Message);
        }
    }
}
