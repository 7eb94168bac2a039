using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Bodies of quadratic elements through the whole step: contacts, the guard, sleep, the integrator fallback (bending: <see cref="FemCantileverTests"/>).</summary>
    public class FemQuadraticBodyTests
    {
        static readonly ElasticMaterial s_Jelly = new ElasticMaterial(2e5f, 0.4f, 1000f, 0.5f);

        static FemParameters Implicit()
        {
            FemParameters p = FemParameters.Default;
            p.CgIterations = 2000;
            p.CgTolerance = 1e-5f;
            return p;
        }

        /// <summary>A quadratic cube dropped on the floor comes to rest on it: every node, edge nodes included, stays above the floor less the contact slop.</summary>
        [Test]
        public void DroppedCube_RestsOnTheFloor_WithEveryNode()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(2, 2, 2, new float3(0.2f)), s_Jelly, null, FemElementOrder.Quadratic);
            FemParameters p = Implicit();
            p.Body.ParticleRadius = 0f;
            var body = new FemTestBody(data, p, new float3(0f, 0.3f, 0f));
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            for (int step = 0; step < 120; step++)
                body.Step(1f / 60f, floor);
            Assert.That(body.AllFinite());
            float lowest = float.MaxValue;
            foreach (float3 x in body.Positions)
                lowest = math.min(lowest, x.y + body.Status.Origin.y);
            // Contacts are resolved at the end of each substep; the implicit solve may leave a node 1 mm under (the sag of one substep's gravity, g h² ≈ 0.7 mm).
            Assert.That(lowest, Is.GreaterThan(-1e-3f));
            Assert.That(lowest, Is.LessThan(0.01f), "it fell to the floor");
        }

        /// <summary>A NaN on an edge node is caught by the guard: the body is reset to its rest shape, finite.</summary>
        [Test]
        public void NaNOnAnEdgeNode_ResetsTheBody()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(1, 1, 1, new float3(0.2f)), s_Jelly, null, FemElementOrder.Quadratic);
            var body = new FemTestBody(data, Implicit());
            int edgeNode = data.RestPositions.Length - 1;
            Assert.That(edgeNode, Is.GreaterThanOrEqualTo(8), "an edge node (after the 8 corners)");
            body.Velocities[edgeNode] = new float3(float.NaN, 0f, 0f);
            FemStepReport report = body.Step(1f / 60f);
            Assert.That(report.Step.Reset);
            Assert.That(body.AllFinite());
        }

        /// <summary>A free quadratic body at rest on the floor falls asleep; XPBD, whose constraints are per linear tetrahedron, runs implicit Euler instead and says so.</summary>
        [Test]
        public void RestingBody_Sleeps_AndXpbdFallsBackToImplicit()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(1, 1, 1, new float3(0.2f)), s_Jelly, null, FemElementOrder.Quadratic);
            FemParameters p = Implicit();
            p.Integrator = FemIntegrator.Xpbd;
            p.Model = FemMaterialModel.NeoHookean;
            var body = new FemTestBody(data, p, new float3(0f, 0.1f + p.Body.ParticleRadius, 0f));
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            bool slept = false;
            for (int step = 0; step < 300 && !slept; step++)
            {
                FemStepReport report = body.Step(1f / 60f, floor);
                Assert.That(report.IntegratorFallback);
                Assert.That(report.Integrator, Is.EqualTo(FemIntegrator.ImplicitEuler));
                slept = report.Step.FellAsleep;
            }
            Assert.That(slept);
        }

        /// <summary>The explicit stability limit counts the edge nodes: quadratic elements are stiffer per node, so ω_max rises.</summary>
        [Test]
        public void MaxFrequency_IsHigher_ForQuadraticElements()
        {
            TetrahedralMesh mesh = FemTestBodies.Box(2, 2, 2, new float3(0.2f));
            float linear = FemStability.MaxFrequency(FemTestBodies.Bake(mesh, s_Jelly).AsModel());
            float quadratic = FemStability.MaxFrequency(FemTestBodies.Bake(mesh, s_Jelly, null, FemElementOrder.Quadratic).AsModel());
            Assert.That(float.IsFinite(quadratic));
            Assert.That(quadratic, Is.GreaterThan(1.5f * linear));
        }
    }
}
