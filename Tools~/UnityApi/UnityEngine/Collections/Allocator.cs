namespace Unity.Collections
{
    // https://docs.unity3d.com/ScriptReference/Unity.Collections.Allocator.html
    // (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Collections/NativeCollectionEnums.bindings.cs)
    public enum Allocator
    {
        Invalid = 0,
        None = 1,
        Temp = 2,
        TempJob = 3,
        Persistent = 4,
        AudioKernel = 5,
        Domain = 6,
        FirstUserIndex = 64,
    }
}
