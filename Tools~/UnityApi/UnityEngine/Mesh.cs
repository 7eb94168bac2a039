using System.Collections.Generic;

namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Mesh.html
    public sealed partial class Mesh : Object
    {
        // https://docs.unity3d.com/ScriptReference/Mesh-ctor.html
        public Mesh() => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh-isReadable.html
        public bool isReadable => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh-vertexCount.html
        public int vertexCount => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh-subMeshCount.html
        public int subMeshCount { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Mesh-vertices.html
        public Vector3[] vertices { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Mesh-triangles.html
        public int[] triangles { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Mesh.GetTriangles.html
        public int[] GetTriangles(int submesh) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.GetTopology.html
        public MeshTopology GetTopology(int submesh) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.UploadMeshData.html
        public void UploadMeshData(bool markNoLongerReadable) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.RecalculateNormals.html
        public void RecalculateNormals(UnityEngine.Rendering.MeshUpdateFlags flags = UnityEngine.Rendering.MeshUpdateFlags.Default) => throw null;

        // https://docs.unity3d.com/ScriptReference/Mesh.RecalculateBounds.html
        public void RecalculateBounds(UnityEngine.Rendering.MeshUpdateFlags flags = UnityEngine.Rendering.MeshUpdateFlags.Default) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/MeshTopology.html (values UNCONFIRMED; names from the page)
    public enum MeshTopology
    {
        Triangles = 0,
        Quads = 2,
        Lines = 3,
        LineStrip = 4,
        Points = 5,
    }
}
