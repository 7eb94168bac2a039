using System;
using SoftBodyDynamics.Compute;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// A GPU fluid's tap spawns (<see cref="FluidComputeEmission.Stage"/>) in a staging area of its own, appended on the
    /// GPU (<see cref="FluidComputeSolver.Emit"/>). There is no prewarm on the GPU path.
    /// </summary>
    sealed class FluidComputeSpawns : IDisposable
    {
        NativeArray<float3> m_Positions, m_Velocities, m_ScratchVectors;
        NativeArray<float> m_Ages, m_Lifetimes, m_Attributes, m_ScratchFloats;
        NativeArray<int> m_Ids, m_ScratchInts;
        NativeArray<float4> m_PackedPositions, m_PackedVelocities;
        NativeArray<FluidComputeExtras> m_PackedExtras;
        readonly int m_Capacity, m_Cells;

        /// <summary>Staging for up to <paramref name="capacity"/> spawns per step on a grid of <paramref name="cells"/> cells.</summary>
        public FluidComputeSpawns(int capacity, int cells)
        {
            m_Capacity = math.max(1, capacity);
            m_Cells = cells;
            m_Positions = new NativeArray<float3>(m_Capacity, Allocator.Persistent);
            m_Velocities = new NativeArray<float3>(m_Capacity, Allocator.Persistent);
            m_Ages = new NativeArray<float>(m_Capacity, Allocator.Persistent);
            m_Lifetimes = new NativeArray<float>(m_Capacity, Allocator.Persistent);
            m_Attributes = new NativeArray<float>(m_Capacity, Allocator.Persistent);
            m_Ids = new NativeArray<int>(m_Capacity, Allocator.Persistent);
            m_ScratchInts = new NativeArray<int>(FluidScratch.FlatInts(m_Capacity, cells), Allocator.Persistent);
            m_ScratchFloats = new NativeArray<float>(FluidScratch.FlatFloats(m_Capacity), Allocator.Persistent);
            m_ScratchVectors = new NativeArray<float3>(FluidScratch.FlatVectors(m_Capacity), Allocator.Persistent);
            m_PackedPositions = new NativeArray<float4>(m_Capacity, Allocator.Persistent);
            m_PackedVelocities = new NativeArray<float4>(m_Capacity, Allocator.Persistent);
            m_PackedExtras = new NativeArray<FluidComputeExtras>(m_Capacity, Allocator.Persistent);
        }

        /// <summary>
        /// Runs the fluid's taps for <paramref name="dt"/> into the staging area and appends what they placed on the GPU;
        /// the fluid's spawn total and next id advance. Returns the frame report (spawned, held back, dropped).
        /// </summary>
        public FluidFrameReport Emit(EntityManager m, Entity fluid, in FluidConstants constants, ref FluidRuntime runtime, FluidComputeSolver solver,
            NativeArray<FluidTap> taps, NativeArray<Entity> tapEntities, int budget, float dt)
        {
            FluidEntityArrays a = FluidSimulationSystem.Arrays(m, fluid);
            var staging = new FluidParticles(m_Positions.AsSpan(), m_Velocities.AsSpan(), m_Ages.AsSpan(), m_Lifetimes.AsSpan(),
                m_Attributes.AsSpan(), m_Ids.AsSpan());
            FluidScratch scratch = FluidScratch.FromFlat(m_ScratchInts.AsSpan(), m_ScratchFloats.AsSpan(), m_ScratchVectors.AsSpan(), m_Capacity, m_Cells);
            var tapSet = FluidTapSet.Collect(fluid, a.Taps, taps, tapEntities);
            FluidFrameReport report = FluidComputeEmission.Stage(constants, tapSet.Instances, tapSet.Bursts, budget - solver.LastKnownCount, dt,
                staging, scratch, ref runtime.Status, out int spawned);
            tapSet.Store(a.Taps);
            tapSet.Dispose();
            FluidComputeStep.Pack(staging, spawned, m_PackedPositions.AsSpan(), m_PackedVelocities.AsSpan(), m_PackedExtras.AsSpan());
            solver.Emit(m_PackedPositions, m_PackedVelocities, m_PackedExtras, spawned);
            return report;
        }

        public void Dispose()
        {
            m_Positions.Dispose(); m_Velocities.Dispose(); m_Ages.Dispose(); m_Lifetimes.Dispose(); m_Attributes.Dispose(); m_Ids.Dispose();
            m_ScratchInts.Dispose(); m_ScratchFloats.Dispose(); m_ScratchVectors.Dispose();
            m_PackedPositions.Dispose(); m_PackedVelocities.Dispose(); m_PackedExtras.Dispose();
        }
    }
}
