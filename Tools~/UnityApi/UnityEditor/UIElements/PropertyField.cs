using System;
using UnityEngine.UIElements;

namespace UnityEditor.UIElements
{
    // https://docs.unity3d.com/ScriptReference/UIElements.PropertyField.html
    public class PropertyField : VisualElement
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.PropertyField-ctor.html
        public PropertyField(SerializedProperty property) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.BindingExtensions.html
    public static class BindingExtensions
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.BindingExtensions.TrackSerializedObjectValue.html
        public static void TrackSerializedObjectValue(this VisualElement element, SerializedObject obj, Action<SerializedObject> callback) => throw null;
    }
}
