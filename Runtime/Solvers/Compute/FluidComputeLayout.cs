using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Per-particle extras on the GPU (8 bytes): the attribute and the id of <see cref="FluidParticles"/>.</summary>
    public struct FluidComputeExtras
    {
        public float Attribute;
        public int Id;
    }

    /// <summary>
    /// The sizes the fluid kernels share with the C# side: thread-group size, stat slots, element strides and lengths of
    /// every <see cref="FluidComputeBuffer"/>, and the levels of the scan.
    /// </summary>
    public static class FluidComputeLayout
    {
        /// <summary>Threads per group of the particle kernels (FLUID_GROUP in FluidCommon.hlsl); the indirect arguments use it.</summary>
        public const int ThreadGroupSize = 256;
        /// <summary>
        /// Most structured buffers one fluid kernel binds (Forces: particles, scratch, neighbours, counters and shapes); a
        /// test checks it against every kernel's reflection. OpenGL ES 3.1 guarantees only 8 per compute shader.
        /// </summary>
        public const int MaxBuffersPerKernel = 11;
        /// <summary>Elements one group of the scan handles (SCAN_BLOCK in FluidScan.hlsl).</summary>
        public const int ScanBlock = 512;

        // _Stats slots (STAT_* in FluidCommon.hlsl).
        public const int StatLive = 0, StatKilled = 1, StatExpired = 2, StatInvalid = 3, StatSpeedClamped = 4, StatOverCompressed = 5,
            StatNeighbourOverflow = 6, StatMaxDensityRatio = 7, StatMaxSpeedSquared = 8, StatContacts = 9,
            StatTotalKilled = 10, StatTotalExpired = 11, StatTotalInvalid = 12, StatMaxHeight = 13, StatMinHeightMirrored = 14, StatCount = 15;

        /// <summary>
        /// <see cref="FluidSolver.Depth"/> from the read-back stats of BeginStep (position-based; 0 when no particle was
        /// measured): heights s ∈ [−L, L] along −g, L the domain's diagonal, kept as max(s + L) and max(L − s).
        /// </summary>
        public static float DepthOf(in FluidConstants c, ReadOnlySpan<uint> stats)
        {
            FluidParameters p = c.Parameters;
            if (p.Solver != FluidSolverKind.PositionBased || stats.Length < StatCount)
                return 0f;
            float top = math.asfloat(stats[StatMaxHeight]), bottom = math.asfloat(stats[StatMinHeightMirrored]);
            if (top == 0f && bottom == 0f)
                return 0f;
            float L = math.length(p.DomainMax - p.DomainMin);
            float depth = top + bottom - 2f * L;
            return math.isfinite(depth) && depth >= 0f ? depth + p.ParticleSpacing : 0f;
        }

        /// <summary>float4s per collider or drain in <see cref="FluidComputeBuffer.Shapes"/> (SHAPE_FLOAT4S in FluidColliders.hlsl).</summary>
        public const int ShapeFloat4s = 5;

        /// <summary>Bytes per element of a buffer.</summary>
        public static int Stride(FluidComputeBuffer buffer)
        {
            switch (buffer)
            {
                case FluidComputeBuffer.Positions: case FluidComputeBuffer.Velocities: case FluidComputeBuffer.Previous:
                case FluidComputeBuffer.PositionsOut: case FluidComputeBuffer.VelocitiesOut: case FluidComputeBuffer.PreviousOut:
                case FluidComputeBuffer.VectorsA: case FluidComputeBuffer.VectorsB: case FluidComputeBuffer.Shapes:
                case FluidComputeBuffer.RenderParticles:
                    return 16;
                case FluidComputeBuffer.Extras: case FluidComputeBuffer.ExtrasOut:
                    return 8;
                default:
                    return 4;
            }
        }

        /// <summary>Elements of a buffer for <paramref name="capacity"/> particles on a grid of <paramref name="cells"/> cells with <paramref name="shapes"/> colliders and drains.</summary>
        public static int Length(FluidComputeBuffer buffer, int capacity, int cells, int shapes)
        {
            capacity = math.max(capacity, 1);
            switch (buffer)
            {
                case FluidComputeBuffer.CellStart: return cells + 2;
                case FluidComputeBuffer.ScanSums: return ScanSumsLength(cells + 2);
                case FluidComputeBuffer.Neighbours: return capacity * FluidScratch.MaxNeighbours;
                case FluidComputeBuffer.Stats: return StatCount;
                case FluidComputeBuffer.Args: return 3;
                case FluidComputeBuffer.Shapes: return ShapeFloat4s * math.max(shapes, 1);
                default: return capacity;
            }
        }

        /// <summary>
        /// The buffers that hold particle state between steps (the rest is rewritten every substep, or does not depend on
        /// the capacity): when the buffers grow, these are copied into the new ones by <see cref="FluidKernel.PermuteCopyBack"/>
        /// with the old buffer bound as its Out partner (<see cref="OutPartner"/>), since a GPU buffer copy needs equal sizes.
        /// </summary>
        public static bool HoldsState(FluidComputeBuffer buffer) =>
            buffer == FluidComputeBuffer.Positions || buffer == FluidComputeBuffer.Velocities || buffer == FluidComputeBuffer.Extras;

        /// <summary>The Out buffer PermuteCopyBack reads for a state buffer.</summary>
        public static FluidComputeBuffer OutPartner(FluidComputeBuffer buffer) => buffer switch
        {
            FluidComputeBuffer.Positions => FluidComputeBuffer.PositionsOut,
            FluidComputeBuffer.Velocities => FluidComputeBuffer.VelocitiesOut,
            FluidComputeBuffer.Extras => FluidComputeBuffer.ExtrasOut,
            _ => buffer,
        };

        /// <summary>The capacity grown by doubling from <paramref name="current"/> (≥ 1) until it holds <paramref name="wanted"/>.</summary>
        public static int GrownCapacity(int current, int wanted)
        {
            long grown = math.max(current, 1);
            while (grown < wanted)
                grown *= 2;
            return (int)math.min(grown, int.MaxValue);
        }

        /// <summary>Most scan levels (512⁴ elements is more than <see cref="FluidGrid.MaxCells"/>).</summary>
        public const int MaxScanLevels = 4;

        /// <summary>
        /// The levels of an inclusive scan of <paramref name="elements"/> values: level 0 is the data, each level above holds
        /// the block totals of the one below, up to the first level of one block. Writes each level's element count and
        /// the index of its block totals in <see cref="FluidComputeBuffer.ScanSums"/>; returns the level count.
        /// </summary>
        public static int ScanLevels(int elements, Span<int> counts, Span<int> sumOffsets)
        {
            int levels = 0, offset = 0, n = math.max(elements, 1);
            while (true)
            {
                int blocks = (n + ScanBlock - 1) / ScanBlock;
                counts[levels] = n;
                sumOffsets[levels] = offset;
                levels++;
                if (blocks <= 1)
                    return levels;
                offset += blocks;
                n = blocks;
            }
        }

        /// <summary>Length of <see cref="FluidComputeBuffer.ScanSums"/> for a scan of <paramref name="elements"/> values.</summary>
        public static int ScanSumsLength(int elements)
        {
            Span<int> counts = stackalloc int[MaxScanLevels];
            Span<int> offsets = stackalloc int[MaxScanLevels];
            int levels = ScanLevels(elements, counts, offsets);
            return offsets[levels - 1] + 1;
        }
    }
}
