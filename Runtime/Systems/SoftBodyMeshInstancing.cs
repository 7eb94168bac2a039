using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Rendering;
using Object = UnityEngine.Object;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Makes the per-body copy of a render mesh with the vertex layout the write-back needs: stream 0
    /// holds position and normal as 3 × float32 each (<see cref="DeformedVertex"/>, rewritten every
    /// frame with <c>Mesh.SetVertexBufferData</c>); every other attribute (UVs, colours, tangents…) keeps
    /// its format and moves to stream 1, uploaded once. Indices and sub-meshes are copied unchanged.
    /// Blend shapes and skinning data are not copied. Main thread only.
    /// </summary>
    public static class SoftBodyMeshInstancing
    {
        /// <summary>Vertex stream rewritten by the write-back.</summary>
        public const int DeformedStream = 0;
        /// <summary>Vertex stream of the attributes the deformation leaves alone.</summary>
        public const int StaticStream = 1;

        /// <summary>Creates the deformable copy of <paramref name="source"/>, or returns null and an error message.</summary>
        /// <param name="source">A readable mesh.</param>
        /// <param name="expectedVertexCount">Render vertices the body's blob binds (<see cref="ShapeMatchingShapeBlob.VertexCount"/>).</param>
        /// <param name="error">Why no copy was made, for the log; null on success.</param>
        public static Mesh CreateDeformableCopy(Mesh source, int expectedVertexCount, out string error)
        {
            error = null;
            if (source == null)
            {
                error = "the source mesh is missing";
                return null;
            }
            if (!source.isReadable)
            {
                error = $"mesh '{source.name}' is not readable: enable Read/Write in its import settings";
                return null;
            }
            if (source.vertexCount != expectedVertexCount || expectedVertexCount == 0)
            {
                error = $"mesh '{source.name}' has {source.vertexCount} vertices but the soft body binds {expectedVertexCount}: re-bake it";
                return null;
            }

            VertexAttributeDescriptor[] sourceLayout = source.GetVertexAttributes();
            var layout = new List<VertexAttributeDescriptor>
            {
                new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3, DeformedStream),
                new VertexAttributeDescriptor(VertexAttribute.Normal, VertexAttributeFormat.Float32, 3, DeformedStream),
            };
            foreach (VertexAttributeDescriptor a in sourceLayout)
                if (a.attribute != VertexAttribute.Position && a.attribute != VertexAttribute.Normal)
                    layout.Add(new VertexAttributeDescriptor(a.attribute, a.format, a.dimension, StaticStream));

            Mesh.MeshDataArray sourceData = Mesh.AcquireReadOnlyMeshData(source);
            Mesh.MeshDataArray copyData = Mesh.AllocateWritableMeshData(1);
            try
            {
                Mesh.MeshData from = sourceData[0];
                Mesh.MeshData to = copyData[0];
                int n = from.vertexCount;
                to.SetVertexBufferParams(n, layout.ToArray());
                CopyPositionsAndNormals(from, to, n);
                for (int i = 2; i < layout.Count; i++)
                    CopyAttribute(from, to, layout[i], n);
                CopyIndices(from, to);
            }
            catch
            {
                copyData.Dispose();
                throw;
            }
            finally
            {
                sourceData.Dispose();
            }

            var copy = new Mesh { name = source.name + " (soft body)" };
            copy.MarkDynamic();
            Mesh.ApplyAndDisposeWritableMeshData(copyData, copy);
            copy.bounds = source.bounds;
            return copy;
        }

        /// <summary>Destroys a mesh made by <see cref="CreateDeformableCopy"/> (immediately outside Play mode).</summary>
        public static void Destroy(Mesh mesh)
        {
            if (mesh == null)
                return;
            if (Application.isPlaying)
                Object.Destroy(mesh);
            else
                Object.DestroyImmediate(mesh);
        }

        static void CopyPositionsAndNormals(Mesh.MeshData from, Mesh.MeshData to, int n)
        {
            var positions = new NativeArray<Vector3>(n, Allocator.Temp, NativeArrayOptions.UninitializedMemory);
            from.GetVertices(positions);
            bool hasNormals = from.HasVertexAttribute(VertexAttribute.Normal);
            var normals = new NativeArray<Vector3>(hasNormals ? n : 0, Allocator.Temp, NativeArrayOptions.UninitializedMemory);
            if (hasNormals)
                from.GetNormals(normals);
            NativeArray<DeformedVertex> vertices = to.GetVertexData<DeformedVertex>(DeformedStream);
            for (int v = 0; v < n; v++)
            {
                Vector3 p = positions[v];
                Vector3 normal = hasNormals ? normals[v] : new Vector3(0f, 1f, 0f);
                vertices[v] = new DeformedVertex
                {
                    Position = new Unity.Mathematics.float3(p.x, p.y, p.z),
                    Normal = new Unity.Mathematics.float3(normal.x, normal.y, normal.z),
                };
            }
            positions.Dispose();
            normals.Dispose();
        }

        static void CopyAttribute(Mesh.MeshData from, Mesh.MeshData to, VertexAttributeDescriptor attribute, int n)
        {
            int size = FormatSize(attribute.format) * attribute.dimension;
            int fromStream = from.GetVertexAttributeStream(attribute.attribute);
            int fromOffset = from.GetVertexAttributeOffset(attribute.attribute);
            int fromStride = from.GetVertexBufferStride(fromStream);
            int toOffset = to.GetVertexAttributeOffset(attribute.attribute);
            int toStride = to.GetVertexBufferStride(StaticStream);
            NativeArray<byte> source = from.GetVertexData<byte>(fromStream);
            NativeArray<byte> target = to.GetVertexData<byte>(StaticStream);
            for (int v = 0; v < n; v++)
                NativeArray<byte>.Copy(source, v * fromStride + fromOffset, target, v * toStride + toOffset, size);
        }

        static void CopyIndices(Mesh.MeshData from, Mesh.MeshData to)
        {
            NativeArray<byte> sourceIndices = from.GetIndexData<byte>();
            int indexSize = from.indexFormat == IndexFormat.UInt16 ? 2 : 4;
            to.SetIndexBufferParams(sourceIndices.Length / indexSize, from.indexFormat);
            to.GetIndexData<byte>().CopyFrom(sourceIndices);
            int subMeshes = from.subMeshCount;
            to.subMeshCount = subMeshes;
            for (int s = 0; s < subMeshes; s++)
                to.SetSubMesh(s, from.GetSubMesh(s));
        }

        /// <summary>Bytes of one component of <paramref name="format"/>.</summary>
        static int FormatSize(VertexAttributeFormat format)
        {
            switch (format)
            {
                case VertexAttributeFormat.Float32:
                case VertexAttributeFormat.UInt32:
                case VertexAttributeFormat.SInt32:
                    return 4;
                case VertexAttributeFormat.Float16:
                case VertexAttributeFormat.UNorm16:
                case VertexAttributeFormat.SNorm16:
                case VertexAttributeFormat.UInt16:
                case VertexAttributeFormat.SInt16:
                    return 2;
                default:
                    return 1;
            }
        }
    }
}
