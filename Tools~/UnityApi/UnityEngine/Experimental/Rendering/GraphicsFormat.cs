namespace UnityEngine.Experimental.Rendering
{
    // https://docs.unity3d.com/ScriptReference/Experimental.Rendering.GraphicsFormat.html (checked: UnityCsReference
    // 6000.0.78f1 Runtime/Export/Graphics/GraphicsEnums.cs; only the members package code uses, with their values)
    public enum GraphicsFormat
    {
        None = 0,
        R16G16B16A16_SFloat = 48,
    }
}
