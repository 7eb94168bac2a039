using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>One pass's compulsory memory traffic: bytes read and written per screen pixel (each target touched once; filter taps and repeated reads are assumed to hit the cache).</summary>
    public struct FluidSurfacePassCost
    {
        public FluidSurfaceStage Stage;
        public string Pass;
        public double BytesPerPixel;
    }

    /// <summary>
    /// Counted memory traffic of the surface passes per screen pixel, for the documentation's cost table and the main
    /// job's report. Formats: depth R32F (4 B), thickness RG32F (8 B), packed normal (4 B), fluid colour RGBA16F (8 B),
    /// URP's opaque colour R11G11B10F (4 B), camera depth 4 B, camera colour read and written by the overlay's blend
    /// (4 + 4 B). A target at 1/k of the resolution costs its bytes times 1/k² per screen pixel: depth at 1 or ½,
    /// thickness at ½, the composite at 1 or ½ (it reads each input it needs at most once per composite pixel). Tile binning is per particle, not per pixel: <see cref="BinningBytesPerParticle"/>.
    /// </summary>
    public static class FluidSurfaceCost
    {
        public const int DepthBytes = 4, ThicknessBytes = 8, NormalBytes = 4, FluidColourBytes = 8, SceneColourBytes = 4, SceneDepthBytes = 4, CameraColourBytes = 4;

        /// <summary>The passes of a frame with these settings and this look, in order (<see cref="FluidSurfacePassList.Of"/>).</summary>
        public static FluidSurfacePassCost[] Passes(in FluidSurfaceSettings settings, in FluidLook look) => Passes(FluidSurfacePassList.Of(settings, look));

        /// <summary>The passes <paramref name="passes"/> runs, in order: a pass that is off is not listed, and the composite reads only the targets the list has.</summary>
        public static FluidSurfacePassCost[] Passes(in FluidSurfacePassList passes)
        {
            double d = 1.0 / (passes.DepthDivisor * passes.DepthDivisor);
            double c = 1.0 / (passes.CompositeDivisor * passes.CompositeDivisor);
            const double t = 1.0 / (FluidSurfaceSettings.ThicknessDivisor * FluidSurfaceSettings.ThicknessDivisor);
            int filterPasses = passes.SmoothingPasses;
            var list = new FluidSurfacePassCost[Count(passes)];
            int n = 0;
            list[n++] = new FluidSurfacePassCost { Stage = FluidSurfaceStage.DepthSplat, Pass = "depth splat (write)", BytesPerPixel = DepthBytes * d };
            if (passes.Thickness)
                list[n++] = new FluidSurfacePassCost { Stage = FluidSurfaceStage.ThicknessSplat, Pass = "thickness splat (write, half resolution)", BytesPerPixel = ThicknessBytes * t };
            if (filterPasses > 0)
                list[n++] = new FluidSurfacePassCost { Stage = FluidSurfaceStage.Smoothing, Pass = $"smoothing ({filterPasses} passes, read + write)", BytesPerPixel = filterPasses * 2 * DepthBytes * d };
            if (passes.Normals)
                list[n++] = new FluidSurfacePassCost { Stage = FluidSurfaceStage.Normals, Pass = "normals (read depth, write normal)", BytesPerPixel = (DepthBytes + NormalBytes) * d };
            list[n++] = new FluidSurfacePassCost
            {
                Stage = FluidSurfaceStage.Composite,
                Pass = "composite (" + (passes.Normals ? "depth, normal" : "depth") + (passes.Thickness ? ", thickness" : "") + ", scene colour and depth; write colour)",
                BytesPerPixel = math.min(d, c) * (DepthBytes + (passes.Normals ? NormalBytes : 0)) + (passes.Thickness ? math.min(t, c) * ThicknessBytes : 0)
                    + c * (SceneColourBytes + SceneDepthBytes + FluidColourBytes),
            };
            list[n] = new FluidSurfacePassCost { Stage = FluidSurfaceStage.Overlay, Pass = "overlay (read fluid colour, blend onto the camera colour)", BytesPerPixel = c * FluidColourBytes + 2 * CameraColourBytes };
            return list;
        }

        static int Count(in FluidSurfacePassList passes) =>
            3 + (passes.Thickness ? 1 : 0) + (passes.SmoothingPasses > 0 ? 1 : 0) + (passes.Normals ? 1 : 0);

        /// <summary>Sum of <see cref="Passes(in FluidSurfacePassList)"/>.</summary>
        public static double BytesPerPixel(in FluidSurfacePassList passes)
        {
            double sum = 0;
            foreach (FluidSurfacePassCost p in Passes(passes))
                sum += p.BytesPerPixel;
            return sum;
        }

        /// <summary>Sum of <see cref="Passes(in FluidSurfaceSettings, in FluidLook)"/>.</summary>
        public static double BytesPerPixel(in FluidSurfaceSettings settings, in FluidLook look) => BytesPerPixel(FluidSurfacePassList.Of(settings, look));

        /// <summary>
        /// Tile binning per particle: CountTiles and BinParticles read the particle (16 B each), every tile entry costs
        /// a count, a cursor and the entry (4 B each), and both splats read each entry and its particle (4 + 16 B, twice).
        /// </summary>
        public static double BinningBytesPerParticle(double entriesPerParticle) => 2 * 16 + entriesPerParticle * (3 * 4 + 2 * (4 + 16));
    }
}
