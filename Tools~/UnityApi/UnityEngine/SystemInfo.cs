namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/SystemInfo.html
    public sealed class SystemInfo
    {
        // https://docs.unity3d.com/ScriptReference/SystemInfo-supportsComputeShaders.html
        public static bool supportsComputeShaders => throw null;

        // https://docs.unity3d.com/ScriptReference/SystemInfo-supportsAsyncGPUReadback.html
        public static bool supportsAsyncGPUReadback => throw null;

        // https://docs.unity3d.com/ScriptReference/SystemInfo-maxComputeBufferInputsCompute.html
        public static int maxComputeBufferInputsCompute => throw null;

        // https://docs.unity3d.com/ScriptReference/SystemInfo-maxComputeWorkGroupSize.html
        public static int maxComputeWorkGroupSize => throw null;

        // https://docs.unity3d.com/ScriptReference/SystemInfo-usesReversedZBuffer.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/SystemInfo/SystemInfo.bindings.cs)
        public static bool usesReversedZBuffer => throw null;

        // https://docs.unity3d.com/ScriptReference/SystemInfo-graphicsUVStartsAtTop.html (same source)
        public static bool graphicsUVStartsAtTop => throw null;
    }
}
