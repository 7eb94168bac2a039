using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using Unity.Transforms;

namespace SoftBodyDynamics
{
    /// <summary>
    /// Conversions between a soft body's entity transform and its simulated placement. The entity's
    /// <see cref="LocalTransform"/> is the pose of the render mesh's origin (pivot): with rest centre of
    /// mass x⁰_cm in mesh space, centre of mass c and rotation R, the pivot is at c − R·x⁰_cm. Soft bodies
    /// are root entities with unit scale (bake any scale into the mesh).
    /// </summary>
    public static class SoftBodyPlacement
    {
        /// <summary>World centre of mass of the rest shape placed at <paramref name="transform"/> (m).</summary>
        /// <param name="transform">Pose of the mesh origin.</param>
        /// <param name="restCenter">Rest centre of mass in mesh space (m), <see cref="ClusterRestData.RestCenter"/> of the body.</param>
        public static float3 CenterOfMass(in LocalTransform transform, float3 restCenter) =>
            transform.Position + math.rotate(math.normalizesafe(transform.Rotation), restCenter);

        /// <summary>Pose of the mesh origin for a body at <paramref name="status"/> (unit scale).</summary>
        /// <param name="status">Centre of mass and best-fit rotation of the body.</param>
        /// <param name="restCenter">Rest centre of mass in mesh space (m).</param>
        public static LocalTransform ToLocalTransform(in ParticleBodyStatus status, float3 restCenter) =>
            LocalTransform.FromPositionRotation(status.Center - math.rotate(status.Rotation, restCenter), status.Rotation);
    }
}
