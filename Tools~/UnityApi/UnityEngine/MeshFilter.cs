namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/MeshFilter.html
    public sealed class MeshFilter : Component
    {
        // https://docs.unity3d.com/ScriptReference/MeshFilter-sharedMesh.html
        public Mesh sharedMesh { get => throw null; set => throw null; }
    }
}
