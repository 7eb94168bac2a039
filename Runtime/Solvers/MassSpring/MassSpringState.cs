using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The mutable part of one mass-spring body (dynamic buffers in ECS) and the scratch its step needs. Views only.
    /// <see cref="MassSpringSolver.Initialize"/> uses no scratch.
    /// </summary>
    public readonly ref struct MassSpringState
    {
        /// <summary>Particle positions xᵢ (m, relative to <see cref="ParticleBodyStatus.Origin"/>).</summary>
        public readonly Span<float3> Positions;
        /// <summary>Particle velocities vᵢ (m/s).</summary>
        public readonly Span<float3> Velocities;
        /// <summary>
        /// Per-particle scratch, <see cref="ScratchPerParticle"/> × particles: predicted positions, contact normals,
        /// forces, Verlet's previous positions, and the conjugate-gradient vectors of the implicit integrator.
        /// </summary>
        public readonly Span<float3> Scratch;
        /// <summary>Per-spring scratch, <see cref="ScratchPerSpring"/> × springs: per-slot values and per-spring frames / multipliers.</summary>
        public readonly Span<float3> SpringScratch;

        /// <summary>Scratch float3s per particle (predicted, contact normals, force, previous, Δv, r, z, p, q, diagonal).</summary>
        public const int ScratchPerParticle = 10;
        /// <summary>Scratch float3s per spring (two slots, two for the spring's direction and coefficients or multiplier).</summary>
        public const int ScratchPerSpring = 4;

        /// <summary>The state over its buffers and the two scratch spans (the layout the ECS job and the benchmarks share).</summary>
        public static MassSpringState FromScratch(Span<float3> positions, Span<float3> velocities, Span<float3> scratch,
            Span<float3> springScratch) => new MassSpringState(positions, velocities, scratch, springScratch);

        public MassSpringState(Span<float3> positions, Span<float3> velocities, Span<float3> scratch, Span<float3> springScratch)
        {
            Positions = positions;
            Velocities = velocities;
            Scratch = scratch;
            SpringScratch = springScratch;
        }

        int N => Positions.Length;
        /// <summary>Scratch: predicted positions x* of the shared step.</summary>
        public Span<float3> Predicted => Scratch.Slice(0, N);
        /// <summary>Scratch: contact normals of the shared step.</summary>
        public Span<float3> ContactNormals => Scratch.Slice(N, N);
        /// <summary>Scratch block k (0 … <see cref="ScratchPerParticle"/> − 1) of one float3 per particle.</summary>
        public Span<float3> Block(int k) => Scratch.Slice(k * N, N);
    }
}
