using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // Many agents through the real runtime: a batch gives separate agents the updates in order and
    // every agent the same steps on any thread count (a brain's bodies act in phases, docs/crowds.md),
    // bodies of one brain share what they learn, a brain saves (XML and binary) and loads as a brain or
    // an agent, bad input refuses the whole batch.
    public class CrowdTests
    {
        private static (Agent[] agents, Brain brain) Crowd()
        {
            var brain = new Brain(new AgentOptions { Actions = 2, Resolution = 8, Seed = 5 }.AddContinuousSensor().AddContinuousSensor());
            var agents = new[]
            {
                TestAgents.Mixed(1), brain.CreateBody(), TestAgents.Mixed(2), brain.CreateBody(), brain.CreateBody(),
            };
            return (agents, brain);
        }

        // Packed inputs of step `step` for the crowd: mixed agents take 2 discrete + 2 continuous, bodies 2 continuous.
        private static (float[] rewards, int[] discrete, float[] continuous) Inputs(Agent[] agents, int step)
        {
            var rewards = new float[agents.Length];
            var discrete = new System.Collections.Generic.List<int>();
            var continuous = new System.Collections.Generic.List<float>();
            for (int i = 0; i < agents.Length; i++)
            {
                rewards[i] = TestAgents.Reward(step + i);
                if (agents[i].Options.DiscreteSensors.Count > 0) discrete.AddRange(TestAgents.Discrete(step + i));
                continuous.AddRange(TestAgents.Continuous(step + 3 * i));
            }
            return (rewards, discrete.ToArray(), continuous.ToArray());
        }

        [Theory]
        [InlineData(1)]
        [InlineData(2)]
        [InlineData(3)]
        public void BatchGivesSeparateAgentsUpdatesInOrderAndAllAgentsTheSameOnAnyThreadCount(int workers)
        {
            var (solo, soloBrain) = Crowd();
            var (crowd, crowdBrain) = Crowd();
            var (twin, twinBrain) = Crowd();
            int[] separate = { 0, 2 };  // the others are bodies of one brain
            using var batch = new Batch(workers);
            using var one = new Batch(1);
            Assert.Equal(workers, batch.WorkerCount);
            var actions = new int[crowd.Length];
            var twinActions = new int[twin.Length];
            var results = new ResultCode[crowd.Length];
            for (int step = 0; step < 80; step++)
            {
                var (rewards, discrete, continuous) = Inputs(solo, step);
                int d = 0, c = 0;
                var expected = new int[solo.Length];
                for (int i = 0; i < solo.Length; i++)
                {
                    int nd = solo[i].Options.DiscreteSensors.Count;
                    expected[i] = solo[i].Update(rewards[i], discrete.AsSpan(d, nd), continuous.AsSpan(c, 2), TestAgents.Dt);
                    d += nd;
                    c += 2;
                }
                batch.Update(crowd, rewards, discrete, continuous, TestAgents.Dt, actions, results);
                one.Update(twin, rewards, discrete, continuous, TestAgents.Dt, twinActions);
                foreach (int i in separate) Assert.Equal(expected[i], actions[i]);
                Assert.Equal(twinActions, actions);
                Assert.All(results, r => Assert.Equal(ResultCode.Ok, r));
            }
            foreach (int i in separate) Assert.Equal(solo[i].SaveToBytes(), crowd[i].SaveToBytes());
            for (int i = 0; i < twin.Length; i++) Assert.Equal(twin[i].SaveToBytes(), crowd[i].SaveToBytes());
            foreach (var a in solo.Concat(crowd).Concat(twin)) a.Dispose();
            soloBrain.Dispose();
            crowdBrain.Dispose();
            twinBrain.Dispose();
        }

        [Fact]
        public void DemonstratedStepsInABatchEqualSingleCallsInOrder()
        {
            var (solo, soloBrain) = Crowd();
            var (crowd, crowdBrain) = Crowd();
            using var batch = new Batch(2);
            var actions = new int[crowd.Length];
            for (int step = 0; step < 40; step++)
            {
                var (rewards, discrete, continuous) = Inputs(solo, step);
                int[] shown = { Batch.AgentChooses, step % 2, Batch.AgentChooses, 1, Batch.AgentChooses };
                int d = 0, c = 0;
                var expected = new int[solo.Length];
                for (int i = 0; i < solo.Length; i++)
                {
                    int nd = solo[i].Options.DiscreteSensors.Count;
                    if (shown[i] == Batch.AgentChooses)
                    {
                        expected[i] = solo[i].Update(rewards[i], discrete.AsSpan(d, nd), continuous.AsSpan(c, 2), TestAgents.Dt);
                    }
                    else
                    {
                        solo[i].UpdateDemonstrated(rewards[i], discrete.AsSpan(d, nd), continuous.AsSpan(c, 2), TestAgents.Dt, shown[i]);
                        expected[i] = shown[i];
                    }
                    d += nd;
                    c += 2;
                }
                batch.UpdateDemonstrated(crowd, rewards, discrete, continuous, TestAgents.Dt, shown, actions);
                Assert.Equal(expected, actions);
            }
            for (int i = 0; i < solo.Length; i++) Assert.Equal(solo[i].SaveToBytes(), crowd[i].SaveToBytes());
            var (r0, d0, c0) = Inputs(crowd, 0);
            Assert.Throws<VerveException>(() => batch.UpdateDemonstrated(crowd, r0, d0, c0, TestAgents.Dt,
                new[] { 7, Batch.AgentChooses, Batch.AgentChooses, Batch.AgentChooses, Batch.AgentChooses }, actions));
            Assert.Throws<ArgumentException>(() => batch.UpdateDemonstrated(crowd, r0, d0, c0, TestAgents.Dt, new[] { 0 }, actions));
            foreach (var a in solo.Concat(crowd)) a.Dispose();
            soloBrain.Dispose();
            crowdBrain.Dispose();
        }

        [Fact]
        public void BadInputRefusesTheWholeBatch()
        {
            var (crowd, brain) = Crowd();
            using var batch = new Batch(2);
            var (rewards, discrete, continuous) = Inputs(crowd, 0);
            var before = crowd.Select(a => a.SaveToBytes()).ToArray();
            continuous[2] = float.NaN; // agent 1's first sensor (agent 0 has 2)
            var actions = new int[crowd.Length];
            var results = new ResultCode[crowd.Length];
            var e = Assert.Throws<VerveException>(() => batch.Update(crowd, rewards, discrete, continuous, TestAgents.Dt, actions, results));
            Assert.Equal(ResultCode.InvalidArgument, e.Code);
            Assert.Contains("agents[1]", e.Message);
            Assert.Equal(new[] { ResultCode.Ok, ResultCode.InvalidArgument, ResultCode.Ok, ResultCode.Ok, ResultCode.Ok }, results);
            Assert.All(actions, a => Assert.Equal(0, a));
            for (int i = 0; i < crowd.Length; i++) Assert.Equal(before[i], crowd[i].SaveToBytes());
            Assert.Throws<ArgumentException>(() => batch.Update(crowd, rewards.AsSpan(1), discrete, continuous, TestAgents.Dt, actions));
            Assert.Throws<VerveException>(() => batch.Update(crowd, rewards, discrete.AsSpan(1), continuous, TestAgents.Dt, actions));
            Assert.Throws<ArgumentOutOfRangeException>(() => new Batch(-1));
            crowd[3].Dispose();
            Assert.Throws<ObjectDisposedException>(() => batch.Update(crowd, rewards, discrete, continuous, TestAgents.Dt, actions));
            batch.Dispose();
            Assert.Throws<ObjectDisposedException>(() => batch.WorkerCount);
            foreach (var a in crowd) a.Dispose();
            brain.Dispose();
        }

        [Fact]
        public void BodiesShareWhatTheyLearnAndTheBrainSaves()
        {
            using var brain = new Brain(new AgentOptions { Actions = 2, Seed = 3 }.AddContinuousSensor());
            using var teacher = brain.CreateBody();
            using var pupil = brain.CreateBody();
            var here = new[] { 0.5f };
            for (int t = 0; t < 300; t++) teacher.Update(1f, null, here, TestAgents.Dt);
            pupil.Learning = false;
            pupil.Update(0f, null, here, TestAgents.Dt);
            Assert.True(pupil.Value > 1f, $"the pupil's value {pupil.Value}");
            Assert.Equal(brain.RbfCount, pupil.RbfCount);

            byte[] saved = brain.SaveToBytes();
            using var copy = Brain.LoadFromBytes(saved);
            Assert.Equal(brain.RbfCount, copy.RbfCount);
            Assert.Equal(saved, copy.SaveToBytes());
            using var asAgent = Agent.LoadFromBytes(saved);
            asAgent.Update(0f, null, here, TestAgents.Dt);
            Assert.Equal(pupil.Value, asAgent.Value, 5);
            string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), $"verve-brain-{Guid.NewGuid():N}.xml");
            brain.Save(path);
            using (var fromFile = Brain.Load(path)) Assert.Equal(brain.RbfCount, fromFile.RbfCount);
            System.IO.File.Delete(path);
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Brain.LoadFromBytes(saved.AsSpan(0, 50))).Code);
            Assert.Throws<VerveException>(() => new Brain(new AgentOptions { Actions = 0 }));
        }

        [Fact]
        public void BrainBinarySavesLoadAsBrainsAndAsAgentsAndAgentSavesAsBrains()
        {
            using var brain = new Brain(new AgentOptions { Actions = 2, Seed = 4 }.AddDiscreteSensor(3).AddContinuousSensor());
            using var first = brain.CreateBody();
            using var second = brain.CreateBody();
            for (int t = 0; t < 200; t++)
                (t % 2 == 0 ? first : second).Update(t % 5 == 0 ? 1f : 0f, new[] { t % 3 }, new[] { (float)Math.Sin(t) }, TestAgents.Dt);

            byte[] bytes = brain.SaveToBinaryBytes();
            Assert.Equal("VERVEBIN", System.Text.Encoding.ASCII.GetString(bytes, 0, 8));
            Assert.True(bytes.Length < brain.SaveToBytes().Length, "the binary save is smaller than the XML");
            using (var copy = Brain.LoadFromBytes(bytes))
            {
                Assert.Equal(bytes, copy.SaveToBinaryBytes());
                Assert.Equal(brain.SaveToBytes(), copy.SaveToBytes());
            }
            using (var asAgent = Agent.LoadFromBytes(bytes))
            using (var back = Brain.LoadFromBytes(asAgent.SaveToBinaryBytes()))
                Assert.Equal(bytes, back.SaveToBinaryBytes());
            using (var fromBody = Brain.LoadFromBytes(first.SaveToBinaryBytes()))
                Assert.Equal(bytes, fromBody.SaveToBinaryBytes());

            string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), $"verve-brain-{Guid.NewGuid():N}.bin");
            brain.SaveBinary(path);
            Assert.Equal(bytes, System.IO.File.ReadAllBytes(path));
            using (var fromFile = Brain.Load(path)) Assert.Equal(bytes, fromFile.SaveToBinaryBytes());
            using (var agentFromFile = Agent.Load(path)) Assert.Equal(brain.RbfCount, agentFromFile.RbfCount);
            System.IO.File.Delete(path);

            byte[] damaged = (byte[])bytes.Clone();
            damaged[damaged.Length / 2] ^= 1;
            var e = Assert.Throws<VerveException>(() => Brain.LoadFromBytes(damaged));
            Assert.Equal(ResultCode.Format, e.Code);
            Assert.Contains("checksum", e.Message);
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Brain.LoadFromBytes(bytes.AsSpan(0, 40))).Code);
            Assert.Equal(ResultCode.Io, Assert.Throws<VerveException>(() => brain.SaveBinary("/nonexistent/dir/brain.bin")).Code);
        }

        [Fact]
        public void EverySaveOfADisposedBrainThrows()
        {
            var brain = new Brain(new AgentOptions { Actions = 2 }.AddContinuousSensor());
            brain.Dispose();
            foreach (Action call in new Action[] { () => brain.Save("never-written.xml"), () => brain.SaveBinary("never-written.xml"),
                                                   () => brain.SaveToBytes(), () => brain.SaveToBinaryBytes() })
                Assert.Equal(nameof(Brain), Assert.Throws<ObjectDisposedException>(call).ObjectName);
            Assert.False(System.IO.File.Exists("never-written.xml"));
        }
    }
}
