using System;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// One fluid's constant buffer of Shaders/FluidSurface.compute: a <see cref="GraphicsBuffer.Target.Constant"/> buffer of
    /// one <see cref="FluidSurfaceConstants"/> (laid out as cbuffer FluidSurfaceConstants), filled and bound by commands
    /// of the render graph's compute command buffer, so every camera's frame of the fluid reads its own values.
    /// </summary>
    sealed class FluidSurfaceConstantBuffer : IDisposable
    {
        static readonly int s_NameId = Shader.PropertyToID(FluidSurfaceConstants.BufferName);

        readonly GraphicsBuffer m_Buffer;
        NativeArray<FluidSurfaceConstants> m_Data;

        public FluidSurfaceConstantBuffer()
        {
            m_Buffer = new GraphicsBuffer(GraphicsBuffer.Target.Constant, 1, FluidSurfaceConstants.Bytes);
            m_Data = new NativeArray<FluidSurfaceConstants>(1, Allocator.Persistent);
        }

        /// <summary>
        /// Records the upload of <paramref name="value"/> (SetBufferData) and its binding as the cbuffer of
        /// <paramref name="shader"/> for the dispatches that follow (SetComputeConstantBufferParam).
        /// </summary>
        public void Record(ComputeCommandBuffer cmd, ComputeShader shader, in FluidSurfaceConstants value)
        {
            m_Data[0] = value;
            cmd.SetBufferData(m_Buffer, m_Data);
            cmd.SetComputeConstantBufferParam(shader, s_NameId, m_Buffer, 0, FluidSurfaceConstants.Bytes);
        }

        public void Dispose()
        {
            m_Buffer.Release();
            if (m_Data.IsCreated)
                m_Data.Dispose();
        }
    }
}
