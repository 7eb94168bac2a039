using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Whether a device can run the surface kernels, and the reason when it cannot.</summary>
    public static class FluidSurfaceDevice
    {
        /// <summary>Threads in the largest group a surface kernel uses (today the tile scan's <see cref="FluidSurfaceLayout.ScanGroup"/>).</summary>
        public static int LargestGroup => math.max(FluidSurfaceLayout.ScanGroup,
            math.max(FluidSurfaceLayout.ParticleGroup, FluidSurfaceLayout.TileGroup * FluidSurfaceLayout.TileGroup));

        /// <summary>
        /// True when the device runs compute shaders, allows <see cref="LargestGroup"/> threads per group
        /// (<c>SystemInfo.maxComputeWorkGroupSize</c>; OpenGL ES 3.1 guarantees only 128) and
        /// <see cref="FluidSurfaceLayout.MaxBuffersPerKernel"/> buffers per kernel (<c>SystemInfo.maxComputeBufferInputsCompute</c>;
        /// OpenGL ES 3.1 guarantees 8). Otherwise false, with the reason in <paramref name="reason"/>.
        /// </summary>
        public static bool CanDraw(bool supportsComputeShaders, int maxWorkGroupSize, int maxBuffersPerKernel, out string reason)
        {
            reason = null;
            if (!supportsComputeShaders)
                reason = "this device does not run compute shaders";
            else if (maxWorkGroupSize < LargestGroup)
                reason = $"this device allows {maxWorkGroupSize} threads per group, the surface's tile scan uses {LargestGroup}";
            else if (maxBuffersPerKernel < FluidSurfaceLayout.MaxBuffersPerKernel)
                reason = $"this device allows {maxBuffersPerKernel} buffers per compute kernel, the surface kernels use up to {FluidSurfaceLayout.MaxBuffersPerKernel}";
            return reason == null;
        }
    }
}
