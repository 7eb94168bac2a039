using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>One pass's compulsory memory traffic: bytes read and written per screen pixel (each target touched once; filter taps and repeated reads are assumed to hit the cache).</summary>
    public struct FluidSurfacePassCost
    {
        public string Pass;
        public double BytesPerPixel;
    }

    /// <summary>
    /// Counted memory traffic of the surface passes per screen pixel, for the documentation's cost table and the main
    /// job's report. Formats: depth R32F (4 B), thickness RG32F (8 B), packed normal (4 B), fluid colour RGBA16F (8 B),
    /// URP's opaque colour R11G11B10F (4 B), camera depth 4 B, camera colour read and written by the overlay's blend
    /// (4 + 4 B). A target at 1/k of the resolution costs its bytes times 1/k² per screen pixel: depth at 1 or ½,
    /// thickness at ½, the composite at 1 or ½ (it reads each input at most once per composite pixel). Tile binning is per particle, not per pixel: <see cref="BinningBytesPerParticle"/>.
    /// </summary>
    public static class FluidSurfaceCost
    {
        public const int DepthBytes = 4, ThicknessBytes = 8, NormalBytes = 4, FluidColourBytes = 8, SceneColourBytes = 4, SceneDepthBytes = 4, CameraColourBytes = 4;

        /// <summary>The passes of a frame with <paramref name="settings"/>, in order.</summary>
        public static FluidSurfacePassCost[] Passes(in FluidSurfaceSettings settings)
        {
            double d = 1.0 / (settings.DepthDivisor * settings.DepthDivisor);
            double c = 1.0 / (settings.CompositeDivisor * settings.CompositeDivisor);
            const double t = 1.0 / (FluidSurfaceSettings.ThicknessDivisor * FluidSurfaceSettings.ThicknessDivisor);
            int iterations = settings.Filter == FluidSurfaceFilter.None ? 0 : settings.Iterations;
            int filterPasses = settings.Filter == FluidSurfaceFilter.CurvatureFlow ? iterations : 2 * iterations;
            return new[]
            {
                new FluidSurfacePassCost { Pass = "depth splat (write)", BytesPerPixel = DepthBytes * d },
                new FluidSurfacePassCost { Pass = "thickness splat (write, half resolution)", BytesPerPixel = ThicknessBytes * t },
                new FluidSurfacePassCost { Pass = $"smoothing ({filterPasses} passes, read + write)", BytesPerPixel = filterPasses * 2 * DepthBytes * d },
                new FluidSurfacePassCost { Pass = "normals (read depth, write normal)", BytesPerPixel = (DepthBytes + NormalBytes) * d },
                new FluidSurfacePassCost
                {
                    Pass = "composite (depth, normal, thickness, scene colour and depth; write colour)",
                    BytesPerPixel = (math.min(d, c) * (DepthBytes + NormalBytes) + math.min(t, c) * ThicknessBytes + c * (SceneColourBytes + SceneDepthBytes + FluidColourBytes)),
                },
                new FluidSurfacePassCost { Pass = "overlay (read fluid colour, blend onto the camera colour)", BytesPerPixel = c * FluidColourBytes + 2 * CameraColourBytes },
            };
        }

        /// <summary>Sum of <see cref="Passes"/>.</summary>
        public static double BytesPerPixel(in FluidSurfaceSettings settings)
        {
            double sum = 0;
            foreach (FluidSurfacePassCost p in Passes(settings))
                sum += p.BytesPerPixel;
            return sum;
        }

        /// <summary>
        /// Tile binning per particle: CountTiles and BinParticles read the particle (16 B each), every tile entry costs
        /// a count, a cursor and the entry (4 B each), and both splats read each entry and its particle (4 + 16 B, twice).
        /// </summary>
        public static double BinningBytesPerParticle(double entriesPerParticle) => 2 * 16 + entriesPerParticle * (3 * 4 + 2 * (4 + 16));
    }
}
