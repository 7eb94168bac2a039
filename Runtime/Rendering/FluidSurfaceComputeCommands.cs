using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// <see cref="FluidSurfaceFrame"/>'s recorder over a render graph compute command buffer: depth slots become
    /// SetComputeBufferParam, dispatches DispatchCompute (one group deep).
    /// </summary>
    readonly struct FluidSurfaceComputeCommands : IFluidSurfaceCommands
    {
        readonly ComputeCommandBuffer m_Cmd;
        readonly ComputeShader m_Shader;
        readonly int[] m_Kernels;
        readonly GraphicsBuffer[] m_Buffers;
        readonly int[] m_Ints;

        /// <param name="kernels">Kernel index per <see cref="FluidSurfaceKernel"/>.</param>
        /// <param name="buffers">Buffer per <see cref="FluidSurfaceBuffer"/> (the two depth buffers at least).</param>
        /// <param name="ints">Four ints of scratch for the uint4 globals (reused, so nothing is allocated per frame).</param>
        public FluidSurfaceComputeCommands(ComputeCommandBuffer cmd, ComputeShader shader, int[] kernels, GraphicsBuffer[] buffers, int[] ints)
        {
            m_Cmd = cmd;
            m_Shader = shader;
            m_Kernels = kernels;
            m_Buffers = buffers;
            m_Ints = ints;
        }

        public void SetVector(int global, float4 value) =>
            m_Cmd.SetComputeVectorParam(m_Shader, FluidShaderIds.Globals[global], new Vector4(value.x, value.y, value.z, value.w));

        public void SetInts(int global, int4 value)
        {
            m_Ints[0] = value.x;
            m_Ints[1] = value.y;
            m_Ints[2] = value.z;
            m_Ints[3] = value.w;
            m_Cmd.SetComputeIntParams(m_Shader, FluidShaderIds.Globals[global], m_Ints);
        }

        public void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer) =>
            m_Cmd.SetComputeBufferParam(m_Shader, m_Kernels[(int)kernel], FluidShaderIds.DepthSlots[(int)slot], m_Buffers[(int)buffer]);

        public void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY) =>
            m_Cmd.DispatchCompute(m_Shader, m_Kernels[(int)kernel], groupsX, groupsY, 1);
    }
}
