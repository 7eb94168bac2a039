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

    /// <summary>The constants of the fluid kernels (float4 or int4 globals); the shader property is "_" + the name.</summary>
    public enum FluidComputeGlobal : byte
    {
        GridOrigin, GridDims, DomainMin, DomainMax, Gravity, Kernel, Kernel2, Material, Motion, Cohesion, Smoothing, Flags, Counts, Scan, ShapeCounts, Colliding,
        Period, InversePeriod, NoSlip, Renormalization,
    }
}
