namespace SoftBodyDynamics.Solvers
{
    /// <summary>The kernels of Shaders/FluidSurface.compute, in its #pragma order (a test holds the two together).</summary>
    public enum FluidSurfaceKernel
    {
        ClearTiles, CountTiles, ScanTiles, BinParticles, SplatDepth, SplatThickness,
        NarrowRangeX, NarrowRangeY, BilateralX, BilateralY, CurvatureFlow, Normals, Composite,
    }

    /// <summary>The buffers of the surface passes (screen targets are structured buffers, row 0 at the bottom).</summary>
    public enum FluidSurfaceBuffer
    {
        /// <summary>float4 per particle: xyz world position (m), w attribute (temperature, K).</summary>
        Particles,
        /// <summary>uint per tile: particles per tile, then each tile's write cursor.</summary>
        TileCounts,
        /// <summary>uint per tile + 1: first entry of each tile; the last is the total.</summary>
        TileStart,
        /// <summary>uint per entry: particle indices grouped by tile (<see cref="FluidSurfaceConstants.TileCapacity"/>).</summary>
        TileEntries,
        /// <summary>uint × <see cref="FluidSurfaceLayout.StatCount"/>.</summary>
        Stats,
        /// <summary>float per depth pixel: the splat's eye depth, and one side of the smoothing ping-pong.</summary>
        DepthA,
        /// <summary>float per depth pixel: the other side of the smoothing ping-pong.</summary>
        DepthB,
        /// <summary>float2 per thickness pixel: thickness (m), mean attribute (0–1).</summary>
        Thickness,
        /// <summary>uint per depth pixel: octahedral view-space normal.</summary>
        Normals,
    }

    /// <summary>The depth slots a kernel binds by name, which the recorder points at <see cref="FluidSurfaceBuffer.DepthA"/> or <see cref="FluidSurfaceBuffer.DepthB"/>.</summary>
    public enum FluidSurfaceDepthSlot
    {
        /// <summary>_Depth: the splat's output, the normals' and the composite's input.</summary>
        Depth,
        /// <summary>_DepthIn: a filter's input.</summary>
        DepthIn,
        /// <summary>_DepthOut: a filter's output.</summary>
        DepthOut,
    }

    /// <summary>What records the surface passes: Unity's command buffer, or the lavapipe harness.</summary>
    public interface IFluidSurfaceCommands
    {
        /// <summary>
        /// Uploads <paramref name="constants"/> whole (<see cref="FluidSurfaceConstants.Bytes"/> bytes) and binds them as
        /// the kernels' constant buffer <see cref="FluidSurfaceConstants.BufferName"/> for the dispatches that follow.
        /// </summary>
        void SetConstants(in FluidSurfaceConstants constants);
        /// <summary>Points the kernel's depth slot at one of the two depth buffers.</summary>
        void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer);
        void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY);
    }
}
