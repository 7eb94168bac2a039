using System;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Compute
{
    /// <summary>
    /// A mass-spring body's XPBD springs and a shape-matching body's cluster sums on the GPU
    /// (SoftBodySolver.compute, recorded by <see cref="SoftBodyComputeStep"/>, the recorder the lavapipe tests run). One
    /// <see cref="GraphicsBuffer"/> per <see cref="SoftBodyComputeBuffer"/>, created when its data is first set and
    /// recreated only when it must grow, bound to every kernel by a cached property ID.
    /// </summary>
    public sealed class SoftBodyComputeSolver : ISoftBodyComputeCommands, IDisposable
    {
        readonly ComputeKernelSet m_Kernels;
        readonly ComputeConstantBuffer<SoftBodyComputeConstants> m_ConstantBuffer;
        readonly GraphicsBuffer[] m_Buffers = new GraphicsBuffer[Enum.GetValues(typeof(SoftBodyComputeBuffer)).Length];

        public SoftBodyComputeSolver(ComputeShader shader)
        {
            m_Kernels = new ComputeKernelSet(shader, typeof(SoftBodyKernel), typeof(SoftBodyComputeBuffer), typeof(SoftBodyComputeGlobal));
            m_ConstantBuffer = new ComputeConstantBuffer<SoftBodyComputeConstants>(shader, SoftBodyComputeConstants.BufferName, SoftBodyComputeConstants.Bytes);
            // Every kernel must have each buffer it declares bound, even one it is not dispatched with.
            for (int b = 0; b < m_Buffers.Length; b++)
                Ensure((SoftBodyComputeBuffer)b, 1, 16);
        }

        /// <summary>The buffer, for a renderer or a read-back.</summary>
        public GraphicsBuffer Buffer(SoftBodyComputeBuffer buffer) => m_Buffers[(int)buffer];

        GraphicsBuffer Ensure(SoftBodyComputeBuffer id, int count, int stride)
        {
            GraphicsBuffer buffer = m_Buffers[(int)id];
            if (buffer != null && buffer.count >= count && buffer.stride == stride)
                return buffer;
            buffer?.Release();
            buffer = new GraphicsBuffer(GraphicsBuffer.Target.Structured, math.max(count, 1), stride);
            m_Buffers[(int)id] = buffer;
            m_Kernels.Bind((int)id, buffer);
            return buffer;
        }

        /// <summary>Uploads <paramref name="data"/> into a buffer (growing it when needed).</summary>
        public void SetData<T>(SoftBodyComputeBuffer id, NativeArray<T> data, int stride) where T : struct =>
            Ensure(id, data.Length, stride).SetData(data, 0, 0, data.Length);

        /// <summary>Allocates a buffer the kernels write (multipliers, predicted positions, cluster results).</summary>
        public void Allocate(SoftBodyComputeBuffer id, int count, int stride) => Ensure(id, count, stride);

        public void SetConstants(in SoftBodyComputeConstants constants) => m_ConstantBuffer.Set(constants);
        public void SetInts(SoftBodyComputeGlobal name, int4 value) => m_Kernels.SetInts((int)name, value);
        public void Dispatch(SoftBodyKernel kernel, int threads) => m_Kernels.Dispatch((int)kernel, threads);
        public void DispatchGroups(SoftBodyKernel kernel, int groups) => m_Kernels.DispatchGroups((int)kernel, groups);

        public void Dispose()
        {
            m_ConstantBuffer.Dispose();
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                m_Buffers[b]?.Release();
                m_Buffers[b] = null;
            }
        }
    }
}
