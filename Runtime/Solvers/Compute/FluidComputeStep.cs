using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Records a fluid step as GPU dispatches: the same passes as <see cref="FluidSolver.Step(in FluidConstants, ReadOnlySpan{ColliderShape}, float, FluidParticles, FluidScratch, ref FluidStatus)"/>,
    /// in the order of <see cref="FluidSubstepPasses.Write"/>, each <see cref="FluidPass"/> one kernel (the sort several).
    /// The live count stays on the GPU (<see cref="FluidComputeLayout.StatLive"/>); kernels over particles are dispatched
    /// indirectly. Used by Unity's dispatch class and by the lavapipe harness alike.
    /// </summary>
    public static class FluidComputeStep
    {
        /// <summary>Zeroes the step's counters, ages the particles by dt and finds the fastest speed (read back for the substeps).</summary>
        public static void RecordBegin<T>(ref T commands, in FluidComputeConstants constants) where T : IFluidComputeCommands
        {
            commands.BindBuffers();
            commands.SetConstants(constants);
            commands.Dispatch(FluidKernel.ClearStats, FluidComputeLayout.StatCount);
            commands.DispatchIndirect(FluidKernel.BeginStep);
        }

        /// <summary>
        /// Appends <paramref name="spawnCount"/> particles the caller wrote at the start of the Out buffers (positions with
        /// age in w, velocities with lifetime in w, extras) after the live ones, up to <paramref name="capacity"/>.
        /// </summary>
        public static void RecordEmit<T>(ref T commands, int spawnCount, int capacity) where T : IFluidComputeCommands
        {
            if (spawnCount <= 0)
                return;
            commands.BindBuffers();
            commands.SetInts(FluidComputeGlobal.Counts, new int4(capacity, spawnCount, 0, 0));
            commands.Dispatch(FluidKernel.Emit, spawnCount);
            commands.Dispatch(FluidKernel.CommitEmit, 1);
        }

        /// <summary>
        /// Writes <see cref="FluidComputeBuffer.RenderParticles"/> for the fluid renderer: every slot up to
        /// <paramref name="capacity"/>, the live ones as position and attribute, the rest NaN (the renderer culls them),
        /// so the renderer needs no live count on the CPU.
        /// </summary>
        public static void RecordPackRender<T>(ref T commands, int capacity) where T : IFluidComputeCommands
        {
            commands.BindBuffers();
            commands.SetInts(FluidComputeGlobal.Counts, new int4(capacity, 0, 0, 0));
            commands.Dispatch(FluidKernel.PackRender, capacity);
        }

        /// <summary>
        /// Marks the live particles inside a drain (<see cref="FluidDrain.Apply"/>): the next sort removes them. The drains
        /// are the shapes after the colliders in <see cref="FluidComputeBuffer.Shapes"/> (<see cref="FluidComputeConstants.DrainCount"/>).
        /// </summary>
        public static void RecordDrain<T>(ref T commands, in FluidComputeConstants constants) where T : IFluidComputeCommands
        {
            if (constants.DrainCount == 0)
                return;
            commands.BindBuffers();
            commands.SetConstants(constants);
            commands.DispatchIndirect(FluidKernel.Drain);
        }

        /// <summary>
        /// Records <paramref name="substeps"/> substeps of the passes <paramref name="passes"/> (from
        /// <see cref="FluidSubstepPasses.Write"/>) with the constants of the substep length.
        /// </summary>
        public static void RecordSubsteps<T>(ref T commands, in FluidConstants c, in FluidComputeConstants constants, int substeps,
            ReadOnlySpan<FluidPass> passes) where T : IFluidComputeCommands
        {
            commands.SetConstants(constants);
            for (int s = 0; s < substeps; s++)
                for (int q = 0; q < passes.Length; q++)
                    RecordPass(ref commands, c, passes[q]);
        }

        /// <summary>One pass: its kernel over the live particles, or the sort's chain of kernels.</summary>
        public static void RecordPass<T>(ref T commands, in FluidConstants c, FluidPass pass) where T : IFluidComputeCommands
        {
            switch (pass)
            {
                case FluidPass.Sort: RecordSort(ref commands, c.Grid.CellCount, false); return;
                case FluidPass.SortWithPrevious: RecordSort(ref commands, c.Grid.CellCount, true); return;
            }
            commands.DispatchIndirect(KernelOf(pass));
        }

        /// <summary>The kernel of a range pass.</summary>
        public static FluidKernel KernelOf(FluidPass pass)
        {
            switch (pass)
            {
                case FluidPass.Density: return FluidKernel.Density;
                case FluidPass.DensityFromNeighbours: return FluidKernel.DensityFromNeighbours;
                case FluidPass.SurfaceNormals: return FluidKernel.SurfaceNormals;
                case FluidPass.Forces: return FluidKernel.Forces;
                case FluidPass.CohesionForces: return FluidKernel.CohesionForces;
                case FluidPass.CopyAToVelocities: return FluidKernel.CopyAToVelocities;
                case FluidPass.CopyVelocitiesToA: return FluidKernel.CopyVelocitiesToA;
                case FluidPass.ViscosityAToB: return FluidKernel.ViscosityAToB;
                case FluidPass.ViscosityBToA: return FluidKernel.ViscosityBToA;
                case FluidPass.CopyBToVelocities: return FluidKernel.CopyBToVelocities;
                case FluidPass.Alignment: return FluidKernel.Alignment;
                case FluidPass.Advect: return FluidKernel.Advect;
                case FluidPass.Predict: return FluidKernel.Predict;
                case FluidPass.Lambda: return FluidKernel.Lambda;
                case FluidPass.Correction: return FluidKernel.Correction;
                case FluidPass.ApplyCorrection: return FluidKernel.ApplyCorrection;
                case FluidPass.VelocityFromPositions: return FluidKernel.VelocityFromPositions;
                case FluidPass.Collide: return FluidKernel.Collide;
                default: throw new ArgumentOutOfRangeException(nameof(pass), pass, "not a range pass");
            }
        }

        /// <summary>
        /// The counting sort (FluidPasses.Keys, Sort, and the permutation of FluidSolver.SortParticles): histogram with
        /// atomic ranks, multi-level scan, scatter, stable ranks and a second scatter (so the order is the CPU's stable one), the live count
        /// (dead keys fall off the end: the stream compaction), then gather and copy back.
        /// </summary>
        public static void RecordSort<T>(ref T commands, int cells, bool previous) where T : IFluidComputeCommands
        {
            int elements = cells + 2;
            commands.SetInts(FluidComputeGlobal.Counts, new int4(0, 0, elements, 0));
            commands.Dispatch(FluidKernel.ClearCells, elements);
            commands.DispatchIndirect(FluidKernel.Keys);
            RecordScan(ref commands, elements);
            commands.DispatchIndirect(FluidKernel.Scatter);
            commands.DispatchIndirect(FluidKernel.StableRanks);
            commands.DispatchIndirect(FluidKernel.Scatter);
            commands.Dispatch(FluidKernel.CommitSort, 1);
            commands.DispatchIndirect(previous ? FluidKernel.PermuteWithPrevious : FluidKernel.Permute);
            commands.DispatchIndirect(previous ? FluidKernel.PermuteCopyBackWithPrevious : FluidKernel.PermuteCopyBack);
        }

        /// <summary>Inclusive scan of the first <paramref name="elements"/> entries of the cell table, level by level (FluidScan.hlsl).</summary>
        public static void RecordScan<T>(ref T commands, int elements) where T : IFluidComputeCommands
        {
            Span<int> counts = stackalloc int[FluidComputeLayout.MaxScanLevels];
            Span<int> sums = stackalloc int[FluidComputeLayout.MaxScanLevels];
            int levels = FluidComputeLayout.ScanLevels(elements, counts, sums);
            // Up: scan every level's blocks, writing the block totals to the level above.
            for (int l = 0; l < levels; l++)
            {
                int dataOffset = l == 0 ? 0 : sums[l - 1];
                commands.SetInts(FluidComputeGlobal.Counts, new int4(0, 0, counts[l], dataOffset));
                commands.SetInts(FluidComputeGlobal.Scan, new int4(sums[l], 0, 0, 0));
                int blocks = (counts[l] + FluidComputeLayout.ScanBlock - 1) / FluidComputeLayout.ScanBlock;
                commands.Dispatch(l == 0 ? FluidKernel.ScanCellBlocks : FluidKernel.ScanSumBlocks, blocks * (FluidComputeLayout.ScanBlock / 2));
            }
            // Down: add the scanned totals of the blocks before each block, from the level below the top to the cells.
            for (int l = levels - 2; l >= 0; l--)
            {
                int dataOffset = l == 0 ? 0 : sums[l - 1];
                commands.SetInts(FluidComputeGlobal.Counts, new int4(0, 0, counts[l], dataOffset));
                commands.SetInts(FluidComputeGlobal.Scan, new int4(sums[l], 0, 0, 0));
                commands.Dispatch(l == 0 ? FluidKernel.AddCellOffsets : FluidKernel.AddSumOffsets, counts[l]);
            }
        }

        /// <summary>
        /// Packs the first <paramref name="count"/> particles into the GPU layout: position with age in w, velocity with
        /// lifetime in w, extras.
        /// </summary>
        public static void Pack(FluidParticles p, int count, Span<float4> positions, Span<float4> velocities, Span<FluidComputeExtras> extras)
        {
            for (int i = 0; i < count; i++)
            {
                positions[i] = new float4(p.Positions[i], p.Ages[i]);
                velocities[i] = new float4(p.Velocities[i], p.Lifetimes[i]);
                extras[i] = new FluidComputeExtras { Attribute = p.Attributes[i], Id = p.Ids[i] };
            }
        }

        /// <summary>
        /// Packs colliders then drains into the shape buffer layout (<see cref="FluidComputeLayout.ShapeFloat4s"/> float4s
        /// each: type bits and radius, centre, axis, rotation, half extents). Returns the float4s written.
        /// </summary>
        public static int PackShapes(ReadOnlySpan<ColliderShape> colliders, ReadOnlySpan<FluidDrain> drains, Span<float4> destination)
        {
            int n = 0;
            for (int i = 0; i < colliders.Length; i++)
                n = PackShape(colliders[i], destination, n);
            for (int i = 0; i < drains.Length; i++)
                n = PackShape(drains[i].Shape, destination, n);
            return n;
        }

        static int PackShape(in ColliderShape s, Span<float4> destination, int n)
        {
            destination[n++] = new float4(math.asfloat((uint)s.Type), s.Radius, 0f, 0f);
            destination[n++] = new float4(s.Center, 0f);
            destination[n++] = new float4(s.Axis, 0f);
            destination[n++] = s.Rotation.value;
            destination[n++] = new float4(s.HalfExtents, 0f);
            return n;
        }

        /// <summary>The inverse of <see cref="Pack"/>.</summary>
        public static void Unpack(ReadOnlySpan<float4> positions, ReadOnlySpan<float4> velocities, ReadOnlySpan<FluidComputeExtras> extras,
            int count, FluidParticles p)
        {
            for (int i = 0; i < count; i++)
            {
                p.Positions[i] = positions[i].xyz;
                p.Ages[i] = positions[i].w;
                p.Velocities[i] = velocities[i].xyz;
                p.Lifetimes[i] = velocities[i].w;
                p.Attributes[i] = extras[i].Attribute;
                p.Ids[i] = extras[i].Id;
            }
        }
    }
}
