namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/RenderTextureDescriptor.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Graphics/Texture.cs)
    public struct RenderTextureDescriptor
    {
        // https://docs.unity3d.com/ScriptReference/RenderTextureDescriptor-width.html
        public int width { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/RenderTextureDescriptor-height.html
        public int height { get => throw null; set => throw null; }
    }
}
