using System;
using Unity.Collections;
using UnityEngine;

namespace SoftBodyDynamics.Compute
{
    /// <summary>
    /// One constant buffer of a <see cref="ComputeShader"/>: a <see cref="GraphicsBuffer.Target.Constant"/> buffer of one
    /// <typeparamref name="T"/> (whose layout matches the HLSL <c>cbuffer</c> field for field), uploaded whole by
    /// <see cref="Set"/> and bound by the cbuffer's name with <see cref="ComputeShader.SetConstantBuffer(int, GraphicsBuffer, int, int)"/>.
    /// </summary>
    sealed class ComputeConstantBuffer<T> : IDisposable where T : struct
    {
        readonly ComputeShader m_Shader;
        readonly int m_NameId, m_Bytes;
        readonly GraphicsBuffer m_Buffer;
        NativeArray<T> m_Data;

        /// <summary>The cbuffer <paramref name="name"/> of <paramref name="shader"/>, <paramref name="bytes"/> long (a multiple of 16).</summary>
        public ComputeConstantBuffer(ComputeShader shader, string name, int bytes)
        {
            if (bytes <= 0 || bytes % 16 != 0)
                throw new ArgumentException($"a constant buffer's size must be a positive multiple of 16 bytes, not {bytes}", nameof(bytes));
            m_Shader = shader;
            m_NameId = Shader.PropertyToID(name);
            m_Bytes = bytes;
            m_Buffer = new GraphicsBuffer(GraphicsBuffer.Target.Constant, 1, bytes);
            m_Data = new NativeArray<T>(1, Allocator.Persistent);
        }

        /// <summary>Uploads <paramref name="value"/> and binds the buffer for the dispatches that follow.</summary>
        public void Set(in T value)
        {
            m_Data[0] = value;
            m_Buffer.SetData(m_Data, 0, 0, 1);
            m_Shader.SetConstantBuffer(m_NameId, m_Buffer, 0, m_Bytes);
        }

        public void Dispose()
        {
            m_Buffer.Release();
            if (m_Data.IsCreated)
                m_Data.Dispose();
        }
    }
}
