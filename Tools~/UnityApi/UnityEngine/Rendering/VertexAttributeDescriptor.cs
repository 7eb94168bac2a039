namespace UnityEngine.Rendering
{
    // Checked: UnityCsReference 6000.0.22f1 Runtime/Export/Graphics/GraphicsEnums.cs.

    // https://docs.unity3d.com/ScriptReference/Rendering.VertexAttributeDescriptor.html
    public struct VertexAttributeDescriptor
    {
        // https://docs.unity3d.com/ScriptReference/Rendering.VertexAttributeDescriptor-attribute.html
        public VertexAttribute attribute { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Rendering.VertexAttributeDescriptor-format.html
        public VertexAttributeFormat format { get => throw null; set => throw null; }
        // https://docs.unity3d.com/ScriptReference/Rendering.VertexAttributeDescriptor-dimension.html
        public int dimension { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Rendering.VertexAttributeDescriptor-ctor.html
        public VertexAttributeDescriptor(VertexAttribute attribute = VertexAttribute.Position,
            VertexAttributeFormat format = VertexAttributeFormat.Float32, int dimension = 3, int stream = 0) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/Rendering.VertexAttribute.html
    public enum VertexAttribute
    {
        Position = 0,
        Normal,
        Tangent,
        Color,
        TexCoord0,
        TexCoord1,
        TexCoord2,
        TexCoord3,
        TexCoord4,
        TexCoord5,
        TexCoord6,
        TexCoord7,
        BlendWeight,
        BlendIndices,
    }

    // https://docs.unity3d.com/ScriptReference/Rendering.VertexAttributeFormat.html
    public enum VertexAttributeFormat
    {
        Float32 = 0,
        Float16 = 1,
        UNorm8 = 2,
        SNorm8 = 3,
        UNorm16 = 4,
        SNorm16 = 5,
        UInt8 = 6,
        SInt8 = 7,
        UInt16 = 8,
        SInt16 = 9,
        UInt32 = 10,
        SInt32 = 11,
    }
}
