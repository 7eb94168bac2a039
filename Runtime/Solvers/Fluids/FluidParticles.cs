using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The particles of one fluid as structure-of-arrays views of equal length (the capacity, or particle budget). The
    /// first <see cref="FluidStatus.Count"/> entries are alive; the step keeps them sorted by grid cell. In packed
    /// storage these are the only copy; with one entity per particle the system gathers into them before the step and
    /// scatters back through <see cref="Ids"/> after it. The GPU backend keeps the same arrays with float3 padded to 16 bytes.
    /// </summary>
    public readonly ref struct FluidParticles
    {
        /// <summary>Positions x (m, world).</summary>
        public readonly Span<float3> Positions;
        /// <summary>Velocities v (m/s).</summary>
        public readonly Span<float3> Velocities;
        /// <summary>Time since spawn (s).</summary>
        public readonly Span<float> Ages;
        /// <summary>Lifetime (s): &gt; 0 expires at that age, 0 lives forever, &lt; 0 is marked for removal (a drain or gameplay code killed it).</summary>
        public readonly Span<float> Lifetimes;
        /// <summary>A per-particle attribute carried along (temperature in K for lava looks, or a colour index); the solver does not read it.</summary>
        public readonly Span<float> Attributes;
        /// <summary>Stable identity of a particle (spawn order); maps a sorted slot back to its entity or to gameplay data.</summary>
        public readonly Span<int> Ids;

        public FluidParticles(Span<float3> positions, Span<float3> velocities, Span<float> ages, Span<float> lifetimes,
            Span<float> attributes, Span<int> ids)
        {
            Positions = positions;
            Velocities = velocities;
            Ages = ages;
            Lifetimes = lifetimes;
            Attributes = attributes;
            Ids = ids;
        }

        /// <summary>Slots available (the shortest array).</summary>
        public int Capacity => Math.Min(Math.Min(Math.Min(Positions.Length, Velocities.Length), Math.Min(Ages.Length, Lifetimes.Length)),
            Math.Min(Attributes.Length, Ids.Length));

        /// <summary>Bytes per particle slot of these arrays.</summary>
        public const int BytesPerParticle = 2 * 12 + 3 * 4 + 4;
    }

    /// <summary>
    /// Working arrays of a fluid step (NativeArrays or a managed <see cref="FluidBuffers"/>): per-particle arrays of the
    /// particle capacity and the cell-start table of <see cref="FluidGrid.CellCount"/> + 2 entries.
    /// </summary>
    public readonly ref struct FluidScratch
    {
        /// <summary>Grid key of each particle (or the dead key).</summary>
        public readonly Span<int> Keys;
        /// <summary>Sorted slot → slot before the sort (the permutation the sort applied).</summary>
        public readonly Span<int> Order;
        /// <summary>Integer scratch for reordering.</summary>
        public readonly Span<int> Ints;
        /// <summary>First sorted slot of each cell; entry CellCount + 1 is the number of particles (live and dead).</summary>
        public readonly Span<int> CellStart;
        /// <summary>Density ρ (kg/m³).</summary>
        public readonly Span<float> Densities;
        /// <summary>Pressure p over ρ² times the gradient renormalization κᵢ/κ∇ (weakly compressible, m²/(s²·kg/m³); <see cref="FluidConstants.GradientRenormalization"/>) or the constraint multiplier λ (position-based).</summary>
        public readonly Span<float> Pressures;
        /// <summary>Float scratch for reordering; during the viscosity solve, each particle's viscosity renormalization (0 until the substep's first iteration sets it).</summary>
        public readonly Span<float> Floats;
        /// <summary>Positions at the start of the substep (position-based) or surface normals (Akinci).</summary>
        public readonly Span<float3> Previous;
        /// <summary>Vector scratch: reordering, Jacobi iterates, position corrections.</summary>
        public readonly Span<float3> VectorsA;
        /// <summary>Vector scratch: second Jacobi buffer, Akinci surface normals.</summary>
        public readonly Span<float3> VectorsB;
        /// <summary>Neighbour lists: slot i's neighbours (sorted slots, itself excluded) at [i·MaxNeighbours, i·MaxNeighbours + NeighbourCounts[i]).</summary>
        public readonly Span<int> Neighbours;
        /// <summary>Neighbours found per particle (at most <see cref="MaxNeighbours"/>).</summary>
        public readonly Span<int> NeighbourCounts;

        /// <summary>Most neighbours kept per particle; about 33 at rest with h = 2Δx, so 64 leaves room for 1.9× compression. Extra ones are dropped and counted.</summary>
        public const int MaxNeighbours = 64;

        public FluidScratch(Span<int> keys, Span<int> order, Span<int> ints, Span<int> cellStart, Span<float> densities,
            Span<float> pressures, Span<float> floats, Span<float3> previous, Span<float3> vectorsA, Span<float3> vectorsB,
            Span<int> neighbours, Span<int> neighbourCounts)
        {
            Neighbours = neighbours;
            NeighbourCounts = neighbourCounts;
            Keys = keys;
            Order = order;
            Ints = ints;
            CellStart = cellStart;
            Densities = densities;
            Pressures = pressures;
            Floats = floats;
            Previous = previous;
            VectorsA = vectorsA;
            VectorsB = vectorsB;
        }

        /// <summary>Ints of one flat integer array holding all integer scratch for <paramref name="capacity"/> particles and <paramref name="cellCount"/> cells.</summary>
        public static int FlatInts(int capacity, int cellCount) => capacity * (4 + MaxNeighbours) + cellCount + 2;

        /// <summary>Floats of one flat float array holding all float scratch.</summary>
        public static int FlatFloats(int capacity) => 3 * capacity;

        /// <summary>Vectors of one flat float3 array holding all vector scratch.</summary>
        public static int FlatVectors(int capacity) => 3 * capacity;

        /// <summary>
        /// The scratch as slices of three flat arrays (of at least <see cref="FlatInts"/>, <see cref="FlatFloats"/> and
        /// <see cref="FlatVectors"/> elements): the layout ECS buffers and the GPU backend use.
        /// </summary>
        public static FluidScratch FromFlat(Span<int> ints, Span<float> floats, Span<float3> vectors, int capacity, int cellCount)
        {
            int n = capacity;
            return new FluidScratch(ints.Slice(0, n), ints.Slice(n, n), ints.Slice(2 * n, n), ints.Slice(3 * n, cellCount + 2),
                floats.Slice(0, n), floats.Slice(n, n), floats.Slice(2 * n, n),
                vectors.Slice(0, n), vectors.Slice(n, n), vectors.Slice(2 * n, n),
                ints.Slice(3 * n + cellCount + 2, n * MaxNeighbours), ints.Slice(3 * n + cellCount + 2 + n * MaxNeighbours, n));
        }

        /// <summary>Scratch bytes per particle slot (the cell table comes on top: 4 bytes per cell).</summary>
        public const int BytesPerParticle = 3 * 4 + 3 * 4 + 3 * 12 + (MaxNeighbours + 1) * 4;
    }

    /// <summary>Counters of one fluid that outlive a step (a component in ECS).</summary>
    public struct FluidStatus
    {
        /// <summary>Live particles: slots [0, Count) of <see cref="FluidParticles"/>.</summary>
        public int Count;
        /// <summary>Id the next spawned particle gets.</summary>
        public int NextId;
        /// <summary>Simulated time (s).</summary>
        public double Time;
        /// <summary>Particles spawned so far.</summary>
        public long Spawned;
        /// <summary>Particles removed because a drain or gameplay code marked them (negative lifetime).</summary>
        public long Killed;
        /// <summary>Particles removed because they reached their lifetime.</summary>
        public long Expired;
        /// <summary>Particles removed because their state was not finite (NaN guard).</summary>
        public long Invalid;
    }
}
