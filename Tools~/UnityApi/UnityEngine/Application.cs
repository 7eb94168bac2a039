namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Application.html
    public class Application
    {
        // https://docs.unity3d.com/ScriptReference/Application-isPlaying.html (checked: UnityCsReference 6000.0.22f1 Runtime/Export/Device/Application.cs)
        public static bool isPlaying => throw null;
    }
}
