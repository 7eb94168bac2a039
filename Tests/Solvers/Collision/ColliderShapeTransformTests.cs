using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// <see cref="ColliderShape.Transformed"/>: a collider given in a body's space and moved into the world by a rigid
    /// transform and a uniform scale is the same solid, so every world point penetrates it exactly as its preimage
    /// penetrates the local collider, scaled.
    /// </summary>
    public class ColliderShapeTransformTests
    {
        static readonly float3 s_Translation = new float3(1.5f, -0.25f, 2f);
        static readonly quaternion s_Rotation = math.normalize(math.mul(quaternion.AxisAngle(new float3(1f, 0f, 0f), 0.3f), quaternion.AxisAngle(math.normalize(new float3(0.2f, 1f, -0.4f)), -1.1f)));

        static ColliderShape Local(ColliderShapeType type)
        {
            switch (type)
            {
                case ColliderShapeType.Plane: return ColliderShape.Plane(new float3(0.1f, 0.2f, -0.1f), new float3(0.2f, 1f, -0.3f));
                case ColliderShapeType.Sphere: return ColliderShape.Sphere(new float3(0.2f, -0.1f, 0.3f), 0.35f);
                case ColliderShapeType.Box: return ColliderShape.Box(new float3(-0.1f, 0.2f, 0.05f), quaternion.AxisAngle(math.normalize(new float3(0.3f, 0.5f, -1f)), 0.45f), new float3(0.3f, 0.15f, 0.4f));
                default: return ColliderShape.Capsule(new float3(-0.2f, 0f, 0.1f), new float3(0.3f, 0.25f, -0.1f), 0.25f);
            }
        }

        [Test]
        public void WorldPoints_PenetrateTheTransformedColliderAsTheirPreimagesDoTheLocalOne(
            [Values(ColliderShapeType.Plane, ColliderShapeType.Sphere, ColliderShapeType.Box, ColliderShapeType.Capsule)] ColliderShapeType type,
            [Values(1f, 0.5f, 2.5f)] float scale)
        {
            ColliderShape local = Local(type);
            ColliderShape world = local.Transformed(s_Translation, s_Rotation, scale);
            var random = new Random(7);
            int inside = 0;
            for (int k = 0; k < 500; k++)
            {
                float3 p = random.NextFloat3(new float3(-0.7f), new float3(0.7f));
                float3 x = s_Translation + math.mul(s_Rotation, scale * p);
                bool localHit = ParticleCollision.Penetration(local, p, 0f, out float3 localNormal, out float localDepth);
                bool worldHit = ParticleCollision.Penetration(world, x, 0f, out float3 worldNormal, out float worldDepth);
                Assert.That(worldHit, Is.EqualTo(localHit), $"point {k}");
                if (!localHit)
                    continue;
                inside++;
                // float32: positions of order 3 m carry ~3e-7 m of round-off per operation, a few operations deep.
                Assert.That(worldDepth, Is.EqualTo(scale * localDepth).Within(1e-5f), $"depth of point {k}");
                if (localDepth > 1e-3f)
                    Assert.That(math.distance(worldNormal, math.mul(s_Rotation, localNormal)), Is.LessThan(1e-4f), $"normal of point {k}");
            }
            Assert.That(inside, Is.GreaterThan(20), "the sample reaches inside the collider");
        }

        [Test]
        public void Identity_LeavesTheColliderAsItWas()
        {
            foreach (ColliderShapeType type in new[] { ColliderShapeType.Plane, ColliderShapeType.Sphere, ColliderShapeType.Box, ColliderShapeType.Capsule })
            {
                ColliderShape local = Local(type), same = local.Transformed(float3.zero, quaternion.identity, 1f);
                Assert.That(same.Center, Is.EqualTo(local.Center));
                Assert.That(same.Axis, Is.EqualTo(local.Axis));
                Assert.That(same.Radius, Is.EqualTo(local.Radius));
                Assert.That(same.HalfExtents, Is.EqualTo(local.HalfExtents));
            }
        }
    }
}
