using System.Runtime.InteropServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// One vertex of a deformed render mesh: position and normal in mesh space, interleaved (24 bytes),
    /// the layout of the vertex stream the mesh write-back uploads.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct DeformedVertex
    {
        /// <summary>Position in mesh space (m).</summary>
        public float3 Position;
        /// <summary>Unit normal in mesh space.</summary>
        public float3 Normal;
    }
}
