namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/ScriptableObject.html
    public class ScriptableObject : Object
    {
    }
}
