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
        static readonly int[] s_BufferIds = PropertyIds(Enum.GetNames(typeof(SoftBodyComputeBuffer)));
        static readonly int[] s_GlobalIds = PropertyIds(Enum.GetNames(typeof(SoftBodyComputeGlobal)));

        readonly ComputeShader m_Shader;
        readonly int[] m_Kernels;
        readonly int[] m_GroupSizes;
        readonly GraphicsBuffer[] m_Buffers = new GraphicsBuffer[s_BufferIds.Length];
        readonly int[] m_Ints = new int[4];

        static int[] PropertyIds(string[] names)
        {
            var ids = new int[names.Length];
            for (int i = 0; i < names.Length; i++)
                ids[i] = Shader.PropertyToID("_" + names[i]);
            return ids;
        }

        public SoftBodyComputeSolver(ComputeShader shader)
        {
            m_Shader = shader;
            string[] names = Enum.GetNames(typeof(SoftBodyKernel));
            m_Kernels = new int[names.Length];
            m_GroupSizes = new int[names.Length];
            for (int k = 0; k < names.Length; k++)
            {
                m_Kernels[k] = shader.FindKernel(names[k]);
                shader.GetKernelThreadGroupSizes(m_Kernels[k], out uint x, out _, out _);
                m_GroupSizes[k] = (int)x;
            }
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
            for (int k = 0; k < m_Kernels.Length; k++)
                m_Shader.SetBuffer(m_Kernels[k], s_BufferIds[(int)id], buffer);
            return buffer;
        }

        /// <summary>Uploads <paramref name="data"/> into a buffer (growing it when needed).</summary>
        public void SetData<T>(SoftBodyComputeBuffer id, NativeArray<T> data, int stride) where T : struct =>
            Ensure(id, data.Length, stride).SetData(data, 0, 0, data.Length);

        /// <summary>Allocates a buffer the kernels write (multipliers, predicted positions, cluster results).</summary>
        public void Allocate(SoftBodyComputeBuffer id, int count, int stride) => Ensure(id, count, stride);

        public void SetVector(SoftBodyComputeGlobal name, float4 value) =>
            m_Shader.SetVector(s_GlobalIds[(int)name], new Vector4(value.x, value.y, value.z, value.w));

        public void SetInts(SoftBodyComputeGlobal name, int4 value)
        {
            m_Ints[0] = value.x; m_Ints[1] = value.y; m_Ints[2] = value.z; m_Ints[3] = value.w;
            m_Shader.SetInts(s_GlobalIds[(int)name], m_Ints);
        }

        public void Dispatch(SoftBodyKernel kernel, int threads)
        {
            if (threads <= 0)
                return;
            int group = m_GroupSizes[(int)kernel];
            m_Shader.Dispatch(m_Kernels[(int)kernel], (threads + group - 1) / group, 1, 1);
        }

        public void DispatchGroups(SoftBodyKernel kernel, int groups)
        {
            if (groups > 0)
                m_Shader.Dispatch(m_Kernels[(int)kernel], groups, 1, 1);
        }

        public void Dispose()
        {
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                m_Buffers[b]?.Release();
                m_Buffers[b] = null;
            }
        }
    }
}
