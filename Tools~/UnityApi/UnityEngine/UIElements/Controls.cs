using System;

namespace UnityEngine.UIElements
{
    // https://docs.unity3d.com/ScriptReference/UIElements.Label.html
    public class Label : TextElement
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.Label-ctor.html
        public Label() => throw null;
        // https://docs.unity3d.com/ScriptReference/UIElements.Label-ctor.html
        public Label(string text) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.Button.html
    public class Button : TextElement
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.Button-ctor.html
        public Button(Action clickEvent) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.Foldout.html
    public class Foldout : BindableElement
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.Foldout-ctor.html
        public Foldout() => throw null;
        // https://docs.unity3d.com/ScriptReference/UIElements.Foldout-text.html
        public string text { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/UIElements.Foldout-value.html
        public bool value { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.HelpBox.html
    public class HelpBox : VisualElement
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.HelpBox-ctor.html
        public HelpBox(string text, HelpBoxMessageType messageType) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.HelpBoxMessageType.html (values UNCONFIRMED; names from the page)
    public enum HelpBoxMessageType
    {
        None = 0,
        Info = 1,
        Warning = 2,
        Error = 3,
    }
}
