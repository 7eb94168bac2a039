using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Deformed render vertices of a soft body, in the space of its render mesh. Each render vertex is
    /// bound to one particle (a welded surface vertex); several render vertices share a particle where
    /// the mesh splits a vertex for UV seams or hard edges.
    /// <para>
    /// Placement: the body is drawn with the transform (t, R) where R is the body's best-fit rotation
    /// and t = c − R·x⁰_cm (c: current centre of mass, x⁰_cm: rest centre of mass in mesh space), so
    /// a particle at xᵢ (world) sits at Rᵀ(xᵢ − c) + x⁰_cm in mesh space and the undeformed body gives
    /// back its rest vertices exactly.
    /// </para>
    /// <para>
    /// Normals are area-weighted face normals summed per particle, then copied to every render vertex
    /// of that particle, so seams stay smooth. Winding follows Unity: a triangle (a, b, c) faces the
    /// side its vertices appear clockwise from, which is the direction of (b − a) × (c − a).
    /// </para>
    /// </summary>
    public static class MeshDeformation
    {
        /// <summary>Normal given to a render vertex whose particle belongs to no non-degenerate triangle.</summary>
        public static readonly float3 FallbackNormal = new float3(0f, 1f, 0f);

        /// <summary>Computes the deformed render vertices and their bounds.</summary>
        /// <param name="particles">Particle positions (m, world), one per particle.</param>
        /// <param name="vertexToParticle">Particle of each render vertex (indices into <paramref name="particles"/>).</param>
        /// <param name="triangles">Triangle list of the render mesh, three render-vertex indices per triangle (all sub-meshes).</param>
        /// <param name="center">Current centre of mass c (m, world).</param>
        /// <param name="rotation">Current best-fit rotation R of the body from its rest pose.</param>
        /// <param name="restCenter">Rest centre of mass x⁰_cm in mesh space (m).</param>
        /// <param name="localParticles">Scratch, one per particle: particle positions in mesh space (m).</param>
        /// <param name="particleNormals">Scratch, one per particle: summed area-weighted normals (m²).</param>
        /// <param name="vertices">Output, one per render vertex: mesh-space position (m) and unit normal.</param>
        /// <returns>The axis-aligned bounds of <paramref name="vertices"/> in mesh space (m); a zero box when there are none.</returns>
        public static AxisAlignedBox Deform(ReadOnlySpan<float3> particles, ReadOnlySpan<int> vertexToParticle,
            ReadOnlySpan<int> triangles, float3 center, quaternion rotation, float3 restCenter,
            Span<float3> localParticles, Span<float3> particleNormals, Span<DeformedVertex> vertices)
        {
            quaternion inverse = math.conjugate(math.normalizesafe(rotation));
            for (int i = 0; i < particles.Length; i++)
            {
                localParticles[i] = math.rotate(inverse, particles[i] - center) + restCenter;
                particleNormals[i] = float3.zero;
            }

            int triangleEnd = triangles.Length - triangles.Length % 3;
            for (int t = 0; t < triangleEnd; t += 3)
            {
                int a = vertexToParticle[triangles[t]];
                int b = vertexToParticle[triangles[t + 1]];
                int c = vertexToParticle[triangles[t + 2]];
                // |(b − a) × (c − a)| = 2 · area: summing it weights each face by its area.
                float3 n = math.cross(localParticles[b] - localParticles[a], localParticles[c] - localParticles[a]);
                particleNormals[a] += n;
                particleNormals[b] += n;
                particleNormals[c] += n;
            }

            if (vertices.Length == 0)
                return default;
            float3 min = new float3(float.PositiveInfinity), max = new float3(float.NegativeInfinity);
            for (int v = 0; v < vertices.Length; v++)
            {
                int p = vertexToParticle[v];
                float3 position = localParticles[p];
                vertices[v] = new DeformedVertex
                {
                    Position = position,
                    Normal = math.normalizesafe(particleNormals[p], FallbackNormal),
                };
                min = math.min(min, position);
                max = math.max(max, position);
            }
            return new AxisAlignedBox { Min = min, Max = max };
        }
    }
}
