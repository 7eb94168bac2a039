namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Gizmos.html
    public sealed class Gizmos
    {
        // https://docs.unity3d.com/ScriptReference/Gizmos-color.html
        public static Color color { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Gizmos-matrix.html
        public static Matrix4x4 matrix { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Gizmos.DrawWireSphere.html
        public static void DrawWireSphere(Vector3 center, float radius) => throw null;
        // https://docs.unity3d.com/ScriptReference/Gizmos.DrawSphere.html
        public static void DrawSphere(Vector3 center, float radius) => throw null;
        // https://docs.unity3d.com/ScriptReference/Gizmos.DrawWireCube.html
        public static void DrawWireCube(Vector3 center, Vector3 size) => throw null;
        // https://docs.unity3d.com/ScriptReference/Gizmos.DrawLine.html
        public static void DrawLine(Vector3 from, Vector3 to) => throw null;
    }
}
