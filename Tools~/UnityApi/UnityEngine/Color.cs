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
    }
}
