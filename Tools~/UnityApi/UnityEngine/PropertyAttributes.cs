using System;

namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/PropertyAttribute.html
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public abstract class PropertyAttribute : Attribute
    {
    }

    // https://docs.unity3d.com/ScriptReference/TooltipAttribute.html
    public class TooltipAttribute : PropertyAttribute
    {
        // https://docs.unity3d.com/ScriptReference/TooltipAttribute-ctor.html
        public TooltipAttribute(string tooltip) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/RangeAttribute.html
    public sealed class RangeAttribute : PropertyAttribute
    {
        // https://docs.unity3d.com/ScriptReference/RangeAttribute-ctor.html
        public RangeAttribute(float min, float max) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/MinAttribute.html
    public sealed class MinAttribute : PropertyAttribute
    {
        // https://docs.unity3d.com/ScriptReference/MinAttribute-ctor.html
        public MinAttribute(float min) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/HeaderAttribute.html
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = true)]
    public class HeaderAttribute : PropertyAttribute
    {
        // https://docs.unity3d.com/ScriptReference/HeaderAttribute-ctor.html
        public HeaderAttribute(string header) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/SerializeField.html
    [AttributeUsage(AttributeTargets.Field)]
    public sealed class SerializeField : Attribute
    {
    }

    // https://docs.unity3d.com/ScriptReference/HideInInspector.html
    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public class HideInInspector : Attribute
    {
    }
}
