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
        /// <summary>
        /// Unit vertex normals at the baked scale (the inverse-transpose of the scale applied, n / s normalised), one per
        /// vertex; computed from the triangles (area-weighted) when the mesh has none. Used by the tetrahedral methods'
        /// render embedding.
        /// </summary>
        public float3[] Normals;

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
            int[] triangleArray = triangles.ToArray();
            return new SoftBodyMeshData { Vertices = vertices, Triangles = triangleArray, Normals = ReadNormals(mesh.normals, magnitude, vertices, triangleArray) };
        }

        static float3[] ReadNormals(Vector3[] source, float3 scale, float3[] vertices, int[] triangles)
        {
            var normals = new float3[vertices.Length];
            if (source.Length == vertices.Length)
            {
                // Normals transform with the inverse transpose of the (diagonal) scale.
                var inverse = new float3(Inverse(scale.x), Inverse(scale.y), Inverse(scale.z));
                for (int i = 0; i < normals.Length; i++)
                    normals[i] = math.normalizesafe(UnityMathConversions.ToFloat3(source[i]) * inverse, new float3(0f, 1f, 0f));
                return normals;
            }
            for (int t = 0; t + 2 < triangles.Length; t += 3)
            {
                int a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
                float3 n = math.cross(vertices[b] - vertices[a], vertices[c] - vertices[a]);
                normals[a] += n;
                normals[b] += n;
                normals[c] += n;
            }
            for (int i = 0; i < normals.Length; i++)
                normals[i] = math.normalizesafe(normals[i], new float3(0f, 1f, 0f));
            return normals;
        }

        static float Inverse(float s) => s != 0f ? 1f / s : 0f;
    }
}
