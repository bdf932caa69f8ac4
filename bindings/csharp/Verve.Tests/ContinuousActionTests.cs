using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // Continuous actions (AgentOptions.ContinuousActions, Agent.ContinuousAction / GetContinuousAction):
    // values in [-1, 1] chosen beside the discrete action on every step, the policy's mean when greedy or
    // demonstrated; saves keep them and their noise; refusals change nothing; and they learn.
    public class ContinuousActionTests
    {
        private const float Dt = 0.1f;

        // An agent that only steers: Actions 0 means the one trivial discrete action.
        private static AgentOptions Steering(ulong seed = 9) =>
            new AgentOptions { Actions = 0, ContinuousActions = 2, Seed = seed }.AddContinuousSensor().AddContinuousSensor();

        private static float[] Readings(int step) => new[] { MathF.Sin(step * 0.37f), MathF.Cos(step * 0.21f) * 0.9f };

        private static float Reward(int step) => step % 7 == 0 ? 1f : 0f;

        [Fact]
        public void AnAgentThatOnlySteersKeepsOneDiscreteAction()
        {
            Assert.Equal(0, new AgentOptions().ContinuousActions);
            using var agent = new Agent(Steering());
            Assert.Equal(1, agent.Options.Actions);
            Assert.Equal(2, agent.Options.ContinuousActions);
            Assert.Equal(new[] { 0f, 0f }, agent.ContinuousAction); // before any update
            Assert.Single(agent.ActionProbabilities);

            Span<float> values = stackalloc float[2];
            float lowest = 1f, highest = -1f;
            for (int step = 0; step < 300; step++)
            {
                Assert.Equal(0, agent.Update(Reward(step), default, Readings(step), Dt));
                agent.GetContinuousAction(values);
                Assert.Equal(agent.ContinuousAction, values.ToArray());
                foreach (float v in values)
                {
                    Assert.InRange(v, -1f, 1f);
                    lowest = Math.Min(lowest, v);
                    highest = Math.Max(highest, v);
                }
            }
            Assert.True(highest - lowest > 0.2f, $"sampled values hardly vary: [{lowest}, {highest}]");

            // With discrete actions too, Actions keeps its meaning.
            using var both = new Agent(new AgentOptions { Actions = 3, ContinuousActions = 1 }.AddContinuousSensor());
            Assert.Equal(3, both.Options.Actions);
            Assert.InRange(both.Update(0f, null, new[] { 0.5f }, Dt), 0, 2);
            Assert.InRange(both.ContinuousAction.Single(), -1f, 1f);
        }

        [Fact]
        public void AnAgentWithoutContinuousActionsHasNone()
        {
            using var agent = new Agent(new AgentOptions { Actions = 2 }.AddContinuousSensor());
            agent.Update(0f, null, new[] { 0.1f }, Dt);
            Assert.Empty(agent.ContinuousAction);
            agent.GetContinuousAction(Span<float>.Empty);
            Assert.Equal(ResultCode.InvalidArgument,
                Assert.Throws<VerveException>(() => agent.GetContinuousAction(new float[1])).Code);
        }

        [Fact]
        public void GreedyPlaysTheSameMeanForTheSameObservation()
        {
            using var agent = new Agent(Steering());
            for (int step = 0; step < 300; step++) agent.Update(Reward(step), default, Readings(step), Dt);
            agent.ActionSelection = ActionSelection.Greedy;
            agent.Learning = false; // the mean moves only when the weights do
            float[] observation = { 0.3f, -0.4f };
            agent.Update(0f, default, observation, Dt);
            float[] first = agent.ContinuousAction;
            agent.Update(0f, default, new[] { -0.8f, 0.7f }, Dt);
            agent.Update(0f, default, observation, Dt);
            Assert.Equal(first, agent.ContinuousAction);
            Assert.All(first, v => Assert.InRange(v, -1f, 1f));

            // A demonstration names the discrete action only: its continuous actions are the mean too.
            using var shown = Agent.LoadFromBytes(agent.SaveToBinaryBytes());
            shown.Learning = false;
            shown.UpdateDemonstrated(0f, default, observation, Dt, 0);
            Assert.Equal(first, shown.ContinuousAction);
        }

        [Fact]
        public void RefusalsChangeNothing()
        {
            var options = Steering();
            Assert.Throws<ArgumentOutOfRangeException>(() => options.ContinuousActions = AgentOptions.MaxContinuousActions + 1);
            Assert.Throws<ArgumentOutOfRangeException>(() => options.ContinuousActions = -1);
            Assert.Equal(2, options.ContinuousActions);
            options.ContinuousActions = AgentOptions.MaxContinuousActions;
            using (var most = new Agent(options)) Assert.Equal(8, most.ContinuousAction.Length);

            options.ContinuousActions = 2;
            options.Planning = true;
            var e = Assert.Throws<VerveException>(() => new Agent(options));
            Assert.Equal(ResultCode.InvalidArgument, e.Code);
            Assert.Contains("num_continuous_actions", e.Message);

            using var agent = new Agent(Steering());
            agent.Update(0f, default, Readings(0), Dt);
            float[] before = agent.ContinuousAction;
            e = Assert.Throws<VerveException>(() => agent.GetContinuousAction(new float[3]));
            Assert.Contains("2 continuous actions", e.Message);
            Assert.Throws<VerveException>(() => agent.GetContinuousAction(new float[1]));
            Assert.Throws<VerveException>(() => agent.GetContinuousAction(Span<float>.Empty));
            Assert.Equal(before, agent.ContinuousAction);
        }

        [Theory]
        [InlineData(false)]
        [InlineData(true)]
        public void ALoadedAgentSteersAsTheSavedOneWould(bool binary)
        {
            using var agent = new Agent(Steering());
            for (int step = 0; step < 200; step++) agent.Update(Reward(step), default, Readings(step), Dt);
            using var copy = Agent.LoadFromBytes(binary ? agent.SaveToBinaryBytes() : agent.SaveToBytes());
            Assert.Equal(2, copy.Options.ContinuousActions);
            Assert.Equal(agent.ContinuousAction, copy.ContinuousAction);
            for (int step = 200; step < 260; step++)
            {
                Assert.Equal(agent.Update(Reward(step), default, Readings(step), Dt), copy.Update(Reward(step), default, Readings(step), Dt));
                Assert.Equal(agent.ContinuousAction, copy.ContinuousAction); // bit for bit: the noise is saved too
            }
        }

        [Fact]
        public void ABatchUpdateActsAsSeparateUpdates()
        {
            Agent[] batched = { new Agent(Steering(1)), new Agent(Steering(2)) };
            Agent[] alone = { new Agent(Steering(1)), new Agent(Steering(2)) };
            using var batch = new Batch(2);
            var actions = new int[2];
            Span<float> mine = stackalloc float[2];
            Span<float> twin = stackalloc float[2];
            for (int step = 0; step < 100; step++)
            {
                float[] sensors = Readings(step).Concat(Readings(step + 50)).ToArray();
                batch.Update(batched, new[] { Reward(step), Reward(step + 3) }, default, sensors, Dt, actions);
                alone[0].Update(Reward(step), default, Readings(step), Dt);
                alone[1].Update(Reward(step + 3), default, Readings(step + 50), Dt);
                for (int i = 0; i < 2; i++)
                {
                    batched[i].GetContinuousAction(mine);
                    alone[i].GetContinuousAction(twin);
                    Assert.True(mine.SequenceEqual(twin), $"agent {i}, step {step}");
                }
            }
            foreach (Agent a in batched.Concat(alone)) a.Dispose();
        }

        [Fact]
        public void ABatchShowsAgentsTheirContinuousActionsAsSeparateDemonstratedUpdates()
        {
            Agent[] batched = { new Agent(Steering(1)), new Agent(Steering(2)) };
            Agent[] alone = { new Agent(Steering(1)), new Agent(Steering(2)) };
            using var batch = new Batch(2);
            var actions = new int[2];
            Span<float> played = stackalloc float[2];
            for (int step = 0; step < 60; step++)
            {
                float[] sensors = Readings(step).Concat(Readings(step + 50)).ToArray();
                // Agent 0 is shown values every other step, agent 1 chooses (its two values unread).
                int[] shown = { step % 2 == 0 ? 0 : Batch.AgentChooses, Batch.AgentChooses };
                float[] values = { 0.5f, -0.25f * (step % 4), 9f, 9f };
                var rewards = new[] { Reward(step), Reward(step + 3) };
                batch.UpdateDemonstratedContinuous(batched, rewards, default, sensors, Dt, shown, values, actions);
                if (shown[0] == 0)
                {
                    alone[0].UpdateDemonstratedContinuous(rewards[0], default, Readings(step), Dt, 0, values.AsSpan(0, 2));
                    batched[0].GetContinuousAction(played);
                    Assert.Equal(values.Take(2), played.ToArray());
                }
                else
                {
                    alone[0].Update(rewards[0], default, Readings(step), Dt);
                }
                alone[1].Update(rewards[1], default, Readings(step + 50), Dt);
            }
            for (int i = 0; i < 2; i++) Assert.Equal(alone[i].SaveToBytes(), batched[i].SaveToBytes());
            var before = batched[0].SaveToBytes();
            float[] sensors0 = Readings(0).Concat(Readings(50)).ToArray();
            var e = Assert.Throws<VerveException>(() => batch.UpdateDemonstratedContinuous(batched, new[] { 0f, 0f },
                default, sensors0, Dt, new[] { 0, Batch.AgentChooses }, new[] { 1.5f, 0f, 0f, 0f }, actions));
            Assert.Contains("agents[0]", e.Message);
            Assert.Throws<VerveException>(() => batch.UpdateDemonstratedContinuous(batched, new[] { 0f, 0f },
                default, sensors0, Dt, new[] { 0, Batch.AgentChooses }, default, actions));
            Assert.Equal(before, batched[0].SaveToBytes());
            foreach (Agent a in batched.Concat(alone)) a.Dispose();
        }

        // A 1-D reach: x in [-1, 1] moves at 2 * a per second (a the continuous action), the reward is -|x|,
        // trials of 100 steps from a random x, cut off by a time limit. Returns the greedy action at -0.6, +0.6.
        private static (float left, float right) LearnToReach(ulong seed, int trials)
        {
            const float dt = 0.05f;
            using var agent = new Agent(new AgentOptions { Actions = 0, ContinuousActions = 1, Seed = seed }.AddContinuousSensor());
            var task = new Random((int)seed);
            var x = new float[1];
            Span<float> a = stackalloc float[1];
            for (int trial = 0; trial < trials; trial++)
            {
                x[0] = (float)(task.NextDouble() * 2 - 1);
                float reward = 0f;
                for (int step = 0; step < 100; step++)
                {
                    agent.Update(reward, default, x, dt);
                    agent.GetContinuousAction(a);
                    x[0] = Math.Clamp(x[0] + 2f * dt * a[0], -1f, 1f);
                    reward = -Math.Abs(x[0]);
                }
                agent.TruncateEpisode(reward);
            }
            agent.ActionSelection = ActionSelection.Greedy;
            agent.Learning = false;
            agent.Update(0f, default, new[] { -0.6f }, dt);
            float left = agent.ContinuousAction[0];
            agent.Update(0f, default, new[] { 0.6f }, dt);
            return (left, agent.ContinuousAction[0]);
        }

        [Fact]
        public void LearnsToSteerTowardsTheMiddle()
        {
            // Measured for seed 1: 0.998 and -1.000 (seeds 1 to 12: at least 0.63 and at most -0.94).
            (float left, float right) = LearnToReach(seed: 1, trials: 400);
            Assert.True(left > 0.3f && right < -0.3f, $"greedy action at x = -0.6: {left} (want > 0.3), at +0.6: {right} (want < -0.3)");
            (float untrainedLeft, float untrainedRight) = LearnToReach(seed: 1, trials: 0);
            Assert.InRange(untrainedLeft, -0.3f, 0.3f); // the bar is not met by a policy that learned nothing
            Assert.InRange(untrainedRight, -0.3f, 0.3f);
        }

        // docs/csharp.md, "Continuous actions", as written there.
        [Fact]
        public void TheDocsSteeringNpc()
        {
            float reward = 0f, dt = 0.1f;
            float[] readings = { 0.2f, -0.5f };
            var options = new AgentOptions { Actions = 0, ContinuousActions = 2 }   // steering, throttle
                .AddContinuousSensor().AddContinuousSensor();
            using var car = new Agent(options);                 // car.Options.Actions == 1
            float[] controls = new float[2];                     // kept, not allocated per step
            car.Update(reward, default, readings, dt);
            car.GetContinuousAction(controls);                   // each in [-1, 1]
            float steeringAngle = controls[0] * 30f;             // degrees
            float throttle = (controls[1] + 1f) / 2f;            // 0 .. 1

            Assert.InRange(steeringAngle, -30f, 30f);
            Assert.InRange(throttle, 0f, 1f);
            Assert.Equal(1, car.Options.Actions);
        }

        // A teacher's continuous actions (docs/teaching.md): the reach (x moves by 0.1 a, every step costs |x|)
        // shown for 10 episodes by a driver steering back to 0 points the greedy action back; the same steps
        // recorded and replayed train an agent to the same bytes; bad values are refused and change nothing.
        [Fact]
        public void DemonstratedContinuousActionsTeachTheReachAndRecord()
        {
            var options = new AgentOptions { Actions = 0, ContinuousActions = 1, Seed = 1 }.AddContinuousSensor();
            using var shown = new Agent(options);
            using var replayed = new Agent(options);
            using var recording = new Recording(shown);
            uint state = 12345;
            float Uniform() { state = state * 1664525u + 1013904223u; return (state >> 8) / 16777216f * 2f - 1f; }
            var value = new float[1];
            for (int episode = 0; episode < 10; episode++)
            {
                float x = Uniform(), reward = 0f;
                for (int t = 0; t < 100; t++)
                {
                    value[0] = Math.Clamp(-10f * x, -1f, 1f);
                    shown.UpdateDemonstratedContinuous(reward, default, new[] { x }, 0.05f, 0, value);
                    recording.AddStepContinuous(reward, default, new[] { x }, 0.05f, 0, value);
                    Assert.Equal(value, shown.ContinuousAction);
                    x = Math.Clamp(x + 0.1f * value[0], -1f, 1f);
                    reward = -Math.Abs(x);
                }
                shown.TruncateEpisode(reward);
                recording.AddTruncation(reward);
            }
            using (var loaded = Recording.LoadFromBytes(recording.SaveToBytes())) replayed.Replay(loaded);
            Assert.Equal(shown.SaveToBinaryBytes(), replayed.SaveToBinaryBytes());

            byte[] before = replayed.SaveToBinaryBytes();
            foreach (float[] bad in new[] { new[] { 1.5f }, new[] { float.NaN }, new[] { 0.1f, 0.2f }, Array.Empty<float>() })
            {
                Assert.Throws<VerveException>(() => replayed.UpdateDemonstratedContinuous(0f, default, new[] { 0f }, 0.05f, 0, bad));
                Assert.Throws<VerveException>(() => recording.AddStepContinuous(0f, default, new[] { 0f }, 0.05f, 0, bad));
            }
            Assert.Equal(before, replayed.SaveToBinaryBytes());

            shown.Learning = false;
            shown.ActionSelection = ActionSelection.Greedy;
            float GreedyAt(float x)
            {
                shown.ResetShortTermMemory();
                shown.Update(0f, default, new[] { x }, 0.05f);
                return shown.ContinuousAction[0];
            }
            Assert.True(GreedyAt(-0.6f) > 0.5f && GreedyAt(0.6f) < -0.5f, $"greedy {GreedyAt(-0.6f)} at -0.6, {GreedyAt(0.6f)} at 0.6");
        }
    }
}
