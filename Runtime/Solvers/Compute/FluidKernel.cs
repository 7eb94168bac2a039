namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The kernels of <c>Shaders/FluidSolver.compute</c>, named as in HLSL (<c>#pragma kernel</c>): one per pass of
    /// <see cref="FluidPasses"/>, plus the pieces of the counting sort, the scan and emission.
    /// </summary>
    public enum FluidKernel : byte
    {
        ClearStats, BeginStep, ClearCells, Keys, ScanCellBlocks, ScanSumBlocks, AddCellOffsets, AddSumOffsets, Scatter, StableRanks,
        CommitSort, Permute, PermuteWithPrevious, PermuteCopyBack, PermuteCopyBackWithPrevious, Emit, CommitEmit,
        Density, DensityFromNeighbours, SurfaceNormals, Forces, CohesionForces, CopyAToVelocities, CopyBToVelocities,
        CopyVelocitiesToA, ViscosityAToB, ViscosityBToA, Alignment, Advect, Predict, Lambda, Correction, ApplyCorrection,
        VelocityFromPositions, Drain, Collide, PackRender,
    }

    /// <summary>The structured buffers of the fluid kernels; the shader property is "_" + the name.</summary>
    public enum FluidComputeBuffer : byte
    {
        Positions, Velocities, Extras, Previous, PositionsOut, VelocitiesOut, ExtrasOut, PreviousOut,
        Keys, Ranks, CellStart, ScanSums, Order, Densities, Pressures, Neighbours, NeighbourCounts, VectorsA, VectorsB, Stats, Args, Shapes,
        /// <summary>float4 per slot for the fluid renderer: xyz position, w attribute; NaN beyond the live particles (<see cref="FluidKernel.PackRender"/>).</summary>
        RenderParticles,
    }

    /// <summary>
    /// The per-dispatch arguments of the fluid kernels (uint4 loose globals, set before the dispatches that read them);
    /// the shader property is "_" + the name. The step's constants are <see cref="FluidComputeConstants"/>.
    /// </summary>
    public enum FluidComputeGlobal : byte
    {
        /// <summary>x capacity, y spawn count, z scan element count, w scan data offset.</summary>
        Counts,
        /// <summary>x index of the scan level's block totals in <see cref="FluidComputeBuffer.ScanSums"/>.</summary>
        Scan,
    }
}
