using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The surface passes of one frame, recorded against <see cref="IFluidSurfaceCommands"/> as
    /// <see cref="FluidSurfacePassList"/> lists them (a pass that is off is not dispatched): the same list in Unity (render
    /// graph compute passes), in the lavapipe harness and in the C# reference frame. Smoothing ping-pongs between the two
    /// depth buffers; <see cref="SmoothedDepth"/> says where the result ends.
    /// </summary>
    public static class FluidSurfaceFrame
    {
        /// <summary>The buffer holding the smoothed depth after the list's filter.</summary>
        public static FluidSurfaceBuffer SmoothedDepth(in FluidSurfacePassList passes) =>
            passes.Filter == FluidSurfaceFilter.CurvatureFlow && passes.Iterations % 2 == 1 ? FluidSurfaceBuffer.DepthB : FluidSurfaceBuffer.DepthA;

        /// <summary>Groups of <paramref name="size"/> threads covering <paramref name="n"/> (at least one).</summary>
        public static int Groups(int n, int size) => math.max(1, (n + size - 1) / size);

        /// <summary>Records the tile lists and the splats (everything before smoothing); the thickness splat only when the list has it.</summary>
        public static void RecordSplats<T>(ref T commands, in FluidSurfaceTargets targets, in FluidSurfacePassList passes, int particles)
            where T : IFluidSurfaceCommands
        {
            commands.Dispatch(FluidSurfaceKernel.ClearTiles, Groups(math.max(targets.TileCount, FluidSurfaceLayout.StatCount), FluidSurfaceLayout.ScanGroup), 1);
            commands.Dispatch(FluidSurfaceKernel.CountTiles, Groups(particles, FluidSurfaceLayout.ParticleGroup), 1);
            commands.Dispatch(FluidSurfaceKernel.ScanTiles, 1, 1);
            commands.Dispatch(FluidSurfaceKernel.BinParticles, Groups(particles, FluidSurfaceLayout.ParticleGroup), 1);
            commands.BindDepth(FluidSurfaceKernel.SplatDepth, FluidSurfaceDepthSlot.Depth, FluidSurfaceBuffer.DepthA);
            commands.Dispatch(FluidSurfaceKernel.SplatDepth, targets.Tiles.x, targets.Tiles.y);
            if (passes.Thickness)
                commands.Dispatch(FluidSurfaceKernel.SplatThickness, targets.Tiles.x, targets.Tiles.y);
        }

        /// <summary>Records the smoothing passes (after the splats); returns the buffer holding the result.</summary>
        public static FluidSurfaceBuffer RecordSmoothing<T>(ref T commands, in FluidSurfaceTargets targets, in FluidSurfacePassList passes)
            where T : IFluidSurfaceCommands
        {
            int gx = Groups(targets.Depth.x, FluidSurfaceLayout.TileGroup), gy = Groups(targets.Depth.y, FluidSurfaceLayout.TileGroup);
            FluidSurfaceBuffer current = FluidSurfaceBuffer.DepthA, other = FluidSurfaceBuffer.DepthB;
            for (int i = 0; i < passes.Iterations && passes.Filter != FluidSurfaceFilter.None; i++)
            {
                if (passes.Filter == FluidSurfaceFilter.CurvatureFlow)
                {
                    Filter(ref commands, FluidSurfaceKernel.CurvatureFlow, current, other, gx, gy);
                    (current, other) = (other, current);
                    continue;
                }
                bool narrow = passes.Filter == FluidSurfaceFilter.NarrowRange;
                Filter(ref commands, narrow ? FluidSurfaceKernel.NarrowRangeX : FluidSurfaceKernel.BilateralX, current, other, gx, gy);
                Filter(ref commands, narrow ? FluidSurfaceKernel.NarrowRangeY : FluidSurfaceKernel.BilateralY, other, current, gx, gy);
            }
            return current;
        }

        /// <summary>Records normals (when the list has them) and the composite, reading the smoothed depth from <paramref name="depth"/>.</summary>
        public static void RecordShading<T>(ref T commands, in FluidSurfaceTargets targets, in FluidSurfacePassList passes, FluidSurfaceBuffer depth)
            where T : IFluidSurfaceCommands
        {
            if (passes.Normals)
            {
                commands.BindDepth(FluidSurfaceKernel.Normals, FluidSurfaceDepthSlot.Depth, depth);
                commands.Dispatch(FluidSurfaceKernel.Normals, Groups(targets.Depth.x, FluidSurfaceLayout.TileGroup), Groups(targets.Depth.y, FluidSurfaceLayout.TileGroup));
            }
            commands.BindDepth(FluidSurfaceKernel.Composite, FluidSurfaceDepthSlot.Depth, depth);
            commands.Dispatch(FluidSurfaceKernel.Composite, Groups(targets.Composite.x, FluidSurfaceLayout.TileGroup), Groups(targets.Composite.y, FluidSurfaceLayout.TileGroup));
        }

        /// <summary>The whole frame: splats, smoothing, normals, composite, as <paramref name="passes"/> lists them.</summary>
        public static void Record<T>(ref T commands, in FluidSurfaceTargets targets, in FluidSurfacePassList passes, int particles)
            where T : IFluidSurfaceCommands
        {
            RecordSplats(ref commands, targets, passes, particles);
            FluidSurfaceBuffer depth = RecordSmoothing(ref commands, targets, passes);
            RecordShading(ref commands, targets, passes, depth);
        }

        static void Filter<T>(ref T commands, FluidSurfaceKernel kernel, FluidSurfaceBuffer input, FluidSurfaceBuffer output, int gx, int gy)
            where T : IFluidSurfaceCommands
        {
            commands.BindDepth(kernel, FluidSurfaceDepthSlot.DepthIn, input);
            commands.BindDepth(kernel, FluidSurfaceDepthSlot.DepthOut, output);
            commands.Dispatch(kernel, gx, gy);
        }
    }
}
