// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.core/Runtime/Textures/MSAASamples.cs.
namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.MSAASamples.html
    public enum MSAASamples
    {
        None = 1,
        MSAA2x = 2,
        MSAA4x = 4,
        MSAA8x = 8,
    }
}
