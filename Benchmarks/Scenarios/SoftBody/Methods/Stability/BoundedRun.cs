using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Why a run was not bounded.</summary>
    public enum UnboundedReason
    {
        /// <summary>The run was bounded.</summary>
        None,
        /// <summary>The step's NaN guard reset the body.</summary>
        Reset,
        /// <summary>A position or velocity was not finite.</summary>
        NonFinite,
        /// <summary>The kinetic energy exceeded <see cref="StabilityCube.KineticEnergyLimit"/>.</summary>
        KineticEnergy,
        /// <summary>The shape deviation exceeded <see cref="StabilityCube.DeformationLimit"/>.</summary>
        Deformation,
    }

    /// <summary>What <see cref="BoundedRun.Run"/> saw.</summary>
    public readonly struct BoundedRunResult
    {
        /// <summary>Why the run was stopped; <see cref="UnboundedReason.None"/> when it was bounded to the end.</summary>
        public readonly UnboundedReason Reason;
        /// <summary>Steps taken (the run stops at the first unbounded step).</summary>
        public readonly int Steps;
        /// <summary>Largest kinetic energy seen over the energy budget (dimensionless).</summary>
        public readonly double PeakKineticEnergy;
        /// <summary>Largest shape deviation seen over the cube size (dimensionless).</summary>
        public readonly double PeakDeviation;

        public BoundedRunResult(UnboundedReason reason, int steps, double peakKineticEnergy, double peakDeviation)
        {
            Reason = reason;
            Steps = steps;
            PeakKineticEnergy = peakKineticEnergy;
            PeakDeviation = peakDeviation;
        }

        public bool Bounded => Reason == UnboundedReason.None;
    }

    /// <summary>
    /// One run of the stable-step search: the cube started compressed (<see cref="StabilityCube.Start"/>), stepped with
    /// steps of dt (one per frame) for T = max(<see cref="MinTime"/>, <see cref="MinSteps"/>·dt) under gravity. It is
    /// bounded when after every step the guard has not reset the body, every position and velocity is finite, the kinetic
    /// energy ½ Σ mᵢ|vᵢ|² is below <see cref="StabilityCube.KineticEnergyLimit"/> and the shape deviation
    /// (<see cref="ShapeDeviation"/>, the strain measure: rigid motion removed) is below <see cref="StabilityCube.DeformationLimit"/>.
    /// </summary>
    public static class BoundedRun
    {
        /// <summary>Shortest simulated time of a run (s).</summary>
        public const double MinTime = 1.0;
        /// <summary>Fewest steps of a run.</summary>
        public const int MinSteps = 50;

        /// <summary>Steps of a run of step <paramref name="dt"/> (s).</summary>
        public static int StepsFor(double dt) => Math.Max(MinSteps, (int)Math.Ceiling(MinTime / dt - 1e-9));

        public static BoundedRunResult Run(StabilityCube cube, IMethodBody body, float dt)
        {
            cube.Start(body);
            int steps = StepsFor(dt);
            double budget = cube.EnergyBudget, size = cube.Size;
            double kineticLimit = cube.KineticEnergyLimit, deformationLimit = cube.DeformationLimit;
            double peakKinetic = 0, peakDeviation = 0;
            quaternion rotation = quaternion.identity;
            for (int k = 0; k < steps; k++)
            {
                body.Step(dt, StabilityCube.Gravity, ReadOnlySpan<ColliderShape>.Empty);
                double kinetic = KineticEnergy(body);
                double deviation = ShapeDeviation.Max(body, ref rotation);
                peakKinetic = Math.Max(peakKinetic, kinetic / budget);
                peakDeviation = Math.Max(peakDeviation, deviation / size);
                UnboundedReason reason = body.Resets > 0 ? UnboundedReason.Reset
                    : !double.IsFinite(kinetic) || !double.IsFinite(deviation) ? UnboundedReason.NonFinite
                    : !(kinetic <= kineticLimit) ? UnboundedReason.KineticEnergy
                    : !(deviation <= deformationLimit) ? UnboundedReason.Deformation
                    : UnboundedReason.None;
                if (reason != UnboundedReason.None)
                    return new BoundedRunResult(reason, k + 1, peakKinetic, peakDeviation);
            }
            return new BoundedRunResult(UnboundedReason.None, steps, peakKinetic, peakDeviation);
        }

        /// <summary>½ Σ mᵢ |vᵢ|² (J), in double; NaN or ∞ when a velocity is not finite.</summary>
        public static double KineticEnergy(IMethodBody body)
        {
            double e = 0;
            for (int i = 0; i < body.ParticleCount; i++)
            {
                float3 v = body.Velocities[i];
                e += 0.5 * body.Masses[i] * ((double)v.x * v.x + (double)v.y * v.y + (double)v.z * v.z);
            }
            return e;
        }
    }
}
