using System;

namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/DisallowMultipleComponent.html
    [AttributeUsage(AttributeTargets.Class, Inherited = false, AllowMultiple = false)]
    public sealed class DisallowMultipleComponent : Attribute
    {
    }

    // https://docs.unity3d.com/ScriptReference/AddComponentMenu.html
    public sealed class AddComponentMenu : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/AddComponentMenu-ctor.html
        public AddComponentMenu(string menuName) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/HelpURLAttribute.html
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = false)]
    public class HelpURLAttribute : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/HelpURLAttribute-ctor.html
        public HelpURLAttribute(string url) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/RequireComponent.html
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponent : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/RequireComponent-ctor.html
        public RequireComponent(Type requiredComponent) => throw null;
    }
}
