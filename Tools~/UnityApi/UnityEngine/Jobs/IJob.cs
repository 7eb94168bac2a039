namespace Unity.Jobs
{
    // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJob.html
    // (checked: UnityCsReference Runtime/Jobs/Managed/IJob.cs; UnityEngine.CoreModule)
    public interface IJob
    {
        // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJob.Execute.html
        void Execute();
    }

    // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJobExtensions.html (same source)
    public static class IJobExtensions
    {
        // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJobExtensions.Run.html
        // "Performs the job's Execute method immediately on the same thread" (Burst-compiled when the job is).
        public static void Run<T>(this T jobData) where T : struct, IJob => throw null;
        // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJobExtensions.Schedule.html
        // (public static JobHandle Schedule<T>(this T jobData, JobHandle dependsOn = new JobHandle()) where T : struct, IJob)
        public static JobHandle Schedule<T>(this T jobData, JobHandle dependsOn = new JobHandle()) where T : struct, IJob => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJobParallelFor.html
    public interface IJobParallelFor
    {
        // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJobParallelFor.Execute.html
        void Execute(int index);
    }

    // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJobParallelForExtensions.html
    public static class IJobParallelForExtensions
    {
        // https://docs.unity3d.com/ScriptReference/Unity.Jobs.IJobParallelForExtensions.Schedule.html
        // (public static JobHandle Schedule<T>(this T jobData, int arrayLength, int innerloopBatchCount, JobHandle dependsOn = new JobHandle()) where T : struct, IJobParallelFor)
        public static JobHandle Schedule<T>(this T jobData, int arrayLength, int innerloopBatchCount, JobHandle dependsOn = new JobHandle())
            where T : struct, IJobParallelFor => throw null;
    }
}
