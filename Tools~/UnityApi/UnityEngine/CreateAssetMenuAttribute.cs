using System;

namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/CreateAssetMenuAttribute.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Scripting/Attributes.cs)
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = false, Inherited = false)]
    public sealed class CreateAssetMenuAttribute : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/CreateAssetMenuAttribute-menuName.html
        public string menuName { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/CreateAssetMenuAttribute-fileName.html
        public string fileName { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/CreateAssetMenuAttribute-order.html
        public int order { get => throw null; set => throw null; }
    }
}
