using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Where a body's components go: a baker (<c>SoftBodyBaker</c>) or, for bodies made from code and for tests, an
    /// <see cref="EntityManager"/> (<see cref="EntityManagerSoftBodyWriter"/>). The component set of a mass-spring or FEM
    /// body is written through it by one function per method (<see cref="SoftBodyArchetype.WriteMassSpring"/>,
    /// <see cref="SoftBodyArchetype.WriteFem"/>) for both.
    /// </summary>
    public interface ISoftBodyEntityWriter
    {
        /// <summary>Adds <paramref name="component"/> to the body's entity.</summary>
        void AddComponent<T>(in T component) where T : unmanaged, IComponentData;

        /// <summary>Adds an enableable component in the given state.</summary>
        void AddComponent<T>(in T component, bool enabled) where T : unmanaged, IComponentData, IEnableableComponent;

        /// <summary>Adds an empty dynamic buffer.</summary>
        void AddBuffer<T>() where T : unmanaged, IBufferElementData;

        /// <summary>Hands <paramref name="blob"/> to the writer's owner (the baker's blob store, or the caller's list to dispose).</summary>
        void AddBlob<T>(ref BlobAssetReference<T> blob) where T : unmanaged;
    }
}
