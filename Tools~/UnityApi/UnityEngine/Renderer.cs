namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Renderer.html
    public class Renderer : Component
    {
        // https://docs.unity3d.com/ScriptReference/Renderer-sharedMaterial.html
        public Material sharedMaterial { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/ScriptReference/MeshRenderer.html
    public class MeshRenderer : Renderer
    {
    }
}
