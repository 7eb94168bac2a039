using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Plasticity (Müller et al. 2005, §4.5): a body squashed beyond its yield keeps part of the
    /// deformation; the plastic strain never exceeds its bound and keeps the volume. Bound: Sₚ is
    /// clamped to ‖Sₚ − I‖_F ≤ c and then divided by s = ∛det Sₚ; the singular values of Sₚ lie in
    /// [1 − c, 1 + c], so s does too, and ‖Sₚ/s − I‖_F ≤ ‖Sₚ − I‖_F/s + |1/s − 1|·√3 ≤ c(1 + √3)/(1 − c).
    /// det Sₚ = 1 to float32 round-off of a 3×3 determinant and a cube root (≤ 1e-5).
    /// </summary>
    public class ShapeMatchingPlasticityTests
    {
        static ShapeMatchingInstance SquashedClay(PlasticityParameters plasticity)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 3, 1f);
            var p = ShapeMatchingParameters.Default;
            p.Body.Acceleration = float3.zero;
            p.Plasticity = plasticity;
            p.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, p, float3.zero, quaternion.identity);
            float s = math.sqrt(2f);
            for (int i = 0; i < body.Positions.Length; i++)
                body.Positions[i] *= new float3(s, 0.5f, s);
            return body;
        }

        [Test]
        public void Plasticity_KeepsPartOfTheDeformationAndStaysBounded()
        {
            var plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 20f, MaxDeformation = 0.3f };
            ShapeMatchingInstance clay = SquashedClay(plasticity);
            float bound = plasticity.MaxDeformation * (1f + math.sqrt(3f)) / (1f - plasticity.MaxDeformation);
            int flows = 0;
            for (int step = 0; step < 240; step++)
            {
                flows += clay.Step(1f / 60f).PlasticUpdates;
                foreach (ClusterState c in clay.Clusters)
                {
                    Assert.That(Plasticity.FrobeniusNorm(c.PlasticDeformation - float3x3.identity), Is.LessThanOrEqualTo(bound));
                    Assert.That(math.determinant(c.PlasticDeformation), Is.EqualTo(1f).Within(1e-5f));
                }
            }
            Assert.That(flows, Is.GreaterThan(0));
            var view = clay.Model.AsModel();
            double size = BodyMeasures.RestSize(view);
            // The elastic twin recovers to < 1% (ShapeMatchingRecoveryTests); the clay keeps clearly more.
            Assert.That(BodyMeasures.ShapeError(clay.Positions, view) / size, Is.GreaterThan(0.03));
            Assert.That(BodyMeasures.VolumeRatio(clay.Positions, view), Is.EqualTo(1.0).Within(0.1), "plastic flow keeps the volume");
        }

        [Test]
        public void Plasticity_BelowYieldIsElastic()
        {
            var plasticity = new PlasticityParameters { Yield = 10f, Creep = 20f, MaxDeformation = 0.3f };
            ShapeMatchingInstance body = SquashedClay(plasticity);
            int flows = 0;
            for (int step = 0; step < 180; step++)
                flows += body.Step(1f / 60f).PlasticUpdates;
            Assert.That(flows, Is.EqualTo(0));
            var view = body.Model.AsModel();
            Assert.That(BodyMeasures.ShapeError(body.Positions, view) / BodyMeasures.RestSize(view), Is.LessThanOrEqualTo(0.01));
        }

        [Test]
        public void Plasticity_WorksInQuadraticModeWithPerInstanceInverses()
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, 5, 1f, buildQuadratic: true);
            var p = ShapeMatchingParameters.Default;
            p.Mode = ShapeMatchingMode.Quadratic;
            p.Body.Acceleration = float3.zero;
            p.Plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 20f, MaxDeformation = 0.3f };
            var body = new ShapeMatchingInstance(model, p, float3.zero, quaternion.identity, perInstanceQuadratic: true);
            for (int i = 0; i < body.Positions.Length; i++)
                body.Positions[i] *= new float3(1.3f, 0.6f, 1.3f);
            int flows = 0, fallbacks = 0;
            for (int step = 0; step < 120; step++)
            {
                ShapeMatchingStepReport r = body.Step(1f / 60f);
                flows += r.PlasticUpdates;
                fallbacks += r.Fallbacks;
                Assert.That(r.Reset, Is.False);
            }
            Assert.That(flows, Is.GreaterThan(0));
            Assert.That(fallbacks, Is.EqualTo(0), "the per-instance inverse keeps the quadratic mode in use");
            Assert.That(body.QuadraticInverse, Is.Not.EqualTo(model.QuadraticInverse), "the rest inverse was rebuilt");
        }
    }
}
