// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.universal/Runtime/UniversalRenderPipelineCore.cs
// (the ContextContainer-backed RenderingData and CameraData of URP 17).
namespace UnityEngine.Rendering.Universal
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.RenderingData.html
    public struct RenderingData
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.RenderingData.html#UnityEngine_Rendering_Universal_RenderingData_cameraData
        public CameraData cameraData;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.CameraData.html
    // (a view onto this frame's UniversalCameraData)
    public struct CameraData
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.CameraData.html#UnityEngine_Rendering_Universal_CameraData_camera
        public ref Camera camera => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.universal@17.0/api/UnityEngine.Rendering.Universal.CameraData.html#UnityEngine_Rendering_Universal_CameraData_cameraType
        public ref CameraType cameraType => throw null;
    }
}
