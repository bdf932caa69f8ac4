using System;
using Xunit;

namespace Verve.Tests
{
    public class ValueSamplingTests
    {
        private static readonly int[] BaseDiscrete = { 2, 1 };
        private static readonly float[] BaseContinuous = { 0.3f, -0.6f };

        private static Agent Trained()
        {
            var agent = TestAgents.Mixed();
            TestAgents.Run(agent, 400);
            return agent;
        }

        [Fact]
        public void SampleAtTheLatestObservationIsTheAgentsValue()
        {
            using var agent = Trained();
            agent.Learning = false; // so the update below cannot move V(s) after computing it
            agent.Update(0f, BaseDiscrete, BaseContinuous, TestAgents.Dt);
            float[] values = agent.SampleValues(ValueAxis.Discrete(0, 4), BaseDiscrete, BaseContinuous);
            Assert.Equal(4, values.Length);
            Assert.Equal(agent.Value, values[BaseDiscrete[0]], 5);
        }

        [Fact]
        public void TwoAxesAreRowsOfOneAxisSamples_AxisZeroFastest()
        {
            using var agent = Trained();
            float[] grid = agent.SampleValues(ValueAxis.Continuous(0, 5), ValueAxis.Discrete(1, 3), BaseDiscrete, BaseContinuous);
            Assert.Equal(15, grid.Length);
            for (int row = 0; row < 3; row++)
            {
                float[] line = agent.SampleValues(ValueAxis.Continuous(0, 5), new[] { BaseDiscrete[0], row }, BaseContinuous);
                Assert.Equal(line, grid.AsSpan(row * 5, 5).ToArray());
            }
            Assert.Contains(grid, v => v != grid[0]); // trained: not flat
        }

        [Fact]
        public void SpanOverloadFillsTheCallersBuffer()
        {
            using var agent = Trained();
            Span<float> destination = stackalloc float[7];
            ReadOnlySpan<ValueAxis> axes = stackalloc ValueAxis[] { ValueAxis.Continuous(1, 7) };
            agent.SampleValues(axes, BaseDiscrete, BaseContinuous, destination);
            Assert.Equal(agent.SampleValues(ValueAxis.Continuous(1, 7), BaseDiscrete, BaseContinuous), destination.ToArray());
        }

        [Fact]
        public void LargerDestinationKeepsItsTail()
        {
            using var agent = Trained();
            var destination = new float[6];
            destination[5] = 42f;
            agent.SampleValues(new[] { ValueAxis.Continuous(0, 5) }, BaseDiscrete, BaseContinuous, destination);
            Assert.Equal(agent.SampleValues(ValueAxis.Continuous(0, 5), BaseDiscrete, BaseContinuous), destination.AsSpan(0, 5).ToArray());
            Assert.Equal(42f, destination[5]);
        }

        public static TheoryData<string, ValueAxis[], int[], float[], int> BadRequests => new TheoryData<string, ValueAxis[], int[], float[], int>
        {
            { "no axes", new ValueAxis[0], BaseDiscrete, BaseContinuous, 1 },
            { "three axes", new[] { ValueAxis.Discrete(0, 4), ValueAxis.Discrete(1, 3), ValueAxis.Continuous(0, 2) }, BaseDiscrete, BaseContinuous, 24 },
            { "destination too small", new[] { ValueAxis.Continuous(0, 5) }, BaseDiscrete, BaseContinuous, 4 },
            { "no such continuous sensor", new[] { ValueAxis.Continuous(2, 5) }, BaseDiscrete, BaseContinuous, 5 },
            { "no such discrete sensor", new[] { ValueAxis.Discrete(2, 3) }, BaseDiscrete, BaseContinuous, 3 },
            { "discrete axis with the wrong value count", new[] { ValueAxis.Discrete(0, 3) }, BaseDiscrete, BaseContinuous, 3 },
            { "base with too few values", new[] { ValueAxis.Continuous(0, 5) }, new[] { 1 }, BaseContinuous, 5 },
            { "base with a NaN", new[] { ValueAxis.Continuous(0, 5) }, BaseDiscrete, new[] { 0f, float.NaN }, 5 },
            { "base with an out-of-range discrete value", new[] { ValueAxis.Continuous(0, 5) }, new[] { 9, 0 }, BaseContinuous, 5 },
        };

        [Theory]
        [MemberData(nameof(BadRequests))]
        public void BadRequestsThrowAndLeaveTheDestinationAlone(string why, ValueAxis[] axes, int[] baseDiscrete, float[] baseContinuous, int count)
        {
            using var agent = Trained();
            var destination = new float[count];
            Array.Fill(destination, 42f);
            var e = Assert.Throws<VerveException>(() => agent.SampleValues(axes, baseDiscrete, baseContinuous, destination));
            Assert.True(e.Code == ResultCode.InvalidArgument, $"{why}: {e.Code}");
            Assert.All(destination, v => Assert.Equal(42f, v));
        }

        [Fact]
        public void AxisFactoriesRefuseNegativeAndEmptyAxes()
        {
            Assert.Throws<ArgumentOutOfRangeException>(() => ValueAxis.Continuous(-1, 5));
            Assert.Throws<ArgumentOutOfRangeException>(() => ValueAxis.Continuous(0, 0));
            Assert.Throws<ArgumentOutOfRangeException>(() => ValueAxis.Discrete(0, -2));
            var axis = ValueAxis.Discrete(1, 3);
            Assert.Equal((SensorKind.Discrete, 1, 3), (axis.Kind, axis.Index, axis.Samples));
            Assert.Equal(axis, ValueAxis.Discrete(1, 3));
            Assert.NotEqual(axis, ValueAxis.Continuous(1, 3));
        }
    }
}
