using System;

// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/IComponentData.cs and ForeachQueryEnumerable.cs.
namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IQueryTypeParameter.html
    public interface IQueryTypeParameter
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IComponentData.html
    public interface IComponentData : IQueryTypeParameter
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IBufferElementData.html
    public interface IBufferElementData
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ICleanupComponentData.html
    public interface ICleanupComponentData : IComponentData
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.IEnableableComponent.html
    public interface IEnableableComponent
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.InternalBufferCapacityAttribute.html
    [AttributeUsage(AttributeTargets.Struct)]
    public class InternalBufferCapacityAttribute : Attribute
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.InternalBufferCapacityAttribute.-ctor.html
        public InternalBufferCapacityAttribute(int capacity) => throw null;
    }
}
