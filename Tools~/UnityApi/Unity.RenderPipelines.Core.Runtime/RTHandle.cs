// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.core/Runtime/Textures/RTHandle.cs.
namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RTHandle.html
    public class RTHandle
    {
        internal RTHandle() => throw null;
    }
}
