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
    }
}
