using System.Collections.Generic;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// The render mesh as the builder reads it: vertex positions in the mesh's local space multiplied by the
    /// GameObject's scale (m: the body is simulated and drawn at scale 1, so the scale is baked into its rest
    /// shape), and the triangles of every triangle sub-mesh, concatenated in sub-mesh order. Sub-meshes drawn
    /// as lines, points or quads have no triangles and are skipped.
    /// </summary>
    public sealed class SoftBodyMeshData
    {
        public float3[] Vertices;
        public int[] Triangles;

        /// <summary>Reads <paramref name="mesh"/>, which must be readable (<see cref="Mesh.isReadable"/>).</summary>
        /// <param name="mesh">The render mesh.</param>
        /// <param name="scale">Scale per local axis applied to every vertex (its magnitude: mirroring is not baked).</param>
        public static SoftBodyMeshData Read(Mesh mesh, float3 scale)
        {
            Vector3[] source = mesh.vertices;
            float3 magnitude = math.abs(scale);
            var vertices = new float3[source.Length];
            for (int i = 0; i < source.Length; i++)
                vertices[i] = UnityMathConversions.ToFloat3(source[i]) * magnitude;

            var triangles = new List<int>();
            for (int subMesh = 0; subMesh < mesh.subMeshCount; subMesh++)
                if (mesh.GetTopology(subMesh) == UnityEngine.MeshTopology.Triangles)
                    triangles.AddRange(mesh.GetTriangles(subMesh));
            return new SoftBodyMeshData { Vertices = vertices, Triangles = triangles.ToArray() };
        }
    }
}
