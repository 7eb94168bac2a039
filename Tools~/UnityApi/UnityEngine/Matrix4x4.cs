namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Matrix4x4.html
    public struct Matrix4x4
    {
        // https://docs.unity3d.com/ScriptReference/Matrix4x4-identity.html
        public static Matrix4x4 identity => throw null;

        // https://docs.unity3d.com/ScriptReference/Matrix4x4.Index_operator.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Math/Matrix4x4.cs)
        public float this[int row, int column] { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Matrix4x4.TRS.html
        public static Matrix4x4 TRS(Vector3 pos, Quaternion q, Vector3 s) => throw null;
    }
}
