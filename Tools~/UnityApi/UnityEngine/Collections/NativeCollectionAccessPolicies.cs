using System;

// Checked: UnityCsReference 6000.0.22f1 Runtime/Export/Collections/NativeCollectionAccessPolicies.cs.
namespace Unity.Collections
{
    // https://docs.unity3d.com/ScriptReference/Unity.Collections.ReadOnlyAttribute.html
    [AttributeUsage(AttributeTargets.Field | AttributeTargets.Parameter | AttributeTargets.ReturnValue)]
    public sealed class ReadOnlyAttribute : Attribute
    {
    }

    // https://docs.unity3d.com/ScriptReference/Unity.Collections.NativeDisableParallelForRestrictionAttribute.html
    [AttributeUsage(AttributeTargets.Field)]
    public sealed class NativeDisableParallelForRestrictionAttribute : Attribute
    {
    }
}
