using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>The kernels of <c>Shaders/SoftBodySolver.compute</c>, named as in HLSL.</summary>
    public enum SoftBodyKernel : byte { XpbdPredict, XpbdClearMultipliers, XpbdProjectColor, XpbdVelocities, ClusterSums }

    /// <summary>The structured buffers of the soft-body kernels; the shader property is "_" + the name.</summary>
    public enum SoftBodyComputeBuffer : byte
    {
        X, V, P, Rest, InverseMass, Springs, ColorSprings, Multipliers, ClusterOffsets, ClusterParticles, ClusterWeights, ClusterRest,
        ClusterCenters, ClusterApq,
    }

    /// <summary>
    /// The per-dispatch arguments of the soft-body kernels (uint4 loose globals); the shader property is "_" + the name.
    /// The substep's constants are <see cref="SoftBodyComputeConstants"/>.
    /// </summary>
    public enum SoftBodyComputeGlobal : byte
    {
        /// <summary>x first, y end (a colour's range in <see cref="SoftBodyComputeBuffer.ColorSprings"/>), or the particle, spring or cluster count in x.</summary>
        Range,
    }

    /// <summary>What <see cref="SoftBodyComputeStep"/> asks of a GPU backend (Unity's ComputeShader or the lavapipe harness).</summary>
    public interface ISoftBodyComputeCommands
    {
        /// <summary>
        /// Uploads <paramref name="constants"/> whole (<see cref="SoftBodyComputeConstants.Bytes"/> bytes) and binds them as
        /// the kernels' constant buffer <see cref="SoftBodyComputeConstants.BufferName"/> for the dispatches that follow.
        /// </summary>
        void SetConstants(in SoftBodyComputeConstants constants);
        /// <summary>Sets a per-dispatch uint4 argument (as int4 bits) for the dispatches that follow.</summary>
        void SetInts(SoftBodyComputeGlobal name, int4 value);
        /// <summary>Dispatches ⌈<paramref name="threads"/> / group size⌉ groups (none for 0).</summary>
        void Dispatch(SoftBodyKernel kernel, int threads);
        /// <summary>Dispatches <paramref name="groups"/> groups (one per cluster for <see cref="SoftBodyKernel.ClusterSums"/>).</summary>
        void DispatchGroups(SoftBodyKernel kernel, int groups);
    }

    /// <summary>
    /// Records soft-body work as GPU dispatches: an XPBD substep of a mass-spring body (the XPBD branch of
    /// MassSpringSolveStage: predict, clear λ, project colour by colour, velocities) and the shape-matching cluster sums.
    /// Also packs the CPU model data into the GPU layout.
    /// </summary>
    public static class SoftBodyComputeStep
    {
        /// <summary>Threads per group (SOFT_BODY_GROUP in SoftBodyCommon.hlsl).</summary>
        public const int ThreadGroupSize = 256;

        /// <summary>
        /// One XPBD substep of <paramref name="h"/> seconds over <paramref name="particles"/> particles and
        /// <paramref name="springs"/> springs in the colours <paramref name="colorOffsets"/>, <paramref name="iterations"/> times.
        /// </summary>
        public static void RecordXpbdSubstep<T>(ref T commands, int particles, int springs, ReadOnlySpan<int> colorOffsets, int iterations, float h)
            where T : ISoftBodyComputeCommands
        {
            commands.SetConstants(SoftBodyComputeConstants.Of(h));
            commands.SetInts(SoftBodyComputeGlobal.Range, new int4(particles, 0, 0, 0));
            commands.Dispatch(SoftBodyKernel.XpbdPredict, particles);
            commands.SetInts(SoftBodyComputeGlobal.Range, new int4(springs, 0, 0, 0));
            commands.Dispatch(SoftBodyKernel.XpbdClearMultipliers, springs);
            for (int it = 0; it < iterations; it++)
                for (int c = 0; c + 1 < colorOffsets.Length; c++)
                {
                    commands.SetInts(SoftBodyComputeGlobal.Range, new int4(colorOffsets[c], colorOffsets[c + 1], 0, 0));
                    commands.Dispatch(SoftBodyKernel.XpbdProjectColor, colorOffsets[c + 1] - colorOffsets[c]);
                }
            commands.SetInts(SoftBodyComputeGlobal.Range, new int4(particles, 0, 0, 0));
            commands.Dispatch(SoftBodyKernel.XpbdVelocities, particles);
        }

        /// <summary>The centre and A_pq of every cluster (one group each).</summary>
        public static void RecordClusterSums<T>(ref T commands, int clusters) where T : ISoftBodyComputeCommands
        {
            commands.SetInts(SoftBodyComputeGlobal.Range, new int4(clusters, 0, 0, 0));
            commands.DispatchGroups(SoftBodyKernel.ClusterSums, clusters);
        }

        /// <summary>Springs as two float4 each: (A bits, B bits, rest length, stiffness), (damping, 0, 0, 0).</summary>
        public static void PackSprings(ReadOnlySpan<Spring> springs, Span<float4> destination)
        {
            for (int e = 0; e < springs.Length; e++)
            {
                Spring s = springs[e];
                destination[2 * e] = new float4(math.asfloat(s.A), math.asfloat(s.B), s.RestLength, s.Stiffness);
                destination[2 * e + 1] = new float4(s.Damping, 0f, 0f, 0f);
            }
        }

        /// <summary>float3 → float4 (w = 0).</summary>
        public static void PackVectors(ReadOnlySpan<float3> source, Span<float4> destination)
        {
            for (int i = 0; i < source.Length; i++)
                destination[i] = new float4(source[i], 0f);
        }
    }
}
