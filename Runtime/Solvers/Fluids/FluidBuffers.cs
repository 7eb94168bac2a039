using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Managed arrays for one fluid of a fixed capacity and grid (tests, benchmarks, bake-time tools). ECS and Burst
    /// code hold the same arrays as NativeArrays and build the two views the same way.
    /// </summary>
    public sealed class FluidBuffers
    {
        public readonly float3[] Positions, Velocities, Previous, VectorsA, VectorsB;
        public readonly float[] Ages, Lifetimes, Attributes, Densities, Pressures, Floats;
        public readonly int[] Ids, Keys, Order, Ints, CellStart, Neighbours, NeighbourCounts;
        public FluidStatus Status;

        /// <summary>Arrays for <paramref name="capacity"/> particles on <paramref name="grid"/>.</summary>
        public FluidBuffers(int capacity, in FluidGrid grid)
        {
            Positions = new float3[capacity];
            Velocities = new float3[capacity];
            Previous = new float3[capacity];
            VectorsA = new float3[capacity];
            VectorsB = new float3[capacity];
            Ages = new float[capacity];
            Lifetimes = new float[capacity];
            Attributes = new float[capacity];
            Densities = new float[capacity];
            Pressures = new float[capacity];
            Floats = new float[capacity];
            Ids = new int[capacity];
            Keys = new int[capacity];
            Order = new int[capacity];
            Ints = new int[capacity];
            CellStart = new int[grid.CellCount + 2];
            Neighbours = new int[capacity * FluidScratch.MaxNeighbours];
            NeighbourCounts = new int[capacity];
        }

        /// <summary>Arrays for <paramref name="capacity"/> particles of a fluid with parameters <paramref name="parameters"/>.</summary>
        public FluidBuffers(int capacity, in FluidParameters parameters) : this(capacity, FluidConstants.GridOf(parameters.Sanitized())) { }

        public int Capacity => Positions.Length;

        public FluidParticles Particles => new FluidParticles(Positions, Velocities, Ages, Lifetimes, Attributes, Ids);

        public FluidScratch Scratch => new FluidScratch(Keys, Order, Ints, CellStart, Densities, Pressures, Floats, Previous, VectorsA, VectorsB, Neighbours, NeighbourCounts);

        /// <summary>Bytes per particle slot of all arrays (the cell table comes on top: 4 bytes per cell).</summary>
        public const int BytesPerParticle = FluidParticles.BytesPerParticle + FluidScratch.BytesPerParticle;
    }
}
