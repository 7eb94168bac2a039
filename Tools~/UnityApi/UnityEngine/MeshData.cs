using System;
using Unity.Collections;
using UnityEngine.Rendering;

// Mesh members of the native-array path (MeshData, vertex streams). Signatures checked against
// Unity-Technologies/UnityCsReference @ 6000.0.22f1: Runtime/Export/Graphics/Mesh.cs, Mesh.bindings.cs, MeshData.cs.
namespace UnityEngine
{
    public sealed partial class Mesh
    {
        // https://docs.unity3d.com/ScriptReference/Mesh-bounds.html
        public Bounds bounds { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Mesh-normals.html
        public Vector3[] normals { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Mesh-uv.html
        public Vector2[] uv { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Mesh.GetVertexAttributeStream.html
        public int GetVertexAttributeStream(VertexAttribute attr) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.GetVertexBufferStride.html
        public int GetVertexBufferStride(int stream) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.MarkDynamic.html
        public void MarkDynamic() => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.GetVertexAttributes.html
        public VertexAttributeDescriptor[] GetVertexAttributes() => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.SetVertexBufferData.html
        public void SetVertexBufferData<T>(NativeArray<T> data, int dataStart, int meshBufferStart, int count, int stream = 0,
            MeshUpdateFlags flags = MeshUpdateFlags.Default) where T : struct => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.AcquireReadOnlyMeshData.html
        public static MeshDataArray AcquireReadOnlyMeshData(Mesh mesh) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.AllocateWritableMeshData.html
        public static MeshDataArray AllocateWritableMeshData(int meshCount) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.ApplyAndDisposeWritableMeshData.html
        public static void ApplyAndDisposeWritableMeshData(MeshDataArray data, Mesh mesh,
            MeshUpdateFlags flags = MeshUpdateFlags.Default) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.MeshDataArray.html
        public struct MeshDataArray : IDisposable
        {
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshDataArray.Index_operator.html
            public MeshData this[int index] => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshDataArray.Dispose.html
            public void Dispose() => throw null;
        }

        // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.html
        public struct MeshData
        {
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData-vertexCount.html
            public int vertexCount => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.HasVertexAttribute.html
            public bool HasVertexAttribute(VertexAttribute attr) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetVertexAttributeStream.html
            public int GetVertexAttributeStream(VertexAttribute attr) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetVertexAttributeOffset.html
            public int GetVertexAttributeOffset(VertexAttribute attr) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetVertexBufferStride.html
            public int GetVertexBufferStride(int stream) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetVertices.html
            public void GetVertices(NativeArray<Vector3> outVertices) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetNormals.html
            public void GetNormals(NativeArray<Vector3> outNormals) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetVertexData.html
            public NativeArray<T> GetVertexData<T>(int stream = 0) where T : struct => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.SetVertexBufferParams.html
            public void SetVertexBufferParams(int vertexCount, params VertexAttributeDescriptor[] attributes) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData-indexFormat.html
            public IndexFormat indexFormat => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.SetIndexBufferParams.html
            public void SetIndexBufferParams(int indexCount, IndexFormat format) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetIndexData.html
            public NativeArray<T> GetIndexData<T>() where T : struct => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData-subMeshCount.html
            public int subMeshCount { get => throw null; set => throw null; }
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.GetSubMesh.html
            public SubMeshDescriptor GetSubMesh(int index) => throw null;
            // https://docs.unity3d.com/ScriptReference/Mesh.MeshData.SetSubMesh.html
            public void SetSubMesh(int index, SubMeshDescriptor desc, MeshUpdateFlags flags = MeshUpdateFlags.Default) => throw null;
        }
    }
}
