// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.core/Runtime/Utilities/CoreUtils.cs.
namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.CoreUtils.html
    public static class CoreUtils
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.CoreUtils.html#UnityEngine_Rendering_CoreUtils_CreateEngineMaterial_UnityEngine_Shader_
        // (a Material with hideFlags HideAndDontSave; null, with an error logged, when the shader is null)
        public static Material CreateEngineMaterial(Shader shader) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.CoreUtils.html#UnityEngine_Rendering_CoreUtils_Destroy_UnityEngine_Object_
        // (Destroy in play mode, DestroyImmediate in the editor; ignores null)
        public static void Destroy(Object obj) => throw null;
    }
}
