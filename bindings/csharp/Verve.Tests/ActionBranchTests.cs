using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // Action branches (AgentOptions.SetActionBranches, Agent.SplitAction/JoinAction): several choices per
    // step, one combined action (from 0, branch 0 fastest). Masks and ActionProbabilities hold one entry
    // per choice of each branch, branch after branch; saves keep the branches; refusals change nothing.
    public class ActionBranchTests
    {
        private static AgentOptions Npc() =>
            new AgentOptions { Seed = 5 }.AddContinuousSensor().AddContinuousSensor().SetActionBranches(3, 2);

        private static float[] Readings(int step) => new[] { MathF.Sin(step * 0.37f), MathF.Cos(step * 0.21f) * 0.9f };

        [Fact]
        public void OneActionSetIsTheDefault()
        {
            Assert.Empty(new AgentOptions().ActionBranches);
            using var plain = new Agent(new AgentOptions { Actions = 4 });
            Assert.Equal(new[] { 3 }, plain.SplitAction(3));
            Assert.Equal(3, plain.JoinAction(3));
            Assert.Equal(4, plain.ActionProbabilities.Length);
        }

        [Fact]
        public void BranchesSetActionsToTheirProductAndComeBack()
        {
            var options = Npc();
            Assert.Equal(6, options.Actions);
            using var agent = new Agent(options);
            Assert.Equal(6, agent.Options.Actions);
            Assert.Equal(new[] { 3, 2 }, agent.Options.ActionBranches);
            using var twin = new Agent(agent.Options);
            Assert.Equal(new[] { 3, 2 }, twin.Options.ActionBranches);
            options.ClearActionBranches();
            Assert.Empty(options.ActionBranches);
            Assert.Equal(6, options.Actions);
        }

        [Fact]
        public void APerBranchMaskHoldsEveryStepAndEachBranchSumsToOne()
        {
            using var agent = new Agent(Npc());
            byte[] mask = { 1, 0, 1, 0, 1 }; // branch 0: choices 0 and 2; branch 1: choice 1 only
            for (int step = 0; step < 200; step++)
            {
                int a = agent.Update(step % 5 == 0 ? 1f : 0f, default, Readings(step), 0.1f, mask);
                int[] c = agent.SplitAction(a);
                Assert.True((c[0] == 0 || c[0] == 2) && c[1] == 1, $"action {a} is [{c[0]}, {c[1]}]");
            }
            float[] p = agent.ActionProbabilities;
            Assert.Equal(5, p.Length);
            Assert.Equal(1f, p[0] + p[1] + p[2], 5);
            Assert.Equal(1f, p[3] + p[4], 5);
            Assert.Equal(0f, p[1]);
            Assert.Equal(0f, p[3]);
        }

        [Fact]
        public void SplitAndJoinRoundTripBranchZeroFastest()
        {
            using var agent = new Agent(Npc());
            for (int a = 0; a < 6; a++) Assert.Equal(a, agent.JoinAction(agent.SplitAction(a)));
            Assert.Equal(new[] { 1, 0 }, agent.SplitAction(1));
            Assert.Equal(new[] { 0, 1 }, agent.SplitAction(3));
            Assert.Equal(5, agent.JoinAction(2, 1));
            // a demonstrated action is a combined one, within the mask
            agent.UpdateDemonstrated(0f, default, Readings(0), 0.1f, agent.JoinAction(2, 1), new byte[] { 1, 0, 1, 0, 1 });
        }

        [Theory]
        [InlineData(false)]
        [InlineData(true)]
        public void SavesKeepTheBranches(bool binary)
        {
            using var agent = new Agent(Npc());
            for (int step = 0; step < 100; step++) agent.Update(step % 7 == 0 ? 1f : 0f, null, Readings(step), 0.1f);
            using var copy = Agent.LoadFromBytes(binary ? agent.SaveToBinaryBytes() : agent.SaveToBytes());
            Assert.Equal(new[] { 3, 2 }, copy.Options.ActionBranches);
            Assert.Equal(5, copy.ActionProbabilities.Length);
            for (int step = 100; step < 140; step++)
                Assert.Equal(agent.Update(0f, null, Readings(step), 0.1f), copy.Update(0f, null, Readings(step), 0.1f));
        }

        [Fact]
        public void ABrainsBodiesTakeBranchesToo()
        {
            using var brain = new Brain(Npc());
            using var body = brain.CreateBody();
            int a = body.Update(0f, default, Readings(0), 0.1f, new byte[] { 0, 1, 0, 1, 1 });
            Assert.Equal(1, body.SplitAction(a)[0]);
        }

        // docs/csharp.md, "Action branches", as written there.
        [Fact]
        public void TheDocsBranchedNpc()
        {
            float reward = 0f, dt = 0.1f;
            float[] readings = { 0.2f, -0.5f };
            // move: 0 left, 1 stay, 2 right; turn: 0 left, 1 none, 2 right; use: 0 no, 1 yes
            var options = new AgentOptions().AddContinuousSensor().AddContinuousSensor().SetActionBranches(3, 3, 2);
            using var npc = new Agent(options);                 // options.Actions == 18
            byte[] allowed = { 1, 1, 1,  1, 1, 1,  1, 0 };     // "use" is not ready yet
            int action = npc.Update(reward, default, readings, dt, allowed);
            int[] choice = npc.SplitAction(action);           // { move, turn, use }

            Assert.Equal(0, choice[2]);
            Assert.InRange(choice[0], 0, 2);
            Assert.InRange(choice[1], 0, 2);
            Assert.Equal(action, npc.JoinAction(choice));
            Assert.Equal(3 + 3 + 2, npc.ActionProbabilities.Length);
        }

        [Fact]
        public void RefusalsChangeNothing()
        {
            var options = Npc();
            Assert.Throws<ArgumentOutOfRangeException>(() => options.SetActionBranches(3, 0));
            Assert.Throws<ArgumentException>(() => options.SetActionBranches());
            Assert.Throws<ArgumentException>(() => options.SetActionBranches(2, 2, 2, 2, 2, 2, 2, 2, 2));
            Assert.Equal(new[] { 3, 2 }, options.ActionBranches); // refused calls kept the branches

            options.Actions = 5; // not the product
            var e = Assert.Throws<VerveException>(() => new Agent(options));
            Assert.Equal(ResultCode.InvalidArgument, e.Code);
            Assert.Contains("product", e.Message);
            options.Actions = 6;
            options.Planning = true;
            Assert.Throws<VerveException>(() => new Agent(options));

            using var agent = new Agent(Npc());
            agent.Update(0f, null, Readings(0), 0.1f);
            byte[] before = agent.SaveToBinaryBytes();
            // one flag per combined action instead of one per choice of each branch
            Assert.Throws<VerveException>(() => agent.Update(0f, default, Readings(1), 0.1f, new byte[] { 1, 1, 1, 1, 1, 1 }));
            // branch 1 allows nothing
            Assert.Throws<VerveException>(() => agent.Update(0f, default, Readings(1), 0.1f, new byte[] { 1, 1, 1, 0, 0 }));
            Assert.Throws<VerveException>(() => agent.SplitAction(6));
            Assert.Throws<ArgumentOutOfRangeException>(() => agent.SplitAction(-1));
            Assert.Contains("out of range", Assert.Throws<VerveException>(() => agent.JoinAction(3, 0)).Message);
            Assert.Throws<VerveException>(() => agent.JoinAction(1, 1, 1));
            Assert.Throws<ArgumentOutOfRangeException>(() => agent.JoinAction(1, -1));
            Assert.Throws<ArgumentException>(() => agent.JoinAction());
            Assert.True(before.SequenceEqual(agent.SaveToBinaryBytes()), "a refused call changed the agent");
        }
    }
}
