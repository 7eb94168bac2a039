namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Debug.html
    public class Debug
    {
        // https://docs.unity3d.com/ScriptReference/Debug.Log.html
        public static void Log(object message) => throw null;
        // https://docs.unity3d.com/ScriptReference/Debug.LogError.html
        public static void LogError(object message) => throw null;
        // https://docs.unity3d.com/ScriptReference/Debug.LogError.html
        public static void LogError(object message, Object context) => throw null;
        // https://docs.unity3d.com/ScriptReference/Debug.LogWarning.html
        public static void LogWarning(object message) => throw null;
        // https://docs.unity3d.com/ScriptReference/Debug.LogWarning.html
        public static void LogWarning(object message, Object context) => throw null;
    }
}
