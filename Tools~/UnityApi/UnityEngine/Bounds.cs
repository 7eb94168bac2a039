namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Bounds.html (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Geometry/Bounds.cs)
    public struct Bounds
    {
        // https://docs.unity3d.com/ScriptReference/Bounds-ctor.html
        public Bounds(Vector3 center, Vector3 size) => throw null;
    }
}
