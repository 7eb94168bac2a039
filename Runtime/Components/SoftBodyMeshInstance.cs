using Unity.Entities;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics
{
    /// <summary>
    /// The per-body copy of the render mesh and its Entities Graphics registration (runtime only, added
    /// by <see cref="SoftBodyRenderMeshSystem"/>). A cleanup component: it outlives the entity until the
    /// system has unregistered and destroyed the mesh, and it is not copied when an entity is instantiated.
    /// </summary>
    public struct SoftBodyMeshInstance : ICleanupComponentData
    {
        /// <summary>The body's own mesh; invalid when the copy could not be made (an error was logged).</summary>
        public UnityObjectRef<Mesh> Mesh;
        /// <summary>The mesh's id in Entities Graphics (<c>EntitiesGraphicsSystem.RegisterMesh</c>).</summary>
        public BatchMeshID MeshId;
        /// <summary><see cref="SoftBodyDynamics.Solvers.ParticleBodyStatus.StepCount"/> the vertices were last computed for.</summary>
        public uint DeformedStep;
        /// <summary>True once the vertices have been computed at least once.</summary>
        public bool Deformed;
        /// <summary>New vertices are waiting in <see cref="SoftBodyMeshVertex"/> to be uploaded to <see cref="Mesh"/>.</summary>
        public bool PendingUpload;
    }
}
