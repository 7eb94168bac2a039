using Unity.Entities;
using UnityEngine;

namespace SoftBodyDynamics
{
    /// <summary>When a GPU fluid's particles are copied back into its entity buffers (for gameplay code that reads them).</summary>
    public enum FluidReadback : byte
    {
        /// <summary>Never: the particles stay on the GPU (the renderer reads the GPU buffer).</summary>
        Never,
        /// <summary>Every <see cref="FluidSettings.ReadbackInterval"/> fixed steps.</summary>
        EveryNFrames,
        /// <summary>Every fixed step (the copy arrives a frame or two late, never stalling the GPU).</summary>
        EveryFrame,
    }

    /// <summary>The fluid kernels (Shaders/FluidSolver.compute) for a fluid that may run on the GPU.</summary>
    public struct FluidComputeShader : IComponentData
    {
        public UnityObjectRef<ComputeShader> Shader;
    }

    /// <summary>Tag of a fluid the GPU runs (added by <see cref="FluidComputeSystem"/>); the CPU system skips it.</summary>
    public struct FluidOnGpu : IComponentData
    {
    }
}
