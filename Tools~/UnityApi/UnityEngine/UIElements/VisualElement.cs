namespace UnityEngine.UIElements
{
    // https://docs.unity3d.com/ScriptReference/UIElements.VisualElement.html
    public class VisualElement
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.VisualElement-ctor.html
        public VisualElement() => throw null;

        // https://docs.unity3d.com/ScriptReference/UIElements.VisualElement-style.html
        public IStyle style => throw null;

        // https://docs.unity3d.com/ScriptReference/UIElements.VisualElement-tooltip.html
        public string tooltip { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/UIElements.VisualElement.Add.html
        public void Add(VisualElement child) => throw null;

        // https://docs.unity3d.com/ScriptReference/UIElements.VisualElement.Clear.html
        public void Clear() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.BindableElement.html
    public class BindableElement : VisualElement
    {
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.TextElement.html
    public class TextElement : BindableElement
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.TextElement-text.html
        public virtual string text { get => throw null; set => throw null; }
    }
}
