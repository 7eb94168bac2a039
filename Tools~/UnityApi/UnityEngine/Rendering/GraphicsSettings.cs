namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/ScriptReference/Rendering.GraphicsSettings.html
    public sealed class GraphicsSettings : Object
    {
        // https://docs.unity3d.com/ScriptReference/Rendering.GraphicsSettings-currentRenderPipeline.html
        public static RenderPipelineAsset currentRenderPipeline => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/Rendering.RenderPipelineAsset.html
    public abstract class RenderPipelineAsset : ScriptableObject
    {
        // https://docs.unity3d.com/ScriptReference/Rendering.RenderPipelineAsset-defaultMaterial.html
        public virtual Material defaultMaterial => throw null;
    }
}
