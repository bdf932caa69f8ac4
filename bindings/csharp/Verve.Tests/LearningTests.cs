using System;
using System.Linq;
using Xunit;

namespace Verve.Tests
{
    // Learning through the binding, on two small tasks with known answers. Seeds are fixed, so a
    // result is reproducible; several seeds keep one lucky run from hiding a broken learner.
    public class LearningTests
    {
        private const float Dt = 0.1f;

        // One-step trials: a signal shows which of 3 actions pays +1; the others pay -1.
        // Returns the fraction of correct actions over the last 100 trials.
        private static double SignalMatching(Agent agent, int trials, Random task)
        {
            int correct = 0;
            for (int t = 0; t < trials; t++)
            {
                int signal = task.Next(3);
                int action = agent.Update(0f, new[] { signal }, null, Dt);
                if (t >= trials - 100 && action == signal) correct++;
                agent.EndEpisode(action == signal ? 1f : -1f);
            }
            return correct / 100.0;
        }

        [Theory]
        [InlineData(1UL)]
        [InlineData(2UL)]
        [InlineData(3UL)]
        public void LearnsWhichActionEachSignalAsksFor(ulong seed)
        {
            var options = new AgentOptions { Actions = 3, Seed = seed }.AddDiscreteSensor(3);
            using var learner = new Agent(options);
            using var control = new Agent(options) { Learning = false }; // same agent, learning off
            double learned = SignalMatching(learner, 500, new Random((int)seed));
            double chance = SignalMatching(control, 500, new Random((int)seed));
            Assert.True(chance < 0.5, $"without learning: near 1/3 correct, got {chance:P0}");
            Assert.True(learned > 0.9, $"with learning: above 90% correct, got {learned:P0}");
        }

        // A 10-cell corridor walked by a continuous position sensor: start at the left end, +1 for
        // reaching the right end; actions left, stay, right. Shortest path: 9 steps.
        private static int Corridor(Agent agent, int maxSteps)
        {
            const int cells = 10;
            int cell = 0;
            for (int step = 1; step <= maxSteps; step++)
            {
                float position = -1f + cell * 2f / (cells - 1);
                int action = agent.Update(0f, null, new[] { position }, Dt);
                cell = Math.Clamp(cell + action - 1, 0, cells - 1);
                if (cell == cells - 1)
                {
                    agent.EndEpisode(1f);
                    return step;
                }
            }
            agent.EndEpisode(0f);
            return maxSteps;
        }

        [Theory]
        [InlineData(1UL)]
        [InlineData(2UL)]
        [InlineData(3UL)]
        public void LearnsTheWayAlongACorridor(ulong seed)
        {
            using var agent = new Agent(new AgentOptions { Actions = 3, Seed = seed }.AddContinuousSensor());
            int[] steps = Enumerable.Range(0, 60).Select(_ => Corridor(agent, 2000)).ToArray();
            double first = steps.Take(5).Average(), last = steps.Skip(50).Average();
            Assert.True(last < 15, $"last trials take {last} steps (shortest 9); first ones {first}");
            Assert.True(first > 2 * last, $"first trials {first} steps vs last {last}");

            // The learned values rise toward the goal.
            float[] values = agent.SampleValues(ValueAxis.Continuous(0, 10), null, new[] { 0f });
            Assert.True(values[8] > values[0], string.Join(", ", values));
        }
    }
}
