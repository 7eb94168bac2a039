using System;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Compute
{
    /// <summary>
    /// The kernels of one <see cref="ComputeShader"/>, found by name once with their reflected thread-group sizes, and
    /// the shader property IDs of its buffers and per-dispatch arguments (names are "_" + the enum names of the caller): the dispatch
    /// plumbing that <see cref="FluidComputeSolver"/> and <see cref="SoftBodyComputeSolver"/> share.
    /// </summary>
    sealed class ComputeKernelSet
    {
        readonly ComputeShader m_Shader;
        readonly int[] m_Kernels, m_GroupSizes, m_BufferIds, m_GlobalIds;
        readonly int[] m_Ints = new int[4];

        public ComputeKernelSet(ComputeShader shader, Type kernels, Type buffers, Type globals)
        {
            m_Shader = shader;
            string[] names = Enum.GetNames(kernels);
            m_Kernels = new int[names.Length];
            m_GroupSizes = new int[names.Length];
            for (int k = 0; k < names.Length; k++)
            {
                m_Kernels[k] = shader.FindKernel(names[k]);
                shader.GetKernelThreadGroupSizes(m_Kernels[k], out uint x, out _, out _);
                m_GroupSizes[k] = (int)x;
            }
            m_BufferIds = PropertyIds(Enum.GetNames(buffers));
            m_GlobalIds = PropertyIds(Enum.GetNames(globals));
        }

        static int[] PropertyIds(string[] names)
        {
            var ids = new int[names.Length];
            for (int i = 0; i < names.Length; i++)
                ids[i] = Shader.PropertyToID("_" + names[i]);
            return ids;
        }

        /// <summary>Binds <paramref name="graphicsBuffer"/> as buffer <paramref name="buffer"/> of every kernel.</summary>
        public void Bind(int buffer, GraphicsBuffer graphicsBuffer)
        {
            for (int k = 0; k < m_Kernels.Length; k++)
                m_Shader.SetBuffer(m_Kernels[k], m_BufferIds[buffer], graphicsBuffer);
        }

        /// <summary>Binds <paramref name="graphicsBuffer"/> as buffer <paramref name="buffer"/> of one kernel.</summary>
        public void Bind(int kernel, int buffer, GraphicsBuffer graphicsBuffer) =>
            m_Shader.SetBuffer(m_Kernels[kernel], m_BufferIds[buffer], graphicsBuffer);

        public void SetInts(int global, int4 value)
        {
            m_Ints[0] = value.x; m_Ints[1] = value.y; m_Ints[2] = value.z; m_Ints[3] = value.w;
            m_Shader.SetInts(m_GlobalIds[global], m_Ints);
        }

        /// <summary>⌈<paramref name="threads"/> / group size⌉ groups of <paramref name="kernel"/> (none for 0).</summary>
        public void Dispatch(int kernel, int threads)
        {
            if (threads <= 0)
                return;
            int group = m_GroupSizes[kernel];
            m_Shader.Dispatch(m_Kernels[kernel], (threads + group - 1) / group, 1, 1);
        }

        public void DispatchGroups(int kernel, int groups)
        {
            if (groups > 0)
                m_Shader.Dispatch(m_Kernels[kernel], groups, 1, 1);
        }

        public void DispatchIndirect(int kernel, GraphicsBuffer arguments) => m_Shader.DispatchIndirect(m_Kernels[kernel], arguments, 0);
    }
}
