using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    public class ContactProjectionEdgeTests
    {
        /// <summary>
        /// A particle that moves past a box edge: the closest point's normal (+y of the box) and the face its motion
        /// crossed (−z) are at right angles, so the sign of their dot product is round-off (−3e-8 here, which sent the
        /// particle out through the crossed face, 1.3 cm away, while the GPU port, rounding the other way, kept it on +y).
        /// At right angles the closest point wins.
        /// </summary>
        [Test]
        public void Project_KeepsTheClosestPointNormalWhenItIsAtRightAnglesToTheSweptFace()
        {
            var box = ColliderShape.Box(new float3(0.2f, 0.02f, 0.08f), quaternion.AxisAngle(math.normalize(new float3(0.3f, 0.5f, 0.2f)), 0.6002f),
                new float3(0.05f, 0.03f, 0.04f));
            var previous = new[] { new float3(0.12931465f, 0.034555517f, 0.05790282f) };
            var x = new[] { new float3(0.13663423f, 0.04550554f, 0.079069644f) };
            const float radius = 0.01f;
            Assume.That(ParticleCollision.Penetration(box, x[0], radius, out float3 closest, out _, out bool deep) && !deep, "touching, centre outside");
            Assume.That(ParticleCollision.Sweep(box, previous[0], x[0], radius, out _, out float3 face), "the motion crossed a face");
            float cosine = math.dot(closest, face);
            Assume.That(cosine < 0f && cosine > -ContactProjection.OppositeNormals, Is.True, "at right angles, with a negative round-off");
            var v = new[] { float3.zero };
            var normals = new float3[1];
            var settings = new ContactProjection.Settings { Radius = radius, BounceThreshold = float.PositiveInfinity, MaxDepenetration = float.PositiveInfinity };
            ContactProjection.Project(previous, x, v, normals, new[] { box }, settings, 1f / 60f);
            Assert.That(math.dot(normals[0], closest), Is.GreaterThan(1f - 1e-6f));
        }
    }
}
