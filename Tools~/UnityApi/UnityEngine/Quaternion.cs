namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Quaternion.html
    public struct Quaternion
    {
        // https://docs.unity3d.com/ScriptReference/Quaternion-x.html
        public float x;
        // https://docs.unity3d.com/ScriptReference/Quaternion-y.html
        public float y;
        // https://docs.unity3d.com/ScriptReference/Quaternion-z.html
        public float z;
        // https://docs.unity3d.com/ScriptReference/Quaternion-w.html
        public float w;

        // https://docs.unity3d.com/ScriptReference/Quaternion-ctor.html
        public Quaternion(float x, float y, float z, float w) => throw null;

        // https://docs.unity3d.com/ScriptReference/Quaternion-identity.html
        public static Quaternion identity => throw null;

        // https://docs.unity3d.com/ScriptReference/Quaternion.Euler.html
        public static Quaternion Euler(float x, float y, float z) => throw null;
    }
}
