using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // What the docs promise C# shows: AgentStats.ClampedRewards and RbfBudgetHits, and libverve's log
    // warnings through VerveLibrary.TakeWarnings(). Other tests may warn too, so these look for their
    // own messages (a reward and a budget no other test uses) rather than count all of them.
    public class WarningTests
    {
        [Fact]
        public void AClampedRewardIsCountedAndWarnedOncePerAgent()
        {
            VerveLibrary.TakeWarnings();
            using var agent = new Agent(new AgentOptions { Actions = 2 }.AddDiscreteSensor(3));
            agent.Update(0f, new[] { 0 }, null, 0.1f);
            agent.Update(7.25f, new[] { 1 }, null, 0.1f);
            agent.Update(-9f, new[] { 2 }, null, 0.1f);
            Assert.Equal(2, agent.Stats.ClampedRewards);
            Assert.Equal(0, agent.Stats.RbfBudgetHits);
            string[] warnings = VerveLibrary.TakeWarnings();
            Assert.Single(warnings, w => w.Contains("a reward of 7.25 was clamped to [-1, 1]"));
            Assert.DoesNotContain(warnings, w => w.Contains("a reward of -9 was clamped"));
            Assert.DoesNotContain(VerveLibrary.TakeWarnings(), w => w.Contains("7.25"));
        }

        [Fact]
        public void TheRbfBudgetReachedIsCountedAndWarnedOncePerAgent()
        {
            VerveLibrary.TakeWarnings();
            using var agent = new Agent(new AgentOptions { Actions = 2, MaxRbfs = 3 }.AddContinuousSensor());
            for (int i = 0; i <= 20; ++i) agent.Update(0f, null, new[] { -1f + 0.1f * i }, 0.1f);
            Assert.True(agent.Stats.RbfCount <= 3, agent.Stats.ToString());
            Assert.True(agent.Stats.RbfBudgetHits > 0, agent.Stats.ToString());
            Assert.Equal(0, agent.Stats.ClampedRewards);
            Assert.Single(VerveLibrary.TakeWarnings(), w => w.Contains("the RBF budget (max_rbfs = 3) is reached"));
        }

        [Fact]
        public void WarningsBeyondTheQueueAreCounted()
        {
            VerveLibrary.TakeWarnings();
            var agents = Enumerable.Range(0, 70).Select(_ => new Agent(new AgentOptions { Actions = 2 }.AddDiscreteSensor(2))).ToList();
            foreach (Agent a in agents) a.Update(3f, new[] { 0 }, null, 0.1f);
            string[] warnings = VerveLibrary.TakeWarnings();
            Assert.Equal(65, warnings.Length);
            Assert.Equal("6 more warnings were dropped (at most 64 are kept between reads)", warnings[^1]);
            foreach (Agent a in agents) a.Dispose();
        }
    }
}
