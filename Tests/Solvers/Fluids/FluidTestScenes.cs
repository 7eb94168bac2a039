using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Small fluids for the tests.</summary>
    static class FluidTestScenes
    {
        /// <summary>Water at <paramref name="spacing"/> in the box [min, max] (speed of sound 10 m/s).</summary>
        public static FluidParameters Water(float spacing, float3 min, float3 max)
        {
            FluidParameters p = FluidParameters.Default;
            p.ParticleSpacing = spacing;
            p.DomainMin = min;
            p.DomainMax = max;
            return p;
        }

        /// <summary>Buffers for <paramref name="capacity"/> particles with a lattice block [lo, hi) at the spacing.</summary>
        public static FluidBuffers Block(in FluidConstants c, int capacity, float3 lo, float3 hi)
        {
            var b = new FluidBuffers(capacity, c.Grid);
            float dx = c.Parameters.ParticleSpacing;
            int n = 0;
            for (float z = lo.z + dx / 2; z < hi.z; z += dx)
            for (float y = lo.y + dx / 2; y < hi.y; y += dx)
            for (float x = lo.x + dx / 2; x < hi.x && n < capacity; x += dx)
            {
                b.Positions[n] = new float3(x, y, z);
                b.Ids[n] = n;
                n++;
            }
            b.Status.Count = n;
            b.Status.NextId = n;
            b.Status.Spawned = n;
            return b;
        }

        /// <summary>Two fluids with the same block, for tests that run them two ways and compare the bits.</summary>
        public static (FluidBuffers, FluidBuffers) Twins(in FluidConstants c, int capacity, float3 lo, float3 hi) =>
            (Block(c, capacity, lo, hi), Block(c, capacity, lo, hi));

        public static FluidStepReport Step(in FluidConstants c, FluidBuffers b, float dt) =>
            FluidSolver.Step(c, default, dt, b.Particles, b.Scratch, ref b.Status);

        public static FluidStepReport Step(in FluidConstants c, FluidBuffers b, float dt, ColliderShape[] colliders) =>
            FluidSolver.Step(c, colliders, dt, b.Particles, b.Scratch, ref b.Status);
    }
}
