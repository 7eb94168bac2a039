namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Application.html
    public class Application
    {
        // https://docs.unity3d.com/ScriptReference/Application-isPlaying.html (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Device/Application.cs)
        public static bool isPlaying => throw null;

        // https://docs.unity3d.com/ScriptReference/Application.LogCallback.html (checked: UnityCsReference
        // Runtime/Export/Application/Application.cs)
        public delegate void LogCallback(string condition, string stackTrace, LogType type);

        // https://docs.unity3d.com/ScriptReference/Application-logMessageReceived.html (same source; main-thread logs only)
        public static event LogCallback logMessageReceived { add => throw null; remove => throw null; }
    }
}
