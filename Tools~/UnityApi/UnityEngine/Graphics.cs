namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Graphics.html
    public class Graphics
    {
        // https://docs.unity3d.com/ScriptReference/Graphics.CopyBuffer.html
        public static void CopyBuffer(GraphicsBuffer source, GraphicsBuffer dest) => throw null;
    }
}
