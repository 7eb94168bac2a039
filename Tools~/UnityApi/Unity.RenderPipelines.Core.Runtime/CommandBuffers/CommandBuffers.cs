// Source: Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.core/Runtime/CommandBuffers/ComputeCommandBuffer.cs
// and RasterCommandBuffer.cs (generated wrappers over UnityEngine.Rendering.CommandBuffer, public since SRP Core 16).
using Unity.Collections;

namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.BaseCommandBuffer.html
    public class BaseCommandBuffer
    {
        internal BaseCommandBuffer() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.RasterCommandBuffer.html
    // (created by the render graph for a raster pass; users never construct one)
    public class RasterCommandBuffer : BaseCommandBuffer
    {
        internal RasterCommandBuffer() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ComputeCommandBuffer.html
    // (created by the render graph for a compute pass; users never construct one)
    public class ComputeCommandBuffer : BaseCommandBuffer
    {
        internal ComputeCommandBuffer() => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ComputeCommandBuffer.html#UnityEngine_Rendering_ComputeCommandBuffer_SetBufferData__1_UnityEngine_GraphicsBuffer_Unity_Collections_NativeArray___0__
        // (wraps CommandBuffer.SetBufferData: https://docs.unity3d.com/ScriptReference/Rendering.CommandBuffer.SetBufferData.html)
        public void SetBufferData<T>(GraphicsBuffer buffer, NativeArray<T> data) where T : struct => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ComputeCommandBuffer.html#UnityEngine_Rendering_ComputeCommandBuffer_SetComputeConstantBufferParam_UnityEngine_ComputeShader_System_Int32_UnityEngine_GraphicsBuffer_System_Int32_System_Int32_
        // (wraps https://docs.unity3d.com/ScriptReference/Rendering.CommandBuffer.SetComputeConstantBufferParam.html)
        public void SetComputeConstantBufferParam(ComputeShader computeShader, int nameID, GraphicsBuffer buffer, int offset, int size) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ComputeCommandBuffer.html#UnityEngine_Rendering_ComputeCommandBuffer_SetComputeBufferParam_UnityEngine_ComputeShader_System_Int32_System_Int32_UnityEngine_GraphicsBuffer_
        public void SetComputeBufferParam(ComputeShader computeShader, int kernelIndex, int nameID, GraphicsBuffer buffer) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ComputeCommandBuffer.html#UnityEngine_Rendering_ComputeCommandBuffer_SetComputeTextureParam_UnityEngine_ComputeShader_System_Int32_System_Int32_UnityEngine_Rendering_RenderGraphModule_TextureHandle_
        // (the handle must be declared on the pass with UseTexture; the wrapper validates it)
        public void SetComputeTextureParam(ComputeShader computeShader, int kernelIndex, int nameID, RenderGraphModule.TextureHandle rt) => throw null;

        // https://docs.unity3d.com/Packages/com.unity.render-pipelines.core@17.0/api/UnityEngine.Rendering.ComputeCommandBuffer.html#UnityEngine_Rendering_ComputeCommandBuffer_DispatchCompute_UnityEngine_ComputeShader_System_Int32_System_Int32_System_Int32_System_Int32_
        public void DispatchCompute(ComputeShader computeShader, int kernelIndex, int threadGroupsX, int threadGroupsY, int threadGroupsZ) => throw null;
    }
}
