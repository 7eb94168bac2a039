using System;
using System.Collections.Generic;
using NUnit.Framework;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Calibration to Young's modulus, presets, and the hybrid body (shape matching + springs).</summary>
    public class MassSpringCalibrationTests
    {
        [TestCase(false)]
        [TestCase(true)]
        public void Calibration_StretchedBoxGivesYoungsModulus(bool bending)
        {
            var settings = new MassSpringBuildSettings { BendingSprings = bending };
            MassSpringCalibration.Result fit = MassSpringCalibration.FitFactor(settings);
            TestContext.WriteLine($"bending {bending}: c = {fit.Factor:G6}, residual {fit.Residual:E2}, E/E along x y z " +
                                  $"{fit.RelativeModulusX:F4} {fit.RelativeModulusY:F4} {fit.RelativeModulusZ:F4}, ν_eff {fit.EffectivePoissonRatio:F4}");
            Assert.IsTrue(fit.Factor > 0.0 && double.IsFinite(fit.Factor));
            Assert.That(fit.Residual, Is.LessThan(0.5));

            // The fitted network of the reference box, E = 1 MPa, stretched 1 % along x: the uniaxial stress from the
            // run-time float32 spring forces at the static solution is E·ε within the reported residual, plus 1.5 ε for
            // the geometric non-linearity the linear solve leaves out (L − L₀ = n·Δ + O(|Δ|²/L) and the turn of n: both
            // relative O(ε); measured 1.0 ε without and 0.5 ε with bending springs).
            const double e = 1e6, strain = 0.01;
            int n = MassSpringCalibration.ReferenceCells;
            TetrahedralMesh box = BoxTetrahedra.Create(new float3(0.1f * n), new int3(n), new float3(0.05f * n));
            var issues = new List<ValidationIssue>();
            MassSpringNetwork network = MassSpringNetwork.Build(box, settings, issues);
            MassSpringCalibration.Apply(network, e, fit.Factor, 0.0);
            MassSpringCalibration.UniaxialModulus(box, network.Springs, 0, out _, out double[] u);
            double scale = strain / MassSpringCalibration.ReferenceStrain;
            var x = new float3[box.NodeCount];
            for (int i = 0; i < x.Length; i++)
                x[i] = box.Positions[i] + new float3((float)(scale * u[3 * i]), (float)(scale * u[3 * i + 1]), (float)(scale * u[3 * i + 2]));
            var data = MassSpringModelData.Create(box.Positions, new float[box.NodeCount], network.Springs);
            var slots = new float3[2 * network.Springs.Length];
            var force = new float3[box.NodeCount];
            SpringForces.Compute(network.Springs, box.Positions, x, new float3[x.Length], 0, network.Springs.Length, slots);
            ElementIncidence.Gather(data.Incidence.Offsets, data.Incidence.Slots, slots, 0, x.Length, force);
            double reaction = 0.0;
            for (int i = 0; i < x.Length; i++)
                if (math.abs(box.Positions[i].x - 0.4f) < 1e-6f)
                    reaction -= force[i].x;
            double stress = reaction / (0.4 * 0.4);
            double relative = stress / (e * strain) - 1.0;
            TestContext.WriteLine($"σ/(Eε) − 1 = {relative:E3}");
            Assert.That(Math.Abs(relative), Is.LessThanOrEqualTo(fit.Residual + 1.5 * strain));
        }

        [Test]
        public void Calibration_PresetsGiveFinitePositiveStiffness()
        {
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(3, 2, 2) * 0.05f, new int3(3, 2, 2), 0.025f * new float3(3, 2, 2));
            foreach (ElasticMaterial material in new[] { ElasticMaterial.Jelly, ElasticMaterial.Rubber, ElasticMaterial.Clay, ElasticMaterial.Flesh })
            {
                var issues = new List<ValidationIssue>();
                MassSpringModelData data = MassSpringModelData.FromMesh(mesh, material, MassSpringBuildSettings.Default, issues,
                    out MassSpringCalibration.Result result);
                Assert.IsNotNull(data, string.Join("\n", issues));
                foreach (Spring s in data.Springs)
                {
                    Assert.IsTrue(s.Stiffness > 0f && float.IsFinite(s.Stiffness));
                    Assert.IsTrue(s.Damping > 0f && float.IsFinite(s.Damping));
                    // Rayleigh: c = β k, β = 2ζ/ω_ref.
                    Assert.That(s.Damping / s.Stiffness, Is.EqualTo((float)result.RayleighBeta).Within(1e-5f * (float)result.RayleighBeta));
                }
                double omega = Math.PI * material.ShearWaveSpeed / 0.15;
                Assert.That(result.ReferenceFrequency, Is.EqualTo(omega).Within(1e-4 * omega));
                // Lumped masses add up to ρ V.
                double mass = 0.0;
                foreach (float m in data.Masses)
                    mass += m;
                Assert.That(mass, Is.EqualTo(material.Density * 0.15 * 0.1 * 0.1).Within(1e-5 * mass));
            }
            var bad = new List<ValidationIssue>();
            Assert.IsNull(MassSpringModelData.FromMesh(mesh, new ElasticMaterial(-1f, 0.3f, 1000f, 0.1f), default, bad, out _));
            Assert.IsTrue(bad.Exists(i => i.Code == MassSpringIssueCode.MaterialInvalid));
        }

        [Test]
        public void Hybrid_ShapeMatchingPlusSpringsReturnsToRest()
        {
            MassSpringModelData springs = MassSpringTestBody.Box(2, 2, 2, 0.05f, ElasticMaterial.Jelly);
            int n = springs.ParticleCount;
            var members = new int[n];
            for (int i = 0; i < n; i++)
                members[i] = i;
            ShapeMatchingModelData shape = ShapeMatchingModelData.Create(springs.RestPositions, springs.Masses, new[] { 0, n }, members, false);
            ShapeMatchingParameters sp = ShapeMatchingParameters.Default;
            sp.Body.Acceleration = float3.zero;
            sp.Body.SleepSpeed = 0f;
            MassSpringParameters mp = MassSpringParameters.Default;
            float dt = 1f / 60f;
            int substeps = ShapeMatchingSolver.Constants(sp.Sanitized(), dt).Substeps;
            Assert.Less(dt / substeps, MassSpringStability.MaxStableStep(springs.AsModel()), "explicit springs stable at this substep");

            var x = new float3[n];
            var v = new float3[n];
            var clusters = new ClusterState[1];
            var smScratch = new float3[ShapeMatchingState.ScratchPerParticle * n];
            var msScratch = new float3[MassSpringState.ScratchPerParticle * n];
            var springScratch = new float3[MassSpringState.ScratchPerSpring * springs.SpringCount];
            var smState = ShapeMatchingState.FromScratch(x, v, clusters, Span<float3x3>.Empty, smScratch);
            var msState = MassSpringState.FromScratch(x, v, msScratch, springScratch);
            ShapeMatchingSolver.Initialize(shape.AsModel(), smState, new float3(0f, 1f, 0f), quaternion.identity, float3.zero, out ParticleBodyStatus status);
            // Stretch 20 % along x about the centre.
            for (int i = 0; i < n; i++)
                x[i].x = 1.2f * x[i].x;
            double initial = Deformation(x, springs, status);
            for (int step = 0; step < 180; step++)
            {
                ParticleStepReport r = HybridSolver.Step(shape.AsModel(), sp, smState, springs.AsModel(), mp, msState,
                    ReadOnlySpan<ColliderShape>.Empty, dt, ref status);
                Assert.IsFalse(r.Reset);
            }
            double final = Deformation(x, springs, status);
            TestContext.WriteLine($"deformation {initial:E3} → {final:E3} m after 3 s");
            // Both stages pull toward the rest shape and the goals' damping (ζ = 0.13 at 9 Hz: e^{−ζω·3 s} ≈ 3e-10) and the
            // dashpots remove the motion: after 3 s, below 1 % of the initial deformation.
            Assert.That(final, Is.LessThan(0.01 * initial));
        }

        /// <summary>Largest distance of a particle from the rest shape placed at the body's centre and rotation (m).</summary>
        static double Deformation(float3[] x, MassSpringModelData model, in ParticleBodyStatus status)
        {
            float3 center = float3.zero;
            float mass = 0f;
            for (int i = 0; i < x.Length; i++)
            {
                center += model.Masses[i] * x[i];
                mass += model.Masses[i];
            }
            center /= mass;
            float3x3 r = new float3x3(status.Rotation);
            double max = 0.0;
            for (int i = 0; i < x.Length; i++)
                max = Math.Max(max, math.length(x[i] - center - math.mul(r, model.RestPositions[i] - model.RestCenter)));
            return max;
        }
    }
}
