using System;
using NUnit.Framework;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Determinism across batch splits, momentum of free networks and pins, for every integrator.</summary>
    public class MassSpringConservationTests
    {
        static MassSpringTestBody Jelly(int seed, bool[] pinned = null)
        {
            var body = new MassSpringTestBody(MassSpringTestBody.Box(3, 2, 2, 0.05f, ElasticMaterial.Jelly, bending: true, pinned: pinned));
            var random = new System.Random(seed);
            for (int i = 0; i < body.Positions.Length; i++)
            {
                if (pinned != null && pinned[i])
                    continue;
                body.Positions[i] += new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f) * 0.01f;
                body.Velocities[i] = new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f) * 0.2f;
            }
            return body;
        }

        static MassSpringParameters Parameters(MassSpringIntegrator integrator, bool gravity)
        {
            MassSpringParameters p = MassSpringTestBody.Plain(integrator);
            p.Body.Substeps = 8;
            p.CgTolerance = 1e-4f;
            p.Iterations = 2;
            p.Body.Acceleration = gravity ? new float3(0f, -9.81f, 0f) : float3.zero;
            return p;
        }

        [Test]
        public void Determinism_SameBitsForAnyBatchSplit()
        {
            foreach (MassSpringIntegrator integrator in Enum.GetValues(typeof(MassSpringIntegrator)))
            {
                MassSpringTestBody reference = Jelly(11);
                MassSpringParameters p = Parameters(integrator, gravity: true);
                for (int n = 0; n < 20; n++)
                    reference.Step(p, 1f / 60f);
                foreach (int batch in new[] { 1, 3, 7, 64 })
                {
                    MassSpringTestBody other = Jelly(11);
                    for (int n = 0; n < 20; n++)
                        other.Step(p, 1f / 60f, batch);
                    for (int i = 0; i < reference.Positions.Length; i++)
                    {
                        Assert.IsTrue(math.all(reference.Positions[i] == other.Positions[i]), $"{integrator} batch {batch} x{i}");
                        Assert.IsTrue(math.all(reference.Velocities[i] == other.Velocities[i]), $"{integrator} batch {batch} v{i}");
                    }
                }
            }
        }

        [Test]
        public void Momentum_FreeNetworkKeepsIt()
        {
            foreach (MassSpringIntegrator integrator in Enum.GetValues(typeof(MassSpringIntegrator)))
            {
                MassSpringTestBody body = Jelly(5);
                MassSpringParameters p = Parameters(integrator, gravity: false);
                double3Sum(body, out double px0, out double py0, out double pz0, out double scale);
                for (int n = 0; n < 60; n++)
                    Assert.IsFalse(body.Step(p, 1f / 60f).Reset);
                double3Sum(body, out double px, out double py, out double pz, out _);
                double drift = Math.Sqrt((px - px0) * (px - px0) + (py - py0) * (py - py0) + (pz - pz0) * (pz - pz0));
                // Internal forces cancel pairwise (f_B = −f_A exactly); what is left is float32 round-off of mᵢwᵢ ≠ 1
                // and of the sums: 1e-5 of Σ m|v| (the plan's row 3 and 22 criterion), over 480 substeps. Verlet's and
                // XPBD's velocities are position differences over h: the rounding of x + h v (ulp(0.15 m)/2 ≈ 7e-9 m
                // per particle, twice for XPBD: p and x*) becomes a velocity error of 7e-9/h ≈ 3.5e-6 m/s per particle
                // and substep, independent between particles: ≈ 3.5e-6 √480 / (0.1 m/s · √36) ≈ 1e-4 to 2e-4 of
                // Σ m|v|; 2e-3 allowed.
                bool positionBased = integrator == MassSpringIntegrator.Verlet || integrator == MassSpringIntegrator.Xpbd;
                double bound = positionBased ? 2e-3 : 1e-5;
                TestContext.WriteLine($"{integrator}: |ΔP| / Σ m|v| = {drift / scale:E2}");
                Assert.That(drift / scale, Is.LessThanOrEqualTo(bound), integrator.ToString());
            }
        }

        [Test]
        public void Pins_HoldTheirParticles()
        {
            MassSpringTestBody probe = Jelly(1);
            var pinned = new bool[probe.Positions.Length];
            for (int i = 0; i < pinned.Length; i++)
                pinned[i] = probe.Data.RestPositions[i].x == 0f;
            foreach (MassSpringIntegrator integrator in Enum.GetValues(typeof(MassSpringIntegrator)))
            {
                MassSpringTestBody body = Jelly(2, pinned);
                for (int i = 0; i < pinned.Length; i++)
                    if (pinned[i])
                        body.Velocities[i] = float3.zero;
                float3[] start = (float3[])body.Positions.Clone();
                MassSpringParameters p = Parameters(integrator, gravity: true);
                for (int n = 0; n < 60; n++)
                    Assert.IsFalse(body.Step(p, 1f / 60f).Reset, integrator.ToString());
                for (int i = 0; i < pinned.Length; i++)
                    if (pinned[i])
                    {
                        Assert.AreEqual(start[i], body.Positions[i], $"{integrator} pin {i}");
                        Assert.AreEqual(float3.zero, body.Velocities[i]);
                    }
                // The body hangs: its free particles moved under gravity and stayed finite and near the wall.
                for (int i = 0; i < pinned.Length; i++)
                    Assert.That(math.length(body.Positions[i] - body.Data.RestPositions[i]), Is.LessThan(0.2f), $"{integrator} {i}");
            }
        }

        static void double3Sum(MassSpringTestBody body, out double px, out double py, out double pz, out double scale)
        {
            px = py = pz = scale = 0.0;
            for (int i = 0; i < body.Positions.Length; i++)
            {
                double m = body.Data.Masses[i];
                px += m * body.Velocities[i].x;
                py += m * body.Velocities[i].y;
                pz += m * body.Velocities[i].z;
                scale += m * math.length(body.Velocities[i]);
            }
        }
    }
}
