namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/RenderSettings.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Graphics/GraphicsManagers.bindings.cs)
    public sealed class RenderSettings : Object
    {
        // https://docs.unity3d.com/ScriptReference/RenderSettings-sun.html (the Lighting window's Sun Source; null when none is set)
        public static Light sun { get => throw null; set => throw null; }
    }
}
