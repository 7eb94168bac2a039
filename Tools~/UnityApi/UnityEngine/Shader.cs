namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Shader.html
    public sealed class Shader : Object
    {
        // https://docs.unity3d.com/ScriptReference/Shader.PropertyToID.html
        public static int PropertyToID(string name) => throw null;
    }
}
