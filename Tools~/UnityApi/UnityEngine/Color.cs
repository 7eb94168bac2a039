namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Color.html
    public struct Color
    {
        // https://docs.unity3d.com/ScriptReference/Color-r.html
        public float r;
        // https://docs.unity3d.com/ScriptReference/Color-g.html
        public float g;
        // https://docs.unity3d.com/ScriptReference/Color-b.html
        public float b;
        // https://docs.unity3d.com/ScriptReference/Color-a.html
        public float a;

        // https://docs.unity3d.com/ScriptReference/Color-ctor.html
        public Color(float r, float g, float b) => throw null;
        // https://docs.unity3d.com/ScriptReference/Color-ctor.html
        public Color(float r, float g, float b, float a) => throw null;

        // https://docs.unity3d.com/ScriptReference/Color-linear.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Math/Color.cs;
        // the sRGB → linear curve applied to r, g, b whatever the project's colour space)
        public Color linear => throw null;
    }
}
