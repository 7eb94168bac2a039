namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Light.html
    public sealed class Light : Behaviour
    {
        // https://docs.unity3d.com/ScriptReference/Light-type.html
        public LightType type { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Light-intensity.html
        public float intensity { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Light-color.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Graphics/GraphicsComponents.bindings.cs)
        public Color color { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Light-shadows.html
        public LightShadows shadows { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/ScriptReference/LightType.html (values UNCONFIRMED; names from the page)
    public enum LightType
    {
        Spot = 0,
        Directional = 1,
        Point = 2,
    }

    // https://docs.unity3d.com/ScriptReference/LightShadows.html (values UNCONFIRMED; names from the page)
    public enum LightShadows
    {
        None = 0,
        Hard = 1,
        Soft = 2,
    }
}
