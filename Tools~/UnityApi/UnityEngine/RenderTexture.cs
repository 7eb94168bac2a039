namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Texture.html
    public class Texture : Object
    {
    }

    // https://docs.unity3d.com/ScriptReference/RenderTexture.html
    public class RenderTexture : Texture
    {
        // https://docs.unity3d.com/ScriptReference/RenderTexture-ctor.html
        public RenderTexture(int width, int height, int depth, RenderTextureFormat format) => throw null;

        // https://docs.unity3d.com/ScriptReference/RenderTexture-enableRandomWrite.html
        public bool enableRandomWrite { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/RenderTexture.Create.html
        public bool Create() => throw null;

        // https://docs.unity3d.com/ScriptReference/RenderTexture.Release.html
        public void Release() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/RenderTextureFormat.html
    public enum RenderTextureFormat
    {
        // https://docs.unity.com/en-us/engine/6000.0/script-reference/unityengine/rendertextureformat/argbhalf ("ARGBHalf = 2")
        ARGBHalf = 2,
        // https://docs.unity3d.com/ScriptReference/RenderTextureFormat.RFloat.html (value UNCONFIRMED: the enum's order puts it at 14)
        RFloat = 14,
    }
}
