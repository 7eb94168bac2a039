namespace UnityEngine.UIElements
{
    // https://docs.unity3d.com/ScriptReference/UIElements.IStyle.html
    public interface IStyle
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.IStyle-display.html
        StyleEnum<DisplayStyle> display { get; set; }
        // https://docs.unity3d.com/ScriptReference/UIElements.IStyle-flexDirection.html
        StyleEnum<FlexDirection> flexDirection { get; set; }
        // https://docs.unity3d.com/ScriptReference/UIElements.IStyle-flexGrow.html
        StyleFloat flexGrow { get; set; }
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.StyleEnum_1.html (generic constraint UNCONFIRMED)
    public struct StyleEnum<T> where T : struct, System.IConvertible
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.StyleEnum_1-ctor.html
        public StyleEnum(T v) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.StyleFloat.html
    public struct StyleFloat
    {
        // https://docs.unity3d.com/ScriptReference/UIElements.StyleFloat-ctor.html
        public StyleFloat(float v) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.DisplayStyle.html (values UNCONFIRMED; names from the page)
    public enum DisplayStyle
    {
        Flex = 0,
        None = 1,
    }

    // https://docs.unity3d.com/ScriptReference/UIElements.FlexDirection.html (values UNCONFIRMED; names from the page)
    public enum FlexDirection
    {
        Column = 0,
        ColumnReverse = 1,
        Row = 2,
        RowReverse = 3,
    }
}
