namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Vector4.html
    public struct Vector4
    {
        // https://docs.unity3d.com/ScriptReference/Vector4-x.html (and y, z, w)
        public float x, y, z, w;

        // https://docs.unity3d.com/ScriptReference/Vector4-ctor.html
        public Vector4(float x, float y, float z, float w) => throw null;
    }
}
