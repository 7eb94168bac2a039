using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// A body resting on a flat floor stays where it is. The 7³ lattice, with 3-particle clusters (over lattice indices
    /// [0-2], [2-4], [4-6] on each axis) or one cluster, is mirror-symmetric left-right and front-back; it starts
    /// upright, centred on x = z = 0 and 1 cm above the floor, and gravity is vertical: in exact arithmetic nothing
    /// pushes it sideways. Float32 round-off of the 0.3 m coordinates (≤ 3e-8 m a rounding) breaks the symmetry only
    /// at that level, and friction (μ ≥ 0.4 against a load of about g per particle) holds such a residue. Even a residue
    /// that kept acting in the same direction every substep of the 15 s measured (at most 7200 substeps: 120 Hz with 4
    /// substeps) would move the centre by less than 7200 × 3e-8 m ≈ 0.2 mm. The horizontal drift of the centre from
    /// 5 s (landed and settled) to 20 s is asserted below 1 mm: Jelly at 30 Hz, Clay at 60 Hz with overlapping clusters
    /// (it yields on landing, so its plastic flow is part of the test) and Rubber at 120 Hz with overlapping clusters;
    /// sleeping is off, so the body is simulated all the way.
    /// </summary>
    public class ShapeMatchingCreepTests
    {
        public enum Preset { Jelly, Rubber, Clay }

        [TestCase(Preset.Jelly, 30, 7)]
        [TestCase(Preset.Clay, 60, 3)]
        [TestCase(Preset.Rubber, 120, 3)]
        public void RestingBody_DoesNotCreepSideways(Preset preset, int frameRate, int clusterSize)
        {
            ShapeMatchingMaterial material = preset == Preset.Jelly ? ShapeMatchingMaterial.Jelly
                : preset == Preset.Rubber ? ShapeMatchingMaterial.Rubber : ShapeMatchingMaterial.Clay;
            var p = material.ApplyTo(ShapeMatchingParameters.Default);
            p.Body.SleepSpeed = 0f;
            var model = LatticeBody.Create(new int3(7, 7, 7), 0.1f, clusterSize, 1f);
            Assert.That(model.ClusterCount, Is.EqualTo(clusterSize == 3 ? 27 : 1), "clusters [0-2], [2-4], [4-6] on each axis, or one");
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            var body = new ShapeMatchingInstance(model, p, new float3(0f, 0.3f + p.Body.ParticleRadius + 0.01f, 0f), quaternion.identity);
            float dt = 1f / frameRate;
            int settle = 5 * frameRate, end = 20 * frameRate;
            float3 settled = float3.zero;
            int plastic = 0;
            for (int step = 1; step <= end; step++)
            {
                ShapeMatchingStepReport report = body.Step(dt, floor);
                Assert.That(report.Reset, Is.False, $"step {step}");
                plastic += report.PlasticUpdates;
                if (step == settle)
                    settled = body.Status.Center;
            }
            float3 drift = body.Status.Center - settled;
            Assert.That(math.length(new float3(drift.x, 0f, drift.z)), Is.LessThanOrEqualTo(1e-3f), "horizontal drift from 5 s to 20 s (m)");
            if (preset == Preset.Clay)
                Assert.That(plastic, Is.GreaterThan(0), "the clay yields on landing, so its plasticity is part of the test");
        }
    }
}
