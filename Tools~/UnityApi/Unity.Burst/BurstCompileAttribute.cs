using System;

namespace Unity.Burst
{
    // https://docs.unity3d.com/Packages/com.unity.burst@1.8/api/Unity.Burst.BurstCompileAttribute.html
    // (source: needle-mirror/com.unity.burst, Runtime/BurstCompileAttribute.cs)
    [AttributeUsage(AttributeTargets.Class | AttributeTargets.Struct | AttributeTargets.Method | AttributeTargets.Assembly)]
    public class BurstCompileAttribute : Attribute
    {
        // https://docs.unity3d.com/Packages/com.unity.burst@1.8/api/Unity.Burst.BurstCompileAttribute.-ctor.html
        public BurstCompileAttribute() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.burst@1.8/api/Unity.Burst.BurstCompileAttribute.CompileSynchronously.html
        // ("true will force this code to be compiled synchronously on first invocation"; default false)
        public bool CompileSynchronously { get => throw null; set => throw null; }
    }
}
