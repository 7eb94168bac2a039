using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>A state no method should be given, but every method must survive (the stability study and the body tests build it with <see cref="HardCases"/>).</summary>
    public enum HardCase
    {
        /// <summary>The body mirrored through the plane x = x_c of its rest centre of mass: every tetrahedron inverted.</summary>
        Inverted,
        /// <summary>Every node moved to the plane y = y_c of its rest centre of mass: every tetrahedron of zero volume.</summary>
        Flattened,
        /// <summary>Steps of <see cref="HardCases.HugeStep"/> from a uniform compression of <see cref="HardCases.HugeStepCompression"/> along y.</summary>
        HugeStep,
        /// <summary>A NaN in the x coordinate of particle 0.</summary>
        NanInput,
    }

    /// <summary>How the hard cases are built from a body placed at rest: one construction for the stability study and the tests.</summary>
    public static class HardCases
    {
        /// <summary>Step length of the <see cref="HardCase.HugeStep"/> case (s): 30 frames of a 60 Hz game.</summary>
        public const float HugeStep = 0.5f;
        /// <summary>Compression along y the <see cref="HardCase.HugeStep"/> case starts from (fraction of the height), so that the step has something to do.</summary>
        public const float HugeStepCompression = 0.1f;

        /// <summary>Every case, in report order.</summary>
        public static readonly HardCase[] All = { HardCase.Inverted, HardCase.Flattened, HardCase.HugeStep, HardCase.NanInput };

        /// <summary>Short name for tables ("inverted", "flattened", "huge step", "NaN input").</summary>
        public static string Label(HardCase c) => c switch
        {
            HardCase.Inverted => "inverted",
            HardCase.Flattened => "flattened",
            HardCase.HugeStep => "huge step",
            _ => "NaN input",
        };

        /// <summary>Step length (s) of the case: <see cref="HugeStep"/> for <see cref="HardCase.HugeStep"/>, else <paramref name="frame"/>.</summary>
        public static float StepLength(HardCase c, float frame) => c == HardCase.HugeStep ? HugeStep : frame;

        /// <summary>
        /// Writes the case into <paramref name="body"/>'s positions (from its rest positions; velocities zero) and calls
        /// <see cref="IMethodBody.StateWritten"/>. Pinned particles move too: give the cases a body without pins, or the pins
        /// hold the written state and the rest shape cannot come back.
        /// </summary>
        public static void Apply(IMethodBody body, HardCase c)
        {
            float3 center = RestCenter(body);
            for (int i = 0; i < body.ParticleCount; i++)
            {
                float3 x = body.RestPositions[i];
                body.Positions[i] = c switch
                {
                    HardCase.Inverted => new float3(2f * center.x - x.x, x.y, x.z),
                    HardCase.Flattened => new float3(x.x, center.y, x.z),
                    HardCase.HugeStep => new float3(x.x, center.y + (1f - HugeStepCompression) * (x.y - center.y), x.z),
                    _ => x,
                };
                body.Velocities[i] = float3.zero;
            }
            if (c == HardCase.NanInput)
                body.Positions[0].x = float.NaN;
            body.StateWritten();
        }

        /// <summary>Centre of mass of the rest shape (m).</summary>
        public static float3 RestCenter(IMethodBody body)
        {
            double x = 0, y = 0, z = 0, m = 0;
            for (int i = 0; i < body.ParticleCount; i++)
            {
                double mi = body.Masses[i];
                x += mi * body.RestPositions[i].x;
                y += mi * body.RestPositions[i].y;
                z += mi * body.RestPositions[i].z;
                m += mi;
            }
            m = Math.Max(m, double.Epsilon);
            return new float3((float)(x / m), (float)(y / m), (float)(z / m));
        }
    }
}
