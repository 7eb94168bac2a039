using System;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>Span views of a body's buffers and scratch, as the solver takes them (no copies).</summary>
    static class SoftBodyBuffers
    {
        public static Span<float3> AsSpan(DynamicBuffer<SoftBodyPosition> buffer) => buffer.Reinterpret<float3>().AsNativeArray().AsSpan();

        public static Span<float3> AsSpan(DynamicBuffer<SoftBodyVelocity> buffer) => buffer.Reinterpret<float3>().AsNativeArray().AsSpan();

        public static Span<ClusterState> AsSpan(DynamicBuffer<ShapeMatchingCluster> buffer) => buffer.Reinterpret<ClusterState>().AsNativeArray().AsSpan();

        public static Span<float3x3> AsSpan(DynamicBuffer<ShapeMatchingQuadraticInverse> buffer) => buffer.Reinterpret<float3x3>().AsNativeArray().AsSpan();

        /// <summary>
        /// The solver state over the buffers and a scratch array of <see cref="ShapeMatchingState.ScratchPerParticle"/> × particles
        /// (allocate it with <see cref="Allocator.Temp"/> inside the job).
        /// </summary>
        public static ShapeMatchingState State(DynamicBuffer<SoftBodyPosition> positions, DynamicBuffer<SoftBodyVelocity> velocities,
            DynamicBuffer<ShapeMatchingCluster> clusters, Span<float3x3> quadraticInverse, NativeArray<float3> scratch)
            => ShapeMatchingState.FromScratch(AsSpan(positions), AsSpan(velocities), AsSpan(clusters), quadraticInverse, scratch.AsSpan());
    }
}
