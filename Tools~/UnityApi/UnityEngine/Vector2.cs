namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Vector2.html (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Math/Vector2.cs)
    public struct Vector2
    {
        // https://docs.unity3d.com/ScriptReference/Vector2-x.html
        public float x;
        // https://docs.unity3d.com/ScriptReference/Vector2-y.html
        public float y;

        // https://docs.unity3d.com/ScriptReference/Vector2-ctor.html
        public Vector2(float x, float y) => throw null;
    }
}
