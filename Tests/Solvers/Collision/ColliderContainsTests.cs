using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    public class ColliderContainsTests
    {
        /// <summary>
        /// <see cref="ParticleCollision.Contains"/> against each shape's own geometry: a point 1 mm inside its surface is in,
        /// 1 mm outside is out (far above float32 round-off at these sizes), along the surface normal at a few places.
        /// </summary>
        [Test]
        public void Contains_IsTrueJustInsideEachShapeAndFalseJustOutside()
        {
            const float e = 1e-3f;
            quaternion q = quaternion.AxisAngle(math.normalize(new float3(0.3f, 0.5f, 0.2f)), 0.6f);
            var box = ColliderShape.Box(new float3(0.2f, 0.1f, -0.1f), q, new float3(0.05f, 0.03f, 0.04f));
            // A face centre, an edge's midpoint and a corner, with their outward directions in the box's frame.
            var local = new[] { new float3(0.05f, 0f, 0f), new float3(0f, 0.03f, -0.04f), new float3(-0.05f, 0.03f, 0.04f) };
            foreach (float3 l in local)
            {
                float3 n = math.rotate(q, math.normalize(math.sign(l)));
                float3 x = box.Center + math.rotate(q, l);
                Assert.IsTrue(ParticleCollision.Contains(box, x - e * n), $"box, inside at {l}");
                Assert.IsFalse(ParticleCollision.Contains(box, x + e * n), $"box, outside at {l}");
            }
            var sphere = ColliderShape.Sphere(new float3(0.1f, 0.2f, 0.3f), 0.06f);
            float3 u = math.normalize(new float3(1f, -2f, 0.5f));
            Assert.IsTrue(ParticleCollision.Contains(sphere, sphere.Center + (0.06f - e) * u));
            Assert.IsFalse(ParticleCollision.Contains(sphere, sphere.Center + (0.06f + e) * u));
            var capsule = ColliderShape.Capsule(new float3(0f, 0f, 0f), new float3(0.1f, 0.1f, 0f), 0.02f);
            float3 side = math.normalize(new float3(-1f, 1f, 0f));
            Assert.IsTrue(ParticleCollision.Contains(capsule, new float3(0.05f, 0.05f, 0f) + (0.02f - e) * side), "capsule side");
            Assert.IsFalse(ParticleCollision.Contains(capsule, new float3(0.05f, 0.05f, 0f) + (0.02f + e) * side), "capsule side");
            float3 beyond = math.normalize(new float3(1f, 1f, 0f));
            Assert.IsTrue(ParticleCollision.Contains(capsule, new float3(0.1f, 0.1f, 0f) + (0.02f - e) * beyond), "capsule cap");
            Assert.IsFalse(ParticleCollision.Contains(capsule, new float3(0.1f, 0.1f, 0f) + (0.02f + e) * beyond), "capsule cap");
            var plane = ColliderShape.Plane(new float3(0f, 0.1f, 0f), new float3(0f, 1f, 0f));
            Assert.IsTrue(ParticleCollision.Contains(plane, new float3(3f, 0.1f - e, -5f)), "behind the plane");
            Assert.IsFalse(ParticleCollision.Contains(plane, new float3(3f, 0.1f + e, -5f)), "in front of the plane");
        }
    }
}
