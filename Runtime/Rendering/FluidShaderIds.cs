using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>Shader property IDs of Shaders/FluidSurface.compute, looked up once.</summary>
    static class FluidShaderIds
    {
        /// <summary>
        /// Buffer name of each <see cref="FluidSurfaceBuffer"/> (FluidSurfaceCommon.hlsl); DepthA and DepthB have none, the
        /// recorder binds them to the depth slots.
        /// </summary>
        static readonly string[] k_BufferNames =
        {
            "_Particles", "_TileCounts", "_TileStart", "_TileEntries", "_SurfaceStats", null, null, "_Thickness", "_Normals",
        };

        /// <summary>Property ID per <see cref="FluidSurfaceBuffer"/>; −1 for the two depth buffers.</summary>
        public static readonly int[] Buffers = Ids(k_BufferNames);

        /// <summary>Property ID per <see cref="FluidSurfaceDepthSlot"/>.</summary>
        public static readonly int[] DepthSlots = Ids(new[] { "_Depth", "_DepthIn", "_DepthOut" });

        /// <summary>Property ID per global of <see cref="FluidSurfaceConstants.Names"/>.</summary>
        public static readonly int[] Globals = Ids(FluidSurfaceConstants.Names);

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
