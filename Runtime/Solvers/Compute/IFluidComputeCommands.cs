using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// What <see cref="FluidComputeStep"/> asks of a GPU backend: bind this fluid's buffers, upload the constants, set a
    /// dispatch's arguments, dispatch a kernel over a thread count known on the CPU or over the live particles (indirect,
    /// the count being known only on the GPU). Unity's implementation drives a <c>ComputeShader</c>; the test harness
    /// drives the same kernels on lavapipe, binding at the shader as Unity does.
    /// </summary>
    public interface IFluidComputeCommands
    {
        /// <summary>
        /// Binds every <see cref="FluidComputeBuffer"/> of this fluid to every kernel by name. Bindings live on the shader
        /// asset, which every fluid shares, so each recording binds its own buffers before its first dispatch.
        /// </summary>
        void BindBuffers();
        /// <summary>
        /// Uploads <paramref name="constants"/> whole (<see cref="FluidComputeConstants.Bytes"/> bytes) and binds them as
        /// the kernels' constant buffer <see cref="FluidComputeConstants.BufferName"/> for the dispatches that follow.
        /// </summary>
        void SetConstants(in FluidComputeConstants constants);
        /// <summary>Sets a per-dispatch uint4 argument (as int4 bits) for the dispatches that follow.</summary>
        void SetInts(FluidComputeGlobal name, int4 value);
        /// <summary>Dispatches ⌈<paramref name="threads"/> / group size⌉ groups (none for 0), the group size reflected from the kernel.</summary>
        void Dispatch(FluidKernel kernel, int threads);
        /// <summary>Dispatches with the group count the GPU wrote to <see cref="FluidComputeBuffer.Args"/> (one thread per live particle).</summary>
        void DispatchIndirect(FluidKernel kernel);
    }
}
