using System;
using System.Collections.Generic;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Writes a body's components straight onto an entity with an <see cref="EntityManager"/> (main thread,
    /// structural changes). The blobs handed to it (<see cref="AddBlob"/>) stay owned by this writer: <see cref="Dispose"/>
    /// releases them, after the world that uses them.
    /// </summary>
    public sealed class EntityManagerSoftBodyWriter : ISoftBodyEntityWriter, IDisposable
    {
        readonly EntityManager m_Manager;
        readonly Entity m_Entity;
        readonly List<IDisposable> m_Blobs = new List<IDisposable>();

        public EntityManagerSoftBodyWriter(EntityManager manager, Entity entity)
        {
            m_Manager = manager;
            m_Entity = entity;
        }

        public void AddComponent<T>(in T component) where T : unmanaged, IComponentData =>
            m_Manager.AddComponentData(m_Entity, component);

        public void AddComponent<T>(in T component, bool enabled) where T : unmanaged, IComponentData, IEnableableComponent
        {
            m_Manager.AddComponentData(m_Entity, component);
            m_Manager.SetComponentEnabled<T>(m_Entity, enabled);
        }

        public void AddBuffer<T>() where T : unmanaged, IBufferElementData => m_Manager.AddBuffer<T>(m_Entity);

        public void AddBlob<T>(ref BlobAssetReference<T> blob) where T : unmanaged => m_Blobs.Add(blob);

        /// <summary>Disposes every blob handed to this writer.</summary>
        public void Dispose()
        {
            foreach (IDisposable blob in m_Blobs)
                blob.Dispose();
            m_Blobs.Clear();
        }
    }
}
