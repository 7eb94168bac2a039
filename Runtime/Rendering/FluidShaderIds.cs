using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>Shader property IDs of Shaders/FluidSurface.compute, looked up once.</summary>
    static class FluidShaderIds
    {
        /// <summary>Property ID per <see cref="FluidSurfaceBuffer"/> (<see cref="FluidSurfaceLayout.BufferNames"/>); −1 for the two depth buffers.</summary>
        public static readonly int[] Buffers = Ids(FluidSurfaceLayout.BufferNames);

        /// <summary>Property ID per <see cref="FluidSurfaceDepthSlot"/>.</summary>
        public static readonly int[] DepthSlots = Ids(FluidSurfaceLayout.DepthSlotNames);

        /// <summary>The composite's scene inputs and its output (FluidSurfaceScreenIO.hlsl).</summary>
        public static readonly int SceneColor = Shader.PropertyToID("_SceneColor");
        public static readonly int SceneDepth = Shader.PropertyToID("_SceneDepth");
        public static readonly int FluidColor = Shader.PropertyToID("_FluidColor");

        static int[] Ids(string[] names)
        {
            var ids = new int[names.Length];
            for (int i = 0; i < names.Length; i++)
                ids[i] = names[i] != null ? Shader.PropertyToID(names[i]) : -1;
            return ids;
        }
    }
}
