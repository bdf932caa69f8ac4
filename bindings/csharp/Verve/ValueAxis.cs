// Nullable annotations on: Unity compiles these sources without the .csproj that enables them.
#nullable enable
using System;
using System.Runtime.InteropServices;

namespace Verve
{
    /// <summary>One sensor swept by <see cref="Agent.SampleValues(ValueAxis, ReadOnlySpan{int}, ReadOnlySpan{float})"/>.
    /// Blittable mirror of <c>verve_value_axis</c>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct ValueAxis : IEquatable<ValueAxis>
    {
        // C names and order: the layout test compares these offsets with the C compiler's.
        private readonly SensorKind kind;
        private readonly uint index;
        private readonly uint samples;

        private ValueAxis(SensorKind kind, int index, int samples)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index), index, "must be >= 0");
            if (samples < 1) throw new ArgumentOutOfRangeException(nameof(samples), samples, "must be >= 1");
            this.kind = kind;
            this.index = (uint)index;
            this.samples = (uint)samples;
        }

        /// <summary>Sweeps continuous sensor <paramref name="index"/> over <paramref name="samples"/>
        /// evenly spaced points from -1 to 1.</summary>
        public static ValueAxis Continuous(int index, int samples) => new ValueAxis(SensorKind.Continuous, index, samples);

        /// <summary>Sweeps every value of discrete sensor <paramref name="index"/>, which has
        /// <paramref name="values"/> values.</summary>
        public static ValueAxis Discrete(int index, int values) => new ValueAxis(SensorKind.Discrete, index, values);

        /// <summary>Kind of the swept sensor.</summary>
        public SensorKind Kind => kind;

        /// <summary>Index of the swept sensor among the sensors of its kind.</summary>
        public int Index => (int)index;

        /// <summary>Number of points along this axis.</summary>
        public int Samples => (int)samples;

        /// <inheritdoc />
        public bool Equals(ValueAxis other) => kind == other.kind && index == other.index && samples == other.samples;

        /// <inheritdoc />
        public override bool Equals(object? obj) => obj is ValueAxis other && Equals(other);

        /// <inheritdoc />
        public override int GetHashCode() => HashCode.Combine(kind, index, samples);

        /// <inheritdoc />
        public override string ToString() => $"{kind}[{index}] x {samples}";
    }
}
