using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Where plastic flow may and may not happen, and what survives the NaN guard. Sₚ is compared bit for bit:
    /// each of these cases either must not touch it at all or must leave it exactly as it was.
    /// </summary>
    public class ShapeMatchingPlasticStateTests
    {
        static readonly PlasticityParameters s_Clay = new PlasticityParameters { Yield = 0.05f, Creep = 20f, MaxDeformation = 0.3f };

        static ShapeMatchingInstance Body(ShapeMatchingMode mode, int clusterSize, bool perInstanceQuadratic, float3 position)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, clusterSize, 1f, mode == ShapeMatchingMode.Quadratic);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Body.Acceleration = float3.zero;
            p.Body.SleepSpeed = 0f;
            p.Plasticity = s_Clay;
            return new ShapeMatchingInstance(model, p, position, quaternion.identity, perInstanceQuadratic: perInstanceQuadratic);
        }

        /// <summary>Squash to <paramref name="squash"/> of the height with the volume kept (x and z by 1/√squash), about the centre.</summary>
        static void Squash(ShapeMatchingInstance body, float squash)
        {
            float3 c = ShapeMatching.CenterOfMass(body.Positions, body.Model.Masses);
            float s = 1f / math.sqrt(squash);
            for (int i = 0; i < body.Positions.Length; i++)
                body.Positions[i] = c + (body.Positions[i] - c) * new float3(s, squash, s);
        }

        static bool SameBits(in float3x3 a, in float3x3 b) =>
            SameBits(a.c0, b.c0) && SameBits(a.c1, b.c1) && SameBits(a.c2, b.c2);

        static bool SameBits(float3 a, float3 b) =>
            math.asuint(a.x) == math.asuint(b.x) && math.asuint(a.y) == math.asuint(b.y) && math.asuint(a.z) == math.asuint(b.z);

        static bool IsIdentity(in float3x3 m) => SameBits(m, float3x3.identity);

        /// <summary>
        /// The guard undoes a broken state, not the body's history: after the clay flowed, a NaN written into one
        /// particle resets the positions to the rest shape at the last good placement, and every cluster keeps its
        /// plastic rest shape Sₚ (and its A_qq⁻¹) exactly; the next steps go on from that rest shape.
        /// </summary>
        [Test]
        public void NaNGuard_KeepsThePlasticRestShape([Values(ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic)] ShapeMatchingMode mode)
        {
            ShapeMatchingInstance body = Body(mode, 3, perInstanceQuadratic: true, new float3(0f, 1f, 0f));
            Squash(body, 0.5f);
            int flows = 0;
            for (int step = 0; step < 60; step++)
                flows += body.Step(1f / 60f).PlasticUpdates;
            Assert.That(flows, Is.GreaterThan(0));
            var before = (ClusterState[])body.Clusters.Clone();
            var quadraticBefore = (float3x3[])body.QuadraticInverse.Clone();
            int flowed = 0;
            foreach (ClusterState c in before)
                if (!IsIdentity(c.PlasticDeformation))
                    flowed++;
            Assert.That(flowed, Is.EqualTo(body.Clusters.Length), "every cluster has flowed");

            body.Positions[17] = new float3(float.NaN, 0f, 0f);
            ShapeMatchingStepReport report = body.Step(1f / 60f);
            Assert.That(report.Reset, Is.True);
            Assert.That(report.BadParticle, Is.EqualTo(17));
            var view = body.Model.AsModel();
            Assert.That(BodyMeasures.ShapeError(body.Positions, view), Is.LessThanOrEqualTo(1e-5), "positions back at the rest shape");
            for (int c = 0; c < before.Length; c++)
            {
                Assert.That(SameBits(body.Clusters[c].PlasticDeformation, before[c].PlasticDeformation), Is.True, $"Sₚ of cluster {c}");
                Assert.That(SameBits(body.Clusters[c].Rest.AqqInverse, before[c].Rest.AqqInverse), Is.True, $"A_qq⁻¹ of cluster {c}");
            }
            for (int k = 0; k < quadraticBefore.Length; k++)
                Assert.That(SameBits(body.QuadraticInverse[k], quadraticBefore[k]), Is.True, $"quadratic inverse block {k}");
            for (int step = 0; step < 30; step++)
                Assert.That(body.Step(1f / 60f).Reset, Is.False);
        }

        /// <summary>
        /// Rigid goals cannot hold a deformed rest shape, so rigid mode never flows, however hard the body is deformed:
        /// squashed to a third of its height, stretched, or sheared by 60 %, with the plasticity of a clay set.
        /// </summary>
        [Test]
        public void RigidMode_NeverFlowsPlastically([Values(0, 1, 2)] int deformation, [Values(3, 5)] int clusterSize)
        {
            ShapeMatchingInstance body = Body(ShapeMatchingMode.Rigid, clusterSize, perInstanceQuadratic: false, float3.zero);
            for (int i = 0; i < body.Positions.Length; i++)
            {
                float3 x = body.Positions[i];
                body.Positions[i] = deformation == 0 ? x * new float3(1.7f, 1f / 3f, 1.7f)
                    : deformation == 1 ? x * new float3(2f, 0.7f, 0.7f)
                    : x + new float3(0.6f * x.y, 0f, 0f);
            }
            for (int step = 0; step < 120; step++)
            {
                ShapeMatchingStepReport report = body.Step(1f / 60f);
                Assert.That(report.PlasticUpdates, Is.EqualTo(0), $"step {step}");
                Assert.That(report.Reset, Is.False);
            }
            foreach (ClusterState c in body.Clusters)
                Assert.That(IsIdentity(c.PlasticDeformation), Is.True, "Sₚ = I");
        }

        /// <summary>
        /// Quadratic goals with plasticity need per-instance quadratic inverses to rewrite as the rest shape flows.
        /// Without them the step says so (<see cref="ShapeMatchingStepReport.PlasticityUnavailable"/>), the body stays
        /// elastic (Sₚ = I) and keeps its quadratic goals: no cluster falls back to linear goals. (With the inverses it
        /// flows: <see cref="ShapeMatchingPlasticityTests.Plasticity_WorksInQuadraticModeWithPerInstanceInverses"/>.)
        /// </summary>
        [Test]
        public void QuadraticPlasticity_WithoutPerInstanceInverses_IsReportedAndStaysElastic()
        {
            ShapeMatchingInstance body = Body(ShapeMatchingMode.Quadratic, 5, perInstanceQuadratic: false, float3.zero);
            for (int i = 0; i < body.Positions.Length; i++)
                body.Positions[i] *= new float3(1.3f, 0.6f, 1.3f);
            for (int step = 0; step < 120; step++)
            {
                ShapeMatchingStepReport report = body.Step(1f / 60f);
                Assert.That(report.PlasticityUnavailable, Is.True, $"step {step}");
                Assert.That(report.PlasticUpdates, Is.EqualTo(0), $"step {step}");
                Assert.That(report.Fallbacks, Is.EqualTo(0), $"step {step}: quadratic goals kept");
                Assert.That(report.Reset, Is.False);
            }
            foreach (ClusterState c in body.Clusters)
                Assert.That(IsIdentity(c.PlasticDeformation), Is.True, "Sₚ = I");
            var view = body.Model.AsModel();
            Assert.That(BodyMeasures.ShapeError(body.Positions, view) / BodyMeasures.RestSize(view), Is.LessThanOrEqualTo(0.01),
                "elastic: back to the rest shape");
        }

        /// <summary>
        /// At the maximum deformation the material has hardened. A body held squashed between two planes (to 60 % of
        /// its height: a strain far above the yield for as long as it is held) flows until ‖Sₚ − I‖_F reaches
        /// <see cref="PlasticityParameters.MaxDeformation"/> (0.999 of it, the refusal threshold); from then on its rest
        /// shape must not change at all, although the load keeps the strain above the yield. Sₚ of every cluster is
        /// compared bit for bit from the step it reached the bound to the end, 4 s later at most.
        /// </summary>
        [Test]
        public void PlasticFlow_StopsAtTheMaximumDeformation([Values(ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic)] ShapeMatchingMode mode,
            [Values(5, 3)] int clusterSize)
        {
            const float maxDeformation = 0.2f;
            ShapeMatchingInstance body = Body(mode, clusterSize, perInstanceQuadratic: true, new float3(0f, 0.2f + 0.02f, 0f));
            body.Parameters.Plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 10f, MaxDeformation = maxDeformation };
            float radius = body.Parameters.Body.ParticleRadius;
            // Floor and a ceiling 0.24 m + 2 radii above it: 60 % of the 0.4 m height.
            var press = new[]
            {
                ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)),
                ColliderShape.Plane(new float3(0f, 0.24f + 2f * radius, 0f), new float3(0f, -1f, 0f)),
            };
            Squash(body, 0.6f);
            int clusters = body.Clusters.Length;
            var frozen = new float3x3[clusters];
            var reached = new bool[clusters];
            int hardened = 0;
            for (int step = 0; step < 240; step++)
            {
                Assert.That(body.Step(1f / 60f, press).Reset, Is.False);
                for (int c = 0; c < clusters; c++)
                {
                    float3x3 sp = body.Clusters[c].PlasticDeformation;
                    if (reached[c])
                        Assert.That(SameBits(sp, frozen[c]), Is.True, $"step {step}: cluster {c} flowed after reaching the bound");
                    else if (Plasticity.FrobeniusNorm(sp - float3x3.identity) >= 0.999f * maxDeformation)
                    {
                        reached[c] = true;
                        frozen[c] = sp;
                        hardened++;
                    }
                }
            }
            Assert.That(hardened, Is.EqualTo(clusters), "every cluster reached the bound");
        }
    }
}
