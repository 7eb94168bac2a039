using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Same input, same bits: the step is sequential within a body and reads nothing but its arguments,
    /// so two bodies fed the same input must agree exactly (the ECS job runs one body per work item,
    /// which makes the result independent of the worker count).
    /// </summary>
    public class ShapeMatchingDeterminismTests
    {
        [Test]
        public void SameInput_GivesSameBits([Values] ShapeMatchingMode mode)
        {
            ShapeMatchingInstance Make()
            {
                var model = LatticeBody.Create(new int3(5, 4, 3), 0.1f, 3, 1f, mode == ShapeMatchingMode.Quadratic);
                var p = ShapeMatchingParameters.Default;
                p.Mode = mode;
                p.Plasticity = new PlasticityParameters { Yield = 0.1f, Creep = 5f, MaxDeformation = 0.3f };
                return new ShapeMatchingInstance(model, p, new float3(0f, 2f, 0f), quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.7f),
                    new float3(1f, 0f, 0f), perInstanceQuadratic: true);
            }
            var colliders = new[]
            {
                ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)),
                ColliderShape.Box(new float3(0.5f, 0.3f, 0f), quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.3f), new float3(0.2f, 0.3f, 0.5f)),
                ColliderShape.Capsule(new float3(1f, 0.1f, -1f), new float3(1f, 0.1f, 1f), 0.1f),
            };
            ShapeMatchingInstance a = Make(), b = Make();
            for (int step = 0; step < 300; step++)
            {
                a.Step(1f / 60f, colliders);
                b.Step(1f / 60f, colliders);
            }
            for (int i = 0; i < a.Positions.Length; i++)
            {
                Assert.That(math.asuint(a.Positions[i].x) == math.asuint(b.Positions[i].x)
                            && math.asuint(a.Positions[i].y) == math.asuint(b.Positions[i].y)
                            && math.asuint(a.Positions[i].z) == math.asuint(b.Positions[i].z), Is.True, $"particle {i}");
                Assert.That(a.Velocities[i], Is.EqualTo(b.Velocities[i]));
            }
            Assert.That(a.Status.Center, Is.EqualTo(b.Status.Center));
            Assert.That(a.Status.Rotation, Is.EqualTo(b.Status.Rotation));
        }
    }
}
