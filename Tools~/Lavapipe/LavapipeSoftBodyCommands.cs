using System;
using System.IO;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Lavapipe
{
    /// <summary>
    /// The soft-body kernels (Shaders/SoftBodySolver.compute) on lavapipe, driven by <see cref="SoftBodyComputeStep"/>:
    /// buffers created by the caller through <see cref="Create"/>, bound to every kernel by name.
    /// </summary>
    public sealed class LavapipeSoftBodyCommands : ISoftBodyComputeCommands, IDisposable
    {
        readonly LavapipeDevice m_Device;
        readonly LavapipeComputeShader m_Shader;
        readonly int[] m_Kernels;
        readonly string[] m_Globals = Array.ConvertAll(Enum.GetNames(typeof(SoftBodyComputeGlobal)), n => "_" + n);
        readonly LavapipeBuffer[] m_Buffers = new LavapipeBuffer[Enum.GetValues(typeof(SoftBodyComputeBuffer)).Length];

        /// <summary>The package's SoftBodySolver.compute.</summary>
        public static string ComputePath() => Path.Combine(Path.GetDirectoryName(LavapipeFluidSolver.ComputePath()), "SoftBodySolver.compute");

        public LavapipeSoftBodyCommands(LavapipeDevice device, LavapipeComputeShader shader)
        {
            m_Device = device;
            m_Shader = shader;
            string[] names = Enum.GetNames(typeof(SoftBodyKernel));
            m_Kernels = new int[names.Length];
            for (int k = 0; k < names.Length; k++)
                m_Kernels[k] = shader.FindKernel(names[k]);
            // Every kernel needs every buffer it declares bound: start with a small buffer for each.
            for (int b = 0; b < m_Buffers.Length; b++)
                Create((SoftBodyComputeBuffer)b, 16);
        }

        /// <summary>(Re)creates a buffer of <paramref name="bytes"/> and binds it to every kernel.</summary>
        public LavapipeBuffer Create(SoftBodyComputeBuffer buffer, long bytes)
        {
            m_Buffers[(int)buffer]?.Dispose();
            LavapipeBuffer created = m_Device.CreateBuffer(bytes);
            m_Buffers[(int)buffer] = created;
            foreach (int k in m_Kernels)
                m_Shader.SetBuffer(k, "_" + buffer, created);
            return created;
        }

        public LavapipeBuffer Buffer(SoftBodyComputeBuffer buffer) => m_Buffers[(int)buffer];

        public void SetConstants(in SoftBodyComputeConstants constants) => m_Shader.SetConstantBuffer(SoftBodyComputeConstants.BufferName, constants);
        public void SetInts(SoftBodyComputeGlobal name, int4 value) => m_Shader.SetInts(m_Globals[(int)name], value);

        public void Dispatch(SoftBodyKernel kernel, int threads)
        {
            if (threads <= 0)
                return;
            int k = m_Kernels[(int)kernel];
            int group = m_Shader.ThreadGroupSize(k).x;
            m_Shader.Dispatch(k, (threads + group - 1) / group);
        }

        public void DispatchGroups(SoftBodyKernel kernel, int groups)
        {
            if (groups > 0)
                m_Shader.Dispatch(m_Kernels[(int)kernel], groups);
        }

        /// <summary>Runs what was recorded.</summary>
        public double Flush() => m_Shader.Submit();

        public void Dispose()
        {
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                m_Buffers[b]?.Dispose();
                m_Buffers[b] = null;
            }
        }
    }
}
