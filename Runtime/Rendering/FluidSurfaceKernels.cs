using System;
using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>The kernel indices of one FluidSurface.compute asset, found by name once, in <see cref="FluidSurfaceKernel"/> order.</summary>
    sealed class FluidSurfaceKernels
    {
        public readonly ComputeShader Shader;
        public readonly int[] Indices;

        FluidSurfaceKernels(ComputeShader shader, int[] indices)
        {
            Shader = shader;
            Indices = indices;
        }

        /// <summary>The kernels of <paramref name="shader"/>, or null with <paramref name="missing"/> naming the first absent one.</summary>
        public static FluidSurfaceKernels Find(ComputeShader shader, out string missing)
        {
            string[] names = Enum.GetNames(typeof(FluidSurfaceKernel));
            var indices = new int[names.Length];
            for (int k = 0; k < names.Length; k++)
            {
                if (!shader.HasKernel(names[k]))
                {
                    missing = names[k];
                    return null;
                }
                indices[k] = shader.FindKernel(names[k]);
            }
            missing = null;
            return new FluidSurfaceKernels(shader, indices);
        }
    }
}
