namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Material.html
    public class Material : Object
    {
        // https://docs.unity3d.com/ScriptReference/Material-ctor.html
        public Material(Material source) => throw null;

        // https://docs.unity3d.com/ScriptReference/Material-color.html
        public Color color { get => throw null; set => throw null; }
    }
}
