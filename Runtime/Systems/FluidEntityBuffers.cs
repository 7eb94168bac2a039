using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>The solver's views of a fluid entity's buffers (no copies), their sizing, and the tap-state lookup.</summary>
    static class FluidEntityBuffers
    {
        /// <summary>Sizes every particle buffer to <paramref name="budget"/> and the scratch to its flat layout (<see cref="FluidScratch.FromFlat"/>).</summary>
        public static void Resize(int budget, int cellCount, DynamicBuffer<FluidPosition> positions, DynamicBuffer<FluidVelocity> velocities,
            DynamicBuffer<FluidAge> ages, DynamicBuffer<FluidLifetime> lifetimes, DynamicBuffer<FluidAttribute> attributes,
            DynamicBuffer<FluidId> ids, DynamicBuffer<FluidScratchInt> ints, DynamicBuffer<FluidScratchFloat> floats,
            DynamicBuffer<FluidScratchVector> vectors)
        {
            positions.ResizeUninitialized(budget);
            velocities.ResizeUninitialized(budget);
            ages.ResizeUninitialized(budget);
            lifetimes.ResizeUninitialized(budget);
            attributes.ResizeUninitialized(budget);
            ids.ResizeUninitialized(budget);
            ints.ResizeUninitialized(FluidScratch.FlatInts(budget, cellCount));
            floats.ResizeUninitialized(FluidScratch.FlatFloats(budget));
            vectors.ResizeUninitialized(FluidScratch.FlatVectors(budget));
        }

        public static FluidParticles Particles(DynamicBuffer<FluidPosition> positions, DynamicBuffer<FluidVelocity> velocities,
            DynamicBuffer<FluidAge> ages, DynamicBuffer<FluidLifetime> lifetimes, DynamicBuffer<FluidAttribute> attributes,
            DynamicBuffer<FluidId> ids) => new FluidParticles(
            positions.Reinterpret<float3>().AsNativeArray().AsSpan(), velocities.Reinterpret<float3>().AsNativeArray().AsSpan(),
            ages.Reinterpret<float>().AsNativeArray().AsSpan(), lifetimes.Reinterpret<float>().AsNativeArray().AsSpan(),
            attributes.Reinterpret<float>().AsNativeArray().AsSpan(), ids.Reinterpret<int>().AsNativeArray().AsSpan());

        public static FluidScratch Scratch(DynamicBuffer<FluidScratchInt> ints, DynamicBuffer<FluidScratchFloat> floats,
            DynamicBuffer<FluidScratchVector> vectors, int budget, int cellCount) => FluidScratch.FromFlat(
            ints.Reinterpret<int>().AsNativeArray().AsSpan(), floats.Reinterpret<float>().AsNativeArray().AsSpan(),
            vectors.Reinterpret<float3>().AsNativeArray().AsSpan(), budget, cellCount);

        /// <summary>The index of <paramref name="tap"/>'s state in the fluid's tap buffer, appending a fresh state for a new tap.</summary>
        public static int TapSlot(DynamicBuffer<FluidTapRuntime> runtime, Entity tap)
        {
            for (int i = 0; i < runtime.Length; i++)
                if (runtime[i].Tap == tap)
                    return i;
            int slot = runtime.Length;
            runtime.ResizeUninitialized(slot + 1);
            runtime[slot] = new FluidTapRuntime { Tap = tap, State = default };
            return slot;
        }
    }
}
