namespace SoftBodyDynamics.Solvers
{
    /// <summary>Where a fluid is simulated.</summary>
    public enum FluidBackend : byte
    {
        /// <summary>Burst jobs on the CPU.</summary>
        Cpu,
        /// <summary>Compute shaders (falls back to the CPU, with a warning, where they cannot run this fluid).</summary>
        Gpu,
        /// <summary>The GPU where it can run this fluid, the CPU otherwise (said once in the console).</summary>
        Auto,
    }

    /// <summary>The choice between the CPU and GPU paths for a fluid, and the reason when the GPU is not taken.</summary>
    public static class FluidBackendChoice
    {
        /// <summary>
        /// True when the fluid runs on the GPU: asked for (<see cref="FluidBackend.Gpu"/> or <see cref="FluidBackend.Auto"/>),
        /// the device runs compute shaders, reads buffers back asynchronously, allows <see cref="FluidComputeLayout.ThreadGroupSize"/>
        /// threads per group (<c>SystemInfo.maxComputeWorkGroupSize</c>; OpenGL ES 3.1 guarantees only 128) and
        /// <see cref="FluidComputeLayout.MaxBuffersPerKernel"/> buffers per kernel (<c>SystemInfo.maxComputeBufferInputsCompute</c>;
        /// OpenGL ES 3.1 guarantees only 8). Otherwise false, with the reason in <paramref name="reason"/> (null when the CPU was asked for).
        /// </summary>
        public static bool UseGpu(FluidBackend requested, bool supportsComputeShaders, bool supportsAsyncReadback, int maxWorkGroupSize,
            int maxBuffersPerKernel, out string reason)
        {
            reason = null;
            if (requested == FluidBackend.Cpu)
                return false;
            if (!supportsComputeShaders)
                reason = "this device does not run compute shaders";
            else if (!supportsAsyncReadback)
                reason = "this device cannot read GPU buffers back asynchronously";
            else if (maxWorkGroupSize < FluidComputeLayout.ThreadGroupSize)
                reason = $"this device allows {maxWorkGroupSize} threads per group, the fluid kernels use {FluidComputeLayout.ThreadGroupSize}";
            else if (maxBuffersPerKernel < FluidComputeLayout.MaxBuffersPerKernel)
                reason = $"this device allows {maxBuffersPerKernel} buffers per compute kernel, the fluid kernels use up to {FluidComputeLayout.MaxBuffersPerKernel}";
            return reason == null;
        }
    }
}
