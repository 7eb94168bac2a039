using System;
using UnityEngine.UIElements;

namespace UnityEditor
{
    // https://docs.unity3d.com/ScriptReference/Editor.html
    public class Editor : UnityEngine.ScriptableObject
    {
        // https://docs.unity3d.com/ScriptReference/Editor-target.html
        public UnityEngine.Object target { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Editor-targets.html
        public UnityEngine.Object[] targets => throw null;
        // https://docs.unity3d.com/ScriptReference/Editor-serializedObject.html
        public SerializedObject serializedObject => throw null;
        // https://docs.unity3d.com/ScriptReference/Editor.CreateInspectorGUI.html
        public virtual VisualElement CreateInspectorGUI() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/CustomEditor.html
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true, Inherited = false)]
    public class CustomEditor : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/CustomEditor-ctor.html
        public CustomEditor(Type inspectedType) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/CanEditMultipleObjects.html
    [AttributeUsage(AttributeTargets.Class)]
    public sealed class CanEditMultipleObjects : Attribute
    {
    }
}
