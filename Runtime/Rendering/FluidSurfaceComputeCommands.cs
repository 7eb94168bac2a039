using SoftBodyDynamics.Solvers;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// <see cref="FluidSurfaceFrame"/>'s recorder over a render graph compute command buffer: the constants become one
    /// constant buffer upload and binding, depth slots SetComputeBufferParam, dispatches DispatchCompute (one group deep).
    /// </summary>
    readonly struct FluidSurfaceComputeCommands : IFluidSurfaceCommands
    {
        readonly ComputeCommandBuffer m_Cmd;
        readonly ComputeShader m_Shader;
        readonly int[] m_Kernels;
        readonly GraphicsBuffer[] m_Buffers;
        readonly FluidSurfaceConstantBuffer m_Constants;

        /// <param name="kernels">Kernel index per <see cref="FluidSurfaceKernel"/>.</param>
        /// <param name="buffers">Buffer per <see cref="FluidSurfaceBuffer"/> (the two depth buffers at least).</param>
        /// <param name="constants">The fluid's constant buffer.</param>
        public FluidSurfaceComputeCommands(ComputeCommandBuffer cmd, ComputeShader shader, int[] kernels, GraphicsBuffer[] buffers, FluidSurfaceConstantBuffer constants)
        {
            m_Cmd = cmd;
            m_Shader = shader;
            m_Kernels = kernels;
            m_Buffers = buffers;
            m_Constants = constants;
        }

        public void SetConstants(in FluidSurfaceConstants constants) => m_Constants.Record(m_Cmd, m_Shader, constants);

        public void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer) =>
            m_Cmd.SetComputeBufferParam(m_Shader, m_Kernels[(int)kernel], FluidShaderIds.DepthSlots[(int)slot], m_Buffers[(int)buffer]);

        public void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY) =>
            m_Cmd.DispatchCompute(m_Shader, m_Kernels[(int)kernel], groupsX, groupsY, 1);
    }
}
