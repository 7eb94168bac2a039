// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blitter.cs; the
// overload below is listed in the SRP Core API reference from 15.0 on.
namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.Blitter.html
    public static class Blitter
    {
        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.Blitter.html#UnityEngine_Rendering_Blitter_BlitTexture_UnityEngine_Rendering_RasterCommandBuffer_UnityEngine_Rendering_RTHandle_UnityEngine_Vector4_UnityEngine_Material_System_Int32_
        // (draws a full-screen triangle with the material's pass, _BlitTexture = source, _BlitScaleBias = scaleBias)
        public static void BlitTexture(RasterCommandBuffer cmd, RTHandle source, Vector4 scaleBias, Material material, int pass) => throw null;
    }
}
