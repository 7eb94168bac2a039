namespace UnityEditor
{
    // https://docs.unity3d.com/ScriptReference/SerializedObject.html
    public class SerializedObject
    {
        // https://docs.unity3d.com/ScriptReference/SerializedObject-ctor.html
        public SerializedObject(UnityEngine.Object[] objs) => throw null;
        // https://docs.unity3d.com/ScriptReference/SerializedObject.FindProperty.html
        public SerializedProperty FindProperty(string propertyPath) => throw null;
        // https://docs.unity3d.com/ScriptReference/SerializedObject.Update.html
        public void Update() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/SerializedProperty.html
    public class SerializedProperty
    {
    }
}
