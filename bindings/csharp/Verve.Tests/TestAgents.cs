using System;

namespace Verve.Tests
{
    // A small agent with every kind of sensor, and a deterministic, varied observation stream for it.
    internal static class TestAgents
    {
        public const float Dt = 0.1f;
        public const int Actions = 3;
        public static readonly int[] DiscreteValues = { 4, 3 };

        public static AgentOptions MixedOptions(ulong seed = 7) =>
            new AgentOptions { Actions = Actions, Seed = seed }
                .AddDiscreteSensor(DiscreteValues[0])
                .AddDiscreteSensor(DiscreteValues[1])
                .AddContinuousSensor()
                .AddContinuousSensor(circular: true);

        public static Agent Mixed(ulong seed = 7) => new Agent(MixedOptions(seed));

        public static int[] Discrete(int step) => new[] { step % 4, step / 4 % 3 };

        public static float[] Continuous(int step) => new[] { MathF.Sin(step * 0.3f), MathF.Cos(step * 0.7f) };

        public static float Reward(int step) => (step % 5 - 2) / 2f;

        /// <summary>Feeds steps [first, first + count) and returns the actions chosen.</summary>
        public static int[] Run(Agent agent, int count, int first = 0)
        {
            var actions = new int[count];
            for (int i = 0; i < count; i++)
            {
                int step = first + i;
                actions[i] = agent.Update(Reward(step), Discrete(step), Continuous(step), Dt);
            }
            return actions;
        }
    }
}
