namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/ScriptableObject.html
    public class ScriptableObject : Object
    {
        // https://docs.unity3d.com/ScriptReference/ScriptableObject.CreateInstance.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Scripting/ScriptableObject.bindings.cs)
        public static T CreateInstance<T>() where T : ScriptableObject => throw null;
    }
}
