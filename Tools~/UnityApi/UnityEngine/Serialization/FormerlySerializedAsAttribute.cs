using System;

namespace UnityEngine.Serialization
{
    // https://docs.unity3d.com/ScriptReference/Serialization.FormerlySerializedAsAttribute.html
    [AttributeUsage(AttributeTargets.Field, AllowMultiple = true, Inherited = false)]
    public class FormerlySerializedAsAttribute : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/Serialization.FormerlySerializedAsAttribute-ctor.html
        public FormerlySerializedAsAttribute(string oldName) => throw null;
        // https://docs.unity3d.com/ScriptReference/Serialization.FormerlySerializedAsAttribute-oldName.html
        public string oldName => throw null;
    }
}
