namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Bounds.html (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Geometry/Bounds.cs)
    public struct Bounds
    {
        // https://docs.unity3d.com/ScriptReference/Bounds-ctor.html
        public Bounds(Vector3 center, Vector3 size) => throw null;

        // https://docs.unity3d.com/ScriptReference/Bounds.Contains.html (checked: UnityCsReference 6000.0 Runtime/Export/Geometry/Bounds.cs;
        // inclusive of the faces)
        public bool Contains(Vector3 point) => throw null;
    }
}
