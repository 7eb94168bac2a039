namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Matrix4x4.html
    public struct Matrix4x4
    {
        // https://docs.unity3d.com/ScriptReference/Matrix4x4-identity.html
        public static Matrix4x4 identity => throw null;

        // https://docs.unity3d.com/ScriptReference/Matrix4x4.TRS.html
        public static Matrix4x4 TRS(Vector3 pos, Quaternion q, Vector3 s) => throw null;
    }
}
