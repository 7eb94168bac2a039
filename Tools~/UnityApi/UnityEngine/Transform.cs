namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Transform.html
    public class Transform : Component
    {
        // https://docs.unity3d.com/ScriptReference/Transform-position.html
        public Vector3 position { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Transform-rotation.html
        public Quaternion rotation { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Transform-lossyScale.html
        public Vector3 lossyScale => throw null;
        // https://docs.unity3d.com/ScriptReference/Transform-localScale.html
        public Vector3 localScale { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Transform-localToWorldMatrix.html
        public Matrix4x4 localToWorldMatrix => throw null;
        // https://docs.unity3d.com/ScriptReference/Transform-forward.html (checked: UnityCsReference 6000.0.78f1 Runtime/Transform/ScriptBindings/Transform.bindings.cs)
        public Vector3 forward { get => throw null; set => throw null; }
    }
}
