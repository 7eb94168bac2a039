namespace Unity.Jobs
{
    // https://docs.unity3d.com/ScriptReference/Unity.Jobs.JobHandle.html
    // (checked: UnityCsReference 6000.0.22f1 Runtime/Jobs/ScriptBindings/JobHandle.bindings.cs)
    public struct JobHandle
    {
    }
}
