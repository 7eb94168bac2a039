namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/LogType.html (UnityEngine.CoreModule). Members in the documented order
    // Error, Assert, Warning, Log, Exception; the numeric values are not documented and package code does not use them.
    public enum LogType
    {
        Error,
        Assert,
        Warning,
        Log,
        Exception,
    }
}
