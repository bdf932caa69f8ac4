using System;

namespace Verve.Sample
{
    /// <summary>The thesis's 1D signaled hot plate: a robot on a row of cells that hurt (-1 per step)
    /// except one safe edge (+1, ends the trial). A signal says which edge is safe this trial; the
    /// robot senses the signal (discrete) and its position (continuous, [-1, 1]).</summary>
    public sealed class SignaledHotPlate
    {
        public const int Actions = 3; // left, right, stay
        public const int Signals = 2; // 0: the left edge is safe, 1: the right edge

        private readonly Random _random;
        private readonly int _cells;
        private int _cell;

        public SignaledHotPlate(int cells, int seed)
        {
            if (cells < 3) throw new ArgumentOutOfRangeException(nameof(cells), cells, "must be >= 3");
            _cells = cells;
            _random = new Random(seed);
        }

        public int Signal { get; private set; }

        /// <summary>Cells between the robot and the safe edge: the fewest steps to finish.</summary>
        public int Distance => Signal == 0 ? _cell : _cells - 1 - _cell;

        /// <summary>The robot's position scaled to [-1, 1], as a continuous sensor reads it.</summary>
        public float Position => -1f + 2f * _cell / (_cells - 1);

        /// <summary>Starts a trial: a random signal and a random cell that is not an edge.</summary>
        public void Reset()
        {
            Signal = _random.Next(Signals);
            _cell = _random.Next(1, _cells - 1);
        }

        /// <summary>Moves the robot; returns the reward and whether it reached the safe edge.</summary>
        public (float Reward, bool Done) Act(int action)
        {
            int move = action switch { 0 => -1, 1 => 1, 2 => 0, _ => throw new ArgumentOutOfRangeException(nameof(action)) };
            _cell = Math.Clamp(_cell + move, 0, _cells - 1);
            return Distance == 0 ? (1f, true) : (-1f, false);
        }
    }
}
