using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // Sensor groups (AgentOptions.Grouping, AddSensorGroup): what reaches the library, what comes back,
    // saves, and the refusals. Full allocation makes the lattices' sizes visible: resolution^(sensors in
    // the group) RBFs per group, created with the agent.
    public class SensorGroupTests
    {
        private static AgentOptions Npc(int continuousSensors, ulong seed = 3)
        {
            var o = new AgentOptions { Actions = 4, Seed = seed };
            for (int i = 0; i < continuousSensors; i++) o.AddContinuousSensor();
            return o;
        }

        private static float[] Readings(int step, int n)
        {
            var r = new float[n];
            for (int i = 0; i < n; i++) r[i] = MathF.Sin(step * (0.31f + 0.17f * i) + i);
            return r;
        }

        [Fact]
        public void AutoIsTheDefaultWithNoGroups()
        {
            var o = new AgentOptions();
            Assert.Equal(SensorGrouping.Auto, o.Grouping);
            Assert.Empty(o.SensorGroups);
        }

        [Fact]
        public void AutoGivesTwelveSensorsALatticePerSensorAndPerNeighbouringPair()
        {
            var options = Npc(12);
            options.Resolution = 10;
            options.RbfAllocation = RbfAllocation.Full;
            using var agent = new Agent(options);
            Assert.Equal(12 * 10 + 11 * 10 * 10, agent.RbfCount);
            Assert.Equal(SensorGrouping.Auto, agent.Options.Grouping);
            Assert.Empty(agent.Options.SensorGroups);
        }

        [Fact]
        public void JointOverTwelveSensorsIsOneLatticeTooLargeToAllocateInFull()
        {
            var options = Npc(12);
            options.Grouping = SensorGrouping.Joint;
            options.RbfAllocation = RbfAllocation.Full;
            var e = Assert.Throws<VerveException>(() => new Agent(options));
            Assert.Equal(ResultCode.InvalidArgument, e.Code);
            options.RbfAllocation = RbfAllocation.Dynamic;
            using var agent = new Agent(options);
            Assert.Equal(SensorGrouping.Joint, agent.Options.Grouping);
        }

        [Fact]
        public void AutoKeepsMemoryBoundedWhereOneJointLatticeKeepsGrowing()
        {
            int RbfsAfter(SensorGrouping grouping)
            {
                var options = Npc(12);
                options.Grouping = grouping;
                using var agent = new Agent(options);
                for (int step = 0; step < 3000; step++) agent.Update(0f, null, Readings(step, 12), 0.1f);
                return agent.RbfCount;
            }
            int auto = RbfsAfter(SensorGrouping.Auto), joint = RbfsAfter(SensorGrouping.Joint);
            Assert.True(auto <= 12 * 10 + 11 * 10 * 10, $"Auto: {auto} RBFs");
            Assert.True(joint > 2 * auto, $"Joint: {joint} RBFs, Auto: {auto}");
        }

        [Fact]
        public void CustomGroupsReachTheLibraryAndComeBack()
        {
            var options = Npc(12);
            options.Resolution = 10;
            options.RbfAllocation = RbfAllocation.Full;
            for (int i = 0; i < 12; i++) options.AddSensorGroup(i);
            options.AddSensorGroup(1, 0); // bearing and distance together; any order
            Assert.Equal(SensorGrouping.Custom, options.Grouping);
            Assert.Equal(new[] { 0, 1 }, options.SensorGroups[12]);

            using var agent = new Agent(options);
            Assert.Equal(12 * 10 + 10 * 10, agent.RbfCount);
            AgentOptions back = agent.Options;
            Assert.Equal(SensorGrouping.Custom, back.Grouping);
            Assert.Equal(13, back.SensorGroups.Count);
            for (int i = 0; i < 12; i++) Assert.Equal(new[] { i }, back.SensorGroups[i]);
            Assert.Equal(new[] { 0, 1 }, back.SensorGroups[12]);

            // Options read back are valid options: a second agent from them is the same agent.
            using var twin = new Agent(back);
            Assert.Equal(agent.RbfCount, twin.RbfCount);
        }

        [Theory]
        [InlineData(false)]
        [InlineData(true)]
        public void SavesKeepTheGroups(bool binary)
        {
            var options = Npc(6, seed: 11).AddSensorGroup(0, 1).AddSensorGroup(2, 3, 4).AddSensorGroup(5).AddSensorGroup(0, 5);
            using var agent = new Agent(options);
            for (int step = 0; step < 200; step++) agent.Update(step % 7 == 0 ? 1f : 0f, null, Readings(step, 6), 0.1f);

            using var loaded = Agent.LoadFromBytes(binary ? agent.SaveToBinaryBytes() : agent.SaveToBytes());
            Assert.Equal(SensorGrouping.Custom, loaded.Options.Grouping);
            Assert.Equal(new[] { new[] { 0, 1 }, new[] { 2, 3, 4 }, new[] { 5 }, new[] { 0, 5 } },
                         loaded.Options.SensorGroups.Select(g => g.ToArray()).ToArray());
            Assert.Equal(agent.RbfCount, loaded.RbfCount);
            for (int step = 200; step < 260; step++)
            {
                float[] r = Readings(step, 6);
                Assert.Equal(agent.Update(0f, null, r, 0.1f), loaded.Update(0f, null, r, 0.1f));
            }
        }

        [Fact]
        public void ABrainTakesGroupsToo()
        {
            using var brain = new Brain(Npc(3).AddSensorGroup(0, 1).AddSensorGroup(2));
            using var body = brain.CreateBody();
            body.Update(0f, null, new[] { 0.1f, 0.2f, 0.3f }, 0.1f);
            Assert.Equal(new[] { 0, 1 }, body.Options.SensorGroups[0]);
        }

        [Fact]
        public void AGroupIsCheckedWhenAdded()
        {
            var o = Npc(4);
            Assert.Throws<ArgumentNullException>(() => o.AddSensorGroup(null!));
            Assert.Contains("at least one", Assert.Throws<ArgumentException>(() => o.AddSensorGroup()).Message);
            Assert.Throws<ArgumentOutOfRangeException>(() => o.AddSensorGroup(-1));
            Assert.Throws<ArgumentOutOfRangeException>(() => o.AddSensorGroup(0, AgentOptions.MaxContinuousSensors));
            Assert.Contains("continuous sensor 2 is listed twice", Assert.Throws<ArgumentException>(() => o.AddSensorGroup(2, 2)).Message);
            Assert.Empty(o.SensorGroups); // a refused group changes nothing
            Assert.Equal(SensorGrouping.Auto, o.Grouping);

            for (int i = 0; i < AgentOptions.MaxSensorGroups; i++) o.AddSensorGroup(i % 4);
            Assert.Throws<InvalidOperationException>(() => o.AddSensorGroup(0));
            Assert.Equal(AgentOptions.MaxSensorGroups, o.SensorGroups.Count);
            using (new Agent(o)) { } // 64 groups, some repeated: allowed

            o.ClearSensorGroups();
            Assert.Empty(o.SensorGroups);
            o.AddSensorGroup(1);
            o.ClearSensors();
            Assert.Empty(o.SensorGroups); // groups name sensors: they go with them
        }

        [Fact]
        public void GroupsThatDoNotFitTheSensorsAreRefusedWithAClearMessage()
        {
            string Refusal(AgentOptions o) => Assert.Throws<ArgumentException>(() => new Agent(o)).Message;

            Assert.Contains("sensor group 1 lists continuous sensor 5, but the agent has 4 continuous sensors",
                            Refusal(Npc(4).AddSensorGroup(0, 1).AddSensorGroup(2, 3, 5)));
            Assert.Contains("continuous sensor 3 is in no sensor group",
                            Refusal(Npc(4).AddSensorGroup(0, 1).AddSensorGroup(2)));
            Assert.Contains("needs sensor groups", Refusal(new AgentOptions { Grouping = SensorGrouping.Custom }.AddContinuousSensor()));
            var joint = Npc(2).AddSensorGroup(0, 1);
            joint.Grouping = SensorGrouping.Joint;
            Assert.Contains("only used with Grouping = SensorGrouping.Custom", Refusal(joint));
            Assert.Throws<ArgumentException>(() => new Brain(Npc(4).AddSensorGroup(0)));

            // Custom without continuous sensors needs no group.
            using (new Agent(new AgentOptions { Grouping = SensorGrouping.Custom }.AddDiscreteSensor(3))) { }
        }

        [Fact]
        public void TheDocsTwelveSensorNpcs()
        {
            // docs/csharp.md, "Many sensors", as written there.
            float reward = 0f, dt = 0.1f;
            float[] readings = Readings(1, 12);
            var options = new AgentOptions { Actions = 4 };
            for (int i = 0; i < 12; i++) options.AddContinuousSensor();
            using var npc = new Agent(options);          // Auto: 12 single-sensor lattices and 11 pairs
            int action = npc.Update(reward, null, readings, dt);   // readings: 12 floats in [-1, 1]

            for (int i = 0; i < 12; i++) options.AddSensorGroup(i);        // each sensor alone
            for (int i = 0; i < 7; i++) options.AddSensorGroup(i, i + 1);  // neighbouring rays
            options.AddSensorGroup(7, 0);                                  // the ring closes: ray 7 beside ray 0
            options.AddSensorGroup(8, 9);                                  // bearing with distance
            using var custom = new Agent(options);       // Grouping is now SensorGrouping.Custom

            Assert.InRange(action, 0, 3);
            Assert.Equal(SensorGrouping.Auto, npc.Options.Grouping);
            Assert.Equal(SensorGrouping.Custom, custom.Options.Grouping);
            Assert.Equal(12 + 7 + 2, custom.Options.SensorGroups.Count);
            Assert.InRange(custom.Update(reward, null, readings, dt), 0, 3);
        }

        [Fact]
        public void AnUnknownGroupingIsTheLibrarysToRefuse()
        {
            var o = Npc(2);
            o.Grouping = (SensorGrouping)7;
            var e = Assert.Throws<VerveException>(() => new Agent(o));
            Assert.Equal(ResultCode.InvalidArgument, e.Code);
            Assert.Contains("sensor_grouping", e.Message);
        }
    }
}
