using System;
using System.IO;
using System.Text;
using Xunit;

namespace Verve.Tests
{
    public sealed class PersistenceTests : IDisposable
    {
        private readonly string _dir = Path.Combine(Path.GetTempPath(), "verve-cs-" + Guid.NewGuid().ToString("N"));

        public PersistenceTests() => Directory.CreateDirectory(_dir);

        public void Dispose() => Directory.Delete(_dir, recursive: true);

        [Fact]
        public void ARecordingReplaysAsTheDemonstratedStepsItHolds()
        {
            using var shown = new Agent(new AgentOptions { Actions = 3, Seed = 4 }.AddDiscreteSensor(2).AddContinuousSensor(false));
            using var replayed = new Agent(new AgentOptions { Actions = 3, Seed = 4 }.AddDiscreteSensor(2).AddContinuousSensor(false));
            using var recording = new Recording(shown);
            for (int i = 0; i < 30; i++)
            {
                int[] d = { i % 2 };
                float[] c = { (float)Math.Sin(i) };
                recording.AddStep(0.1f, d, c, 0.1f, i % 3);
                shown.UpdateDemonstrated(0.1f, d, c, 0.1f, i % 3);
                if (i % 10 == 9) { recording.AddEndEpisode(1f); shown.EndEpisode(1f); }
            }
            recording.AddTruncation(0f);
            shown.TruncateEpisode(0f);
            Assert.Equal(34, recording.Count);
            string path = Path.Combine(_dir, "shown.vrec");
            recording.Save(path);
            using var loaded = Recording.Load(path);
            Assert.Equal(recording.SaveToBytes(), loaded.SaveToBytes());
            replayed.Replay(loaded);
            Assert.Equal(shown.SaveToBinaryBytes(), replayed.SaveToBinaryBytes());

            byte[] before = recording.SaveToBytes();
            Assert.Throws<VerveException>(() => recording.AddStep(0f, new[] { 2 }, new[] { 0f }, 0.1f, 0));
            Assert.Throws<ArgumentOutOfRangeException>(() => recording.AddStep(0f, new[] { 0 }, new[] { 0f }, 0.1f, -1));
            Assert.Equal(before, recording.SaveToBytes());
            byte[] damaged = (byte[])before.Clone();
            damaged[damaged.Length / 2] ^= 0x10;
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Recording.LoadFromBytes(damaged)).Code);
            using var stranger = new Agent(new AgentOptions { Actions = 2 }.AddContinuousSensor(false));
            Assert.Throws<VerveException>(() => stranger.Replay(loaded));
            recording.Dispose();
            Assert.Throws<ObjectDisposedException>(() => recording.Count);
        }

        private static Agent Trained(ulong seed = 11)
        {
            var agent = TestAgents.Mixed(seed);
            TestAgents.Run(agent, 300);
            return agent;
        }

        [Fact]
        public void FileRoundTripGivesIdenticalActions()
        {
            using var original = Trained();
            string path = Path.Combine(_dir, "agent ü.xml"); // a space and non-ASCII: UTF-8 paths
            original.Save(path);
            Assert.StartsWith("<?xml", File.ReadAllText(path).TrimStart());

            using var loaded = Agent.Load(path);
            Assert.Equal(original.SaveToBytes(), loaded.SaveToBytes());
            Assert.Equal(TestAgents.Run(original, 300, first: 300), TestAgents.Run(loaded, 300, first: 300));
            Assert.Equal(original.Stats.Steps, loaded.Stats.Steps);
        }

        [Fact]
        public void BytesRoundTripGivesIdenticalActionsAndOptions()
        {
            using var original = Trained();
            byte[] bytes = original.SaveToBytes();
            using var loaded = Agent.LoadFromBytes(bytes);
            using var fromSpan = Agent.LoadFromBytes(new ReadOnlySpan<byte>(bytes));

            Assert.Equal(original.Options.Seed, loaded.Options.Seed);
            Assert.Equal(original.Options.DiscreteSensors, loaded.Options.DiscreteSensors);
            Assert.Equal(original.RbfCount, loaded.RbfCount);
            int[] expected = TestAgents.Run(original, 300, first: 300);
            Assert.Equal(expected, TestAgents.Run(loaded, 300, first: 300));
            Assert.Equal(expected, TestAgents.Run(fromSpan, 300, first: 300));
        }

        [Fact]
        public void BinarySaveRoundTripGivesIdenticalActions()
        {
            using var original = Trained();
            byte[] bytes = original.SaveToBinaryBytes();
            Assert.Equal("VERVEBIN", Encoding.ASCII.GetString(bytes, 0, 8));
            Assert.True(bytes.Length < original.SaveToBytes().Length);
            string path = Path.Combine(_dir, "agent.bin");
            original.SaveBinary(path);
            Assert.Equal(bytes, File.ReadAllBytes(path));

            using var fromBytes = Agent.LoadFromBytes(bytes);
            using var fromFile = Agent.Load(path);
            Assert.Equal(bytes, fromBytes.SaveToBinaryBytes());
            Assert.Equal(original.SaveToBytes(), fromFile.SaveToBytes());
            int[] expected = TestAgents.Run(original, 300, first: 300);
            Assert.Equal(expected, TestAgents.Run(fromBytes, 300, first: 300));
            Assert.Equal(expected, TestAgents.Run(fromFile, 300, first: 300));
        }

        [Fact]
        public void DamagedBinarySaveIsAFormatError()
        {
            using var agent = Trained();
            byte[] bytes = agent.SaveToBinaryBytes();
            bytes[bytes.Length / 2] ^= 1;
            var e = Assert.Throws<VerveException>(() => Agent.LoadFromBytes(bytes));
            Assert.Equal(ResultCode.Format, e.Code);
            Assert.Contains("checksum", e.Message);
        }

        [Fact]
        public void FileAndBytesHoldTheSameSave()
        {
            using var agent = Trained();
            string path = Path.Combine(_dir, "same.xml");
            agent.Save(path);
            Assert.Equal(agent.SaveToBytes(), File.ReadAllBytes(path));
        }

        [Fact]
        public void SaveReplacesAnOlderSave()
        {
            using var agent = Trained();
            string path = Path.Combine(_dir, "replaced.xml");
            File.WriteAllText(path, "old");
            agent.Save(path);
            Assert.Equal(agent.SaveToBytes(), File.ReadAllBytes(path));
        }

        [Fact]
        public void CorruptBytesAreAFormatError()
        {
            using var agent = Trained();
            byte[] bytes = agent.SaveToBytes();

            byte[] truncated = bytes.AsSpan(0, bytes.Length / 2).ToArray();
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Agent.LoadFromBytes(truncated)).Code);

            byte[] garbage = Encoding.UTF8.GetBytes("this is not a save");
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Agent.LoadFromBytes(garbage)).Code);

            string text = Encoding.UTF8.GetString(bytes);
            byte[] malformed = Encoding.UTF8.GetBytes(text.Replace("</", "<"));
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Agent.LoadFromBytes(malformed)).Code);

            // Well-formed XML describing an impossible agent is refused too.
            string actions = $"actions=\"{TestAgents.Actions}\"";
            Assert.Contains(actions, text);
            byte[] inconsistent = Encoding.UTF8.GetBytes(text.Replace(actions, "actions=\"0\""));
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Agent.LoadFromBytes(inconsistent)).Code);

            byte[] flipped = (byte[])bytes.Clone();
            flipped[flipped.Length / 2] = (byte)'\u0001';
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Agent.LoadFromBytes(flipped)).Code);
        }

        [Fact]
        public void EmptyAndNullInputsAreRefused()
        {
            Assert.Throws<VerveException>(() => Agent.LoadFromBytes(Array.Empty<byte>()));
            Assert.Throws<ArgumentNullException>(() => Agent.LoadFromBytes((byte[])null!));
            Assert.Throws<ArgumentNullException>(() => Agent.Load(null!));
            using var agent = Trained();
            Assert.Throws<ArgumentNullException>(() => agent.Save(null!));
            Assert.Throws<ArgumentException>(() => agent.Save("bad\0name.xml"));
        }

        [Fact]
        public void MissingFilesAndFoldersAreIoErrors()
        {
            var e = Assert.Throws<VerveException>(() => Agent.Load(Path.Combine(_dir, "missing.xml")));
            Assert.Equal(ResultCode.Io, e.Code);
            Assert.Contains("missing.xml", e.Message);

            using var agent = Trained();
            string inMissingFolder = Path.Combine(_dir, "no-such-folder", "agent.xml");
            Assert.Equal(ResultCode.Io, Assert.Throws<VerveException>(() => agent.Save(inMissingFolder)).Code);
            Assert.False(File.Exists(inMissingFolder));
        }

        [Fact]
        public void CorruptFileIsAFormatError()
        {
            string path = Path.Combine(_dir, "corrupt.xml");
            File.WriteAllText(path, "<verve><agent");
            Assert.Equal(ResultCode.Format, Assert.Throws<VerveException>(() => Agent.Load(path)).Code);
        }
    }
}
