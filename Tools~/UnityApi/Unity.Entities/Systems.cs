using System;

// Source: needle-mirror/com.unity.entities 1.4.2, Unity.Entities/ComponentSystemBase.cs, SystemBase.cs,
// ComponentSystemGroup.cs, DefaultWorld.cs and ScriptBehaviourUpdateOrder.cs.
namespace Unity.Entities
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.html
    public abstract partial class ComponentSystemBase
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.Enabled.html
        public bool Enabled { get => throw null; set => throw null; }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.EntityManager.html
        public EntityManager EntityManager => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.World.html
        // (source: ComponentSystemBase.cs, 1.4.2: public World World => m_StatePtr != null ? (World)m_StatePtr->m_World.Target : null;)
        public World World => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.RequireForUpdate.html
        // (source: ComponentSystemBase.cs, 1.4.2: public void RequireForUpdate<T>())
        public void RequireForUpdate<T>() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.Update.html
        // (source: ComponentSystemBase.cs, 1.4.2: public abstract void Update(); SystemBase seals its override)
        public void Update() => throw null;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.OnCreate.html
        protected virtual void OnCreate() { }
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemBase.OnDestroy.html
        protected virtual void OnDestroy() { }
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemBase.html
    public abstract partial class SystemBase : ComponentSystemBase
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemBase.OnUpdate.html
        protected abstract void OnUpdate();
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.SystemBase.CompleteDependency.html
        // (source: SystemBase.cs, 1.4.2: protected void CompleteDependency())
        protected void CompleteDependency() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemGroup.html
    public abstract partial class ComponentSystemGroup : SystemBase
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.ComponentSystemGroup.OnUpdate.html
        protected override void OnUpdate() => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.FixedStepSimulationSystemGroup.html
    public partial class FixedStepSimulationSystemGroup : ComponentSystemGroup
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.PresentationSystemGroup.html
    public partial class PresentationSystemGroup : ComponentSystemGroup
    {
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateInGroupAttribute.html
    [AttributeUsage(AttributeTargets.Class | AttributeTargets.Struct)]
    public class UpdateInGroupAttribute : Attribute
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateInGroupAttribute.OrderFirst.html
        public bool OrderFirst = false;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateInGroupAttribute.OrderLast.html
        public bool OrderLast = false;
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateInGroupAttribute.-ctor.html
        public UpdateInGroupAttribute(Type groupType) => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateBeforeAttribute.html
    [AttributeUsage(AttributeTargets.Class | AttributeTargets.Struct, AllowMultiple = true)]
    public class UpdateBeforeAttribute : Attribute
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateBeforeAttribute.-ctor.html
        public UpdateBeforeAttribute(Type systemType) => throw null;
    }

    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateAfterAttribute.html
    [AttributeUsage(AttributeTargets.Class | AttributeTargets.Struct, AllowMultiple = true)]
    public class UpdateAfterAttribute : Attribute
    {
        // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Entities.UpdateAfterAttribute.-ctor.html
        public UpdateAfterAttribute(Type systemType) => throw null;
    }
}
