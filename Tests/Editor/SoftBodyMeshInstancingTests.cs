using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>The per-body render mesh copy: same mesh, position and normal in their own stream, refused inputs.</summary>
    public class SoftBodyMeshInstancingTests
    {
        Mesh m_Source;
        Mesh m_Copy;

        /// <summary>A unit quad facing −z with normals and UVs (Unity's procedural-mesh example).</summary>
        [SetUp]
        public void SetUp()
        {
            m_Copy = null;
            m_Source = new Mesh { name = "Quad" };
            m_Source.vertices = new[] { new Vector3(0f, 0f, 0f), new Vector3(1f, 0f, 0f), new Vector3(0f, 1f, 0f), new Vector3(1f, 1f, 0f) };
            m_Source.normals = new[] { new Vector3(0f, 0f, -1f), new Vector3(0f, 0f, -1f), new Vector3(0f, 0f, -1f), new Vector3(0f, 0f, -1f) };
            m_Source.uv = new[] { new Vector2(0f, 0f), new Vector2(1f, 0f), new Vector2(0f, 1f), new Vector2(1f, 1f) };
            m_Source.triangles = new[] { 0, 2, 1, 2, 3, 1 };
        }

        [TearDown]
        public void TearDown()
        {
            if (m_Copy != null)
                Object.DestroyImmediate(m_Copy);
            Object.DestroyImmediate(m_Source);
        }

        [Test]
        public void DeformableCopy_IsTheSameMesh_WithPositionAndNormalInTheirOwnStream()
        {
            m_Copy = SoftBodyMeshInstancing.CreateDeformableCopy(m_Source, 4, out string error);

            Assert.That(error, Is.Null);
            Assert.That(m_Copy != null, Is.True);
            Assert.That(m_Copy.vertexCount, Is.EqualTo(4));
            Assert.That(m_Copy.GetVertexAttributeStream(VertexAttribute.Position), Is.EqualTo(SoftBodyMeshInstancing.DeformedStream));
            Assert.That(m_Copy.GetVertexAttributeStream(VertexAttribute.Normal), Is.EqualTo(SoftBodyMeshInstancing.DeformedStream));
            Assert.That(m_Copy.GetVertexAttributeStream(VertexAttribute.TexCoord0), Is.EqualTo(SoftBodyMeshInstancing.StaticStream));
            Assert.That(m_Copy.GetVertexBufferStride(SoftBodyMeshInstancing.DeformedStream), Is.EqualTo(24),
                "the stream is exactly DeformedVertex: 3 + 3 float32");
            Assert.That(m_Copy.vertices, Is.EqualTo(m_Source.vertices));
            Assert.That(m_Copy.normals, Is.EqualTo(m_Source.normals));
            Assert.That(m_Copy.uv, Is.EqualTo(m_Source.uv));
            Assert.That(m_Copy.triangles, Is.EqualTo(m_Source.triangles));
        }

        [Test]
        public void WritingTheDeformedStream_MovesVerticesAndNormals_AndKeepsTheUVs()
        {
            m_Copy = SoftBodyMeshInstancing.CreateDeformableCopy(m_Source, 4, out _);
            var deformed = new NativeArray<DeformedVertex>(4, Allocator.Temp);
            var expected = new Vector3[4];
            for (int v = 0; v < 4; v++)
            {
                Vector3 p = m_Source.vertices[v];
                deformed[v] = new DeformedVertex { Position = new float3(p.x, p.y + 2f, p.z), Normal = new float3(0f, 1f, 0f) };
                expected[v] = new Vector3(p.x, p.y + 2f, p.z);
            }

            m_Copy.SetVertexBufferData(deformed, 0, 0, deformed.Length, SoftBodyMeshInstancing.DeformedStream);
            deformed.Dispose();

            Assert.That(m_Copy.vertices, Is.EqualTo(expected));
            foreach (Vector3 n in m_Copy.normals)
                Assert.That(n, Is.EqualTo(new Vector3(0f, 1f, 0f)));
            Assert.That(m_Copy.uv, Is.EqualTo(m_Source.uv));
        }

        [Test]
        public void MeshWithAnotherVertexCount_IsRefused_WithAReason()
        {
            m_Copy = SoftBodyMeshInstancing.CreateDeformableCopy(m_Source, 5, out string error);
            Assert.That(m_Copy == null, Is.True);
            Assert.That(error, Does.Contain("re-bake"));
        }

        [Test]
        public void NonReadableMesh_IsRefused_WithAReason()
        {
            m_Source.UploadMeshData(true);
            m_Copy = SoftBodyMeshInstancing.CreateDeformableCopy(m_Source, 4, out string error);
            Assert.That(m_Copy == null, Is.True);
            Assert.That(error, Does.Contain("Read/Write"));
        }
    }
}
