namespace Unity.Jobs
{
    // https://docs.unity3d.com/ScriptReference/Unity.Jobs.JobHandle.html
    // (checked: UnityCsReference 6000.0.22f1 Runtime/Jobs/ScriptBindings/JobHandle.bindings.cs)
    public struct JobHandle
    {
        // https://docs.unity3d.com/ScriptReference/Unity.Jobs.JobHandle.Complete.html
        public void Complete() => throw null;
        // https://docs.unity3d.com/ScriptReference/Unity.Jobs.JobHandle.CombineDependencies.html
        // (public static JobHandle CombineDependencies(JobHandle job0, JobHandle job1))
        public static JobHandle CombineDependencies(JobHandle job0, JobHandle job1) => throw null;
    }
}
