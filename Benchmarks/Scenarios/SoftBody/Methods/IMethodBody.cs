using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One soft body of the method study, whatever holds it together: the scenes of the study place it, step it and
    /// read its particles through this interface only, so every method is measured by the same code. Every body is built
    /// from the same tetrahedral box (its nodes are the particles) and the same <see cref="SoftBodyDynamics.Solvers.ElasticMaterial"/>
    /// (<see cref="MethodBodySetup"/>). Particle positions are world positions (the study's bodies stay near the world
    /// origin, so the body's origin stays at zero).
    /// </summary>
    public interface IMethodBody
    {
        /// <summary>Method family, the legend entry of the study's figures (e.g. "FEM co-rotational, implicit").</summary>
        string Family { get; }
        /// <summary>The cost knob of this body, e.g. "8 substeps".</summary>
        string Knob { get; }
        /// <summary>Particles (= mesh nodes).</summary>
        int ParticleCount { get; }
        /// <summary>Rest positions (m).</summary>
        float3[] RestPositions { get; }
        /// <summary>Particle masses (kg), lumped from the tetrahedra (the same for every method).</summary>
        float[] Masses { get; }
        /// <summary>Positions xᵢ (m); a scene may write them, then calls <see cref="StateWritten"/>.</summary>
        float3[] Positions { get; }
        /// <summary>Velocities vᵢ (m/s); a scene may write them, then calls <see cref="StateWritten"/>.</summary>
        float3[] Velocities { get; }
        /// <summary>NaN-guard resets since the last <see cref="Place"/>.</summary>
        int Resets { get; }
        /// <summary>Rest shape at rest, status and method state back to their start; pinned particles at their rest positions.</summary>
        void Place();
        /// <summary>One step of <paramref name="dt"/> (s) under uniform acceleration <paramref name="gravity"/> (m/s²) against static colliders.</summary>
        void Step(float dt, float3 gravity, ReadOnlySpan<SoftBodyDynamics.Solvers.ColliderShape> colliders);
        /// <summary>Positions or velocities were written from outside: the method drops what it keeps of the previous state.</summary>
        void StateWritten();
    }
}
