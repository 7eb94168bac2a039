using System;
using Unity.Jobs;

// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/IJobEntity.cs. The scheduling extensions are
// replaced by the Entities source generators at compile time in Unity.
namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IJobEntity.html
    public interface IJobEntity
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IJobEntityExtensions.html
    public static class IJobEntityExtensions
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IJobEntityExtensions.ScheduleParallel.html
        public static void ScheduleParallel<T>(this T jobData) where T : unmanaged, IJobEntity => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IJobEntityExtensions.ScheduleParallel.html
        public static JobHandle ScheduleParallel<T>(this T jobData, JobHandle dependsOn) where T : unmanaged, IJobEntity => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WithNoneAttribute.html
    [AttributeUsage(AttributeTargets.Struct, AllowMultiple = true)]
    public sealed class WithNoneAttribute : Attribute
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.WithNoneAttribute.-ctor.html
        public WithNoneAttribute(params Type[] types) => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EnabledRefRW-1.html
    // (source: Unity.Entities/Iterators/EnabledRefRW.cs)
    public readonly struct EnabledRefRW<T> : IQueryTypeParameter where T : unmanaged, IEnableableComponent
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.EnabledRefRW-1.ValueRW.html
        public bool ValueRW { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BufferLookup-1.html
    // (source: Unity.Entities/Iterators/BufferLookup.cs)
    public struct BufferLookup<T> where T : unmanaged, IBufferElementData
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.BufferLookup-1.TryGetBuffer.html
        public bool TryGetBuffer(Entity entity, out DynamicBuffer<T> bufferData) => throw null;
    }
}
