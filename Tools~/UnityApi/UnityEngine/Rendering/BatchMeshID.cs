using System;

namespace UnityEngine.Rendering
{
    // https://docs.unity3d.com/ScriptReference/Rendering.BatchMeshID.html
    // (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Rendering/BatchRendererGroup.bindings.cs)
    public struct BatchMeshID : IEquatable<BatchMeshID>
    {
        // https://docs.unity3d.com/ScriptReference/Rendering.BatchMeshID.Null.html
        public static readonly BatchMeshID Null;
        // https://docs.unity3d.com/ScriptReference/Rendering.BatchMeshID.Equals.html
        public bool Equals(BatchMeshID other) => throw null;
    }
}
