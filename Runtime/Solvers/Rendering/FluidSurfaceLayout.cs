using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>The sizes the surface kernels share with the C# side (FluidSurfaceCommon.hlsl's SURFACE_* defines).</summary>
    public static class FluidSurfaceLayout
    {
        /// <summary>Threads per group of the particle kernels.</summary>
        public const int ParticleGroup = 64;
        /// <summary>Depth pixels per tile side.</summary>
        public const int TileSize = 16;
        /// <summary>Threads per side of the tile and pixel kernels (8 × 8).</summary>
        public const int TileGroup = 8;
        /// <summary>Threads of the one-group tile scan.</summary>
        public const int ScanGroup = 256;
        /// <summary>Most storage buffers any surface kernel binds (checked against the kernels' reflection on lavapipe).</summary>
        public const int MaxBuffersPerKernel = 6;

        public const int StatEntries = 0, StatDropped = 1, StatDrawn = 2, StatCount = 4;

        /// <summary>
        /// The shader name of each <see cref="FluidSurfaceBuffer"/> (FluidSurfaceCommon.hlsl), bound by name to every
        /// kernel; null for <see cref="FluidSurfaceBuffer.DepthA"/> and <see cref="FluidSurfaceBuffer.DepthB"/>, which the
        /// recorder binds to the depth slots (<see cref="DepthSlotNames"/>).
        /// </summary>
        public static readonly string[] BufferNames =
        {
            "_Particles", "_TileCounts", "_TileStart", "_TileEntries", "_SurfaceStats", null, null, "_Thickness", "_Normals",
        };

        /// <summary>The shader name of each <see cref="FluidSurfaceDepthSlot"/>.</summary>
        public static readonly string[] DepthSlotNames = { "_Depth", "_DepthIn", "_DepthOut" };

        /// <summary>Bytes per element of each buffer.</summary>
        public static int Stride(FluidSurfaceBuffer b) => b switch
        {
            FluidSurfaceBuffer.Particles => 16,
            FluidSurfaceBuffer.Thickness => 8,
            _ => 4,
        };

        /// <summary>Elements of each buffer for these targets and this many particles.</summary>
        public static int Length(FluidSurfaceBuffer b, in FluidSurfaceTargets t, int particles, int tileCapacity) => b switch
        {
            FluidSurfaceBuffer.Particles => math.max(particles, 1),
            FluidSurfaceBuffer.TileCounts => t.TileCount,
            FluidSurfaceBuffer.TileStart => t.TileCount + 1,
            FluidSurfaceBuffer.TileEntries => math.max(tileCapacity, 1),
            FluidSurfaceBuffer.Stats => StatCount,
            FluidSurfaceBuffer.DepthA or FluidSurfaceBuffer.DepthB or FluidSurfaceBuffer.Normals => t.Depth.x * t.Depth.y,
            FluidSurfaceBuffer.Thickness => t.Thickness.x * t.Thickness.y,
            _ => 1,
        };
    }

    /// <summary>The render targets of one camera: screen, depth (full or half), thickness (half), composite (full or half), and the tile grid.</summary>
    public struct FluidSurfaceTargets
    {
        public int2 Screen, Depth, Thickness, Composite, Tiles;
        public int DepthDivisor, CompositeDivisor;

        public int TileCount => Tiles.x * Tiles.y;

        public static FluidSurfaceTargets Of(in FluidSurfaceCamera camera, in FluidSurfaceSettings settings) =>
            Of(camera, settings.DepthDivisor, settings.CompositeDivisor);

        public static FluidSurfaceTargets Of(in FluidSurfaceCamera camera, int depthDivisor, int compositeDivisor = 1)
        {
            int2 depth = camera.Size(depthDivisor);
            const int tile = FluidSurfaceLayout.TileSize;
            return new FluidSurfaceTargets
            {
                Screen = camera.Size(1),
                Depth = depth,
                Thickness = camera.Size(FluidSurfaceSettings.ThicknessDivisor),
                Composite = camera.Size(compositeDivisor),
                Tiles = new int2((depth.x + tile - 1) / tile, (depth.y + tile - 1) / tile),
                DepthDivisor = depthDivisor,
                CompositeDivisor = compositeDivisor,
            };
        }
    }
}
