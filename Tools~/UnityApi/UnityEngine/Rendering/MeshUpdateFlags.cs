using System;

namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/ScriptReference/Rendering.MeshUpdateFlags.html
    // (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Graphics/GraphicsEnums.cs)
    [Flags]
    public enum MeshUpdateFlags
    {
        Default = 0,
        DontValidateIndices = 1 << 0,
        DontResetBoneBounds = 1 << 1,
        DontNotifyMeshUsers = 1 << 2,
        DontRecalculateBounds = 1 << 3,
    }

    // https://docs.unity3d.com/ScriptReference/Rendering.IndexFormat.html
    public enum IndexFormat
    {
        UInt16 = 0,
        UInt32 = 1,
    }

    // https://docs.unity3d.com/ScriptReference/Rendering.SubMeshDescriptor.html (passed through unchanged; no members used)
    public struct SubMeshDescriptor
    {
    }
}
