namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Vector3.html
    public struct Vector3
    {
        // https://docs.unity3d.com/ScriptReference/Vector3-x.html
        public float x;
        // https://docs.unity3d.com/ScriptReference/Vector3-y.html
        public float y;
        // https://docs.unity3d.com/ScriptReference/Vector3-z.html
        public float z;

        // https://docs.unity3d.com/ScriptReference/Vector3-ctor.html
        public Vector3(float x, float y, float z) => throw null;

        // https://docs.unity3d.com/ScriptReference/Vector3-zero.html
        public static Vector3 zero => throw null;
        // https://docs.unity3d.com/ScriptReference/Vector3-one.html
        public static Vector3 one => throw null;
    }
}
