namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/GeometryUtility.html (checked: UnityCsReference 6000.0.78f1
    // Runtime/Export/Geometry/GeometryUtility.cs and Runtime/Export/Graphics/Graphics.bindings.cs)
    public sealed class GeometryUtility
    {
        // https://docs.unity3d.com/ScriptReference/GeometryUtility.CalculateFrustumPlanes.html (allocates a new array of 6)
        public static Plane[] CalculateFrustumPlanes(Camera camera) => throw null;

        // https://docs.unity3d.com/ScriptReference/GeometryUtility.CalculateFrustumPlanes.html (fills planes, which must have length 6)
        public static void CalculateFrustumPlanes(Camera camera, Plane[] planes) => throw null;

        // https://docs.unity3d.com/ScriptReference/GeometryUtility.TestPlanesAABB.html (true when the box is inside or intersects the planes)
        public static bool TestPlanesAABB(Plane[] planes, Bounds bounds) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/Plane.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Geometry/Plane.cs)
    public struct Plane
    {
    }
}
