using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The squash-and-release scene of the method study: its float64 reference is exact where an exact answer exists
    /// (the squashed state), damps a mode at the ratio its coefficient promises, uses the package's damping coefficient,
    /// its estimators read sampled motion correctly, and a method's measurement gives the volume its law predicts.
    /// </summary>
    public class SquashSceneTests
    {
        static ElasticMaterial Jelly => SquashScene.Material;

        /// <summary>
        /// Between frictionless plates the octant settles to the homogeneous uniaxial compression with the lateral
        /// stretch of <see cref="UniaxialNeoHookean"/> (Q2 represents it exactly, so every node agrees), and the plate
        /// carries the nominal stress times the face area. Started from the small-strain guess s = 1 + ν(1 − λ), off by
        /// 0.13 L/2. Bounds: Newton stops at an absolute residual of 1e-10 N or a step of 1e-13 of u; the stiffness is
        /// ~E L = 4e3 N/m, so displacements agree to ~1e-14 m; 1e-10 L leaves room for round-off in the assembly
        /// (relative 1e-16 × condition number ≲ 1e4). The reaction is a sum of element forces of size |P| (L/2)²: 1e-9 relative.
        /// </summary>
        [TestCase(1)]
        [TestCase(2)]
        public void Reference_SquashedStateIsTheExactHomogeneousCompression(int resolution)
        {
            ElasticMaterial m = Jelly;
            double size = SquashScene.Size, stretch = SquashScene.Stretch;
            (double[] u, FemSolveReport report) = SquashReference.Squashed(size, m.YoungsModulus, m.PoissonRatio, m.Density, resolution, stretch);
            Assert.IsTrue(report.Converged);
            UniaxialResult exact = UniaxialNeoHookean.Stress(stretch, m.YoungsModulus, m.PoissonRatio, SquashReference.Law);
            FemReferenceModel model = SquashReference.Model(size, m.YoungsModulus, m.PoissonRatio, m.Density, resolution, plates: true);
            double[] expected = SquashReference.Homogeneous(model.Mesh, stretch, exact.LateralStretch);
            for (int d = 0; d < u.Length; d++)
                Assert.That(u[d], Is.EqualTo(expected[d]).Within(1e-10 * size), $"dof {d}");
            var force = new double[u.Length];
            model.InternalForce(u, force, null);
            double reaction = 0;
            FemBoxMesh mesh = model.Mesh;
            for (int i = 0; i < mesh.NodesX; i++)
            for (int k = 0; k < mesh.NodesZ; k++)
                reaction += force[mesh.Node(i, mesh.NodesY - 1, k) * 3 + 1];
            double area = 0.25 * size * size;
            Assert.That(reaction, Is.EqualTo(exact.NominalStress * area).Within(1e-9 * Math.Abs(exact.NominalStress) * area));
        }

        /// <summary>
        /// Kelvin–Voigt damping with β = 2ζ/ω: the lowest symmetric mode of the octant (r = 1), started at a strain of ~1e-6
        /// (linear: the viscous force is β K₀ v), follows the damped oscillator q(t) = e^(−ζωt)(cos ω_d t + ζ/√(1 − ζ²)
        /// sin ω_d t), ω_d = ω√(1 − ζ²), for two periods with ζ = 0.1. Newmark's average acceleration at h = T/200 has a
        /// relative frequency error (ωh)²/12 = 8e-5, a phase error of 1e-3 rad after two periods, so |Δq| ≲ 1e-3; bound 2e-3.
        /// A ratio of βω instead of βω/2 would make q(2T) 0.08 instead of 0.28.
        /// </summary>
        [Test]
        public void Reference_DampedModeDecaysAtRatioBetaOmegaOverTwo()
        {
            const double zeta = 0.1, amplitude = 1e-6 * SquashScene.Size;
            ElasticMaterial m = Jelly;
            FemReferenceModel model = SquashReference.Model(SquashScene.Size, m.YoungsModulus, m.PoissonRatio, m.Density, 1);
            (double w2, double[] mode, _) = FemEigen.Lowest(model, new double[model.Mesh.DofCount],
                SquashReference.Homogeneous(model.Mesh, 0.5, 1.25));
            double omega = Math.Sqrt(w2), period = 2 * Math.PI / omega, omegaD = omega * Math.Sqrt(1 - zeta * zeta);
            var u0 = new double[model.Mesh.DofCount];
            for (int k = 0; k < model.FreeCount; k++)
                u0[model.FreeDofs[k]] = amplitude * mode[k];
            const int steps = 400;
            // Linear problem: one factorisation serves every step.
            var run = new FemNewmark(model, new double[u0.Length], 2 * period / steps, u0, null, 2 * zeta / omega) { ReuseTangent = true };
            FemCsrMatrix mass = model.MassMatrix();
            var mphi = new double[model.FreeCount];
            mass.Multiply(mode, mphi);
            double worst = 0;
            for (int s = 1; s <= steps; s++)
            {
                Assert.IsTrue(run.Step().Converged);
                double q = 0;
                for (int k = 0; k < model.FreeCount; k++)
                    q += mphi[k] * run.U[model.FreeDofs[k]];
                q /= amplitude;
                double t = run.Time;
                double exact = Math.Exp(-zeta * omega * t) * (Math.Cos(omegaD * t) + zeta / Math.Sqrt(1 - zeta * zeta) * Math.Sin(omegaD * t));
                worst = Math.Max(worst, Math.Abs(q - exact));
            }
            TestContext.WriteLine($"ω = {omega} rad/s, worst |q − q_exact| = {worst}");
            Assert.That(worst, Is.LessThan(2e-3));
        }

        /// <summary>
        /// The reference's β is the one the package's FEM and mass-spring bodies of the scene's cube compute from the same
        /// material (float32 there: 1e-6 relative).
        /// </summary>
        [Test]
        public void Reference_DampingCoefficientIsThePackagesRayleighBeta()
        {
            MethodBodySetup setup = SquashScene.CreateSetup(2);
            var issues = new List<ValidationIssue>();
            FemModelData fem = FemModelData.Create(setup.Mesh, setup.Material, new bool[setup.Mesh.NodeCount], issues);
            MassSpringModelData.FromMesh(setup.Mesh, setup.Material, MassSpringBuildSettings.Default, issues, out MassSpringCalibration.Result springs);
            double beta = SquashTargets.DampingCoefficient(setup.Material, SquashScene.Size);
            Assert.That(FemSolver.DampingCoefficient(fem.AsModel(), FemParameters.Default), Is.EqualTo(beta).Within(1e-6 * beta));
            Assert.That(springs.RayleighBeta, Is.EqualTo(beta).Within(1e-6 * beta));
        }

        /// <summary>
        /// The viscous stress is frame-indifferent (a rigid spin Ḟ = W F, W skew, gives no stress: round-off 1e-12 of
        /// β E |Ḟ|), and its rate tangent is its derivative (P_v is linear in Ḟ, so a difference quotient is exact up to
        /// round-off: 1e-7 relative with δ = 1e-3) and symmetric.
        /// </summary>
        [Test]
        public void FemViscosity_IsFreeUnderRigidSpinAndItsTangentIsItsDerivative()
        {
            const double beta = 0.01, mu = 3000, lambda = 30000;
            double[] h = { -0.4, 0.1, 0.05, 0.02, 0.3, -0.1, 0.07, 0.04, 0.2 };
            double[] w = { 0, -0.7, 0.2, 0.7, 0, -0.5, -0.2, 0.5, 0 };
            var spin = new double[9];
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                spin[3 * i + j] += w[3 * i + k] * (h[3 * k + j] + (k == j ? 1 : 0));
            var p = new double[9];
            FemViscosity.Evaluate(h, spin, beta, mu, lambda, p, Span<double>.Empty);
            foreach (double v in p)
                Assert.That(Math.Abs(v), Is.LessThan(1e-12 * beta * lambda));
            double[] rate = { 0.3, -0.2, 0.1, 0.05, -0.6, 0.2, -0.1, 0.15, 0.4 };
            var tangent = new double[81];
            var p0 = new double[9];
            var p1 = new double[9];
            FemViscosity.Evaluate(h, rate, beta, mu, lambda, p0, tangent);
            const double delta = 1e-3;
            for (int kl = 0; kl < 9; kl++)
            {
                var shifted = (double[])rate.Clone();
                shifted[kl] += delta;
                FemViscosity.Evaluate(h, shifted, beta, mu, lambda, p1, Span<double>.Empty);
                for (int ij = 0; ij < 9; ij++)
                {
                    double scale = beta * (lambda + 2 * mu);
                    Assert.That((p1[ij] - p0[ij]) / delta, Is.EqualTo(tangent[9 * ij + kl]).Within(1e-7 * scale), $"∂P{ij}/∂Ḟ{kl}");
                    Assert.That(tangent[9 * kl + ij], Is.EqualTo(tangent[9 * ij + kl]).Within(1e-12 * scale));
                }
            }
        }

        /// <summary>
        /// The estimators on one damped mode sampled at 60 Hz, a = e^(−σt)cos(ω_d t), ω = 2π·3.3 rad/s, ζ = 0.14 (the cube's),
        /// against the same estimators on a 1000× finer grid. Recovery time of A = √(a² + ȧ²/ω²): ln A = −σt + ½ ln(1 + ζ
        /// sin(2ω_d t + φ)) to first order in ζ, so log-linear interpolation over Δt misses by at most (2ζω_d²)Δt²/8 in ln A,
        /// i.e. ωΔt²/4 = 1.4 ms in time (0.2 % of the cube's recovery time); bound 1.5 ms. Overshoot of h = 1 − ½a: the
        /// parabola through three samples at 18 per period misses the peak of a cosine by at most 3.4e-4 of its amplitude,
        /// 1e-3 of this overshoot (0.65); bound 1e-3 relative.
        /// </summary>
        [Test]
        public void SquashMeasures_ReadASampledDampedModeLikeTheContinuousOne()
        {
            double omega = 2 * Math.PI * 3.3, zeta = 0.14, sigma = zeta * omega, omegaD = omega * Math.Sqrt(1 - zeta * zeta);
            double Amplitude(double t)
            {
                double e = Math.Exp(-sigma * t), a = e * Math.Cos(omegaD * t), da = -e * (sigma * Math.Cos(omegaD * t) + omegaD * Math.Sin(omegaD * t));
                return Math.Sqrt(a * a + da * da / (omega * omega));
            }
            double Height(double t) => 1 - 0.5 * Math.Exp(-sigma * t) * Math.Cos(omegaD * t);
            (double recovery, double overshoot) Read(double dt, int count)
            {
                var a = new double[count];
                var h = new double[count];
                for (int k = 0; k < count; k++)
                {
                    a[k] = Amplitude(k * dt);
                    h[k] = Height(k * dt);
                }
                return (SquashMeasures.RecoveryTime(a, dt, 0.01), SquashMeasures.Overshoot(h, 1, 0.5));
            }
            (double coarseRecovery, double coarseOvershoot) = Read(StudyScene.Dt, 150);
            (double fineRecovery, double fineOvershoot) = Read(StudyScene.Dt / 1000, 150000);
            TestContext.WriteLine($"recovery {coarseRecovery} vs {fineRecovery} s, overshoot {coarseOvershoot} vs {fineOvershoot}");
            Assert.That(coarseRecovery, Is.EqualTo(fineRecovery).Within(1.5e-3));
            Assert.That(coarseOvershoot, Is.EqualTo(fineOvershoot).Within(1e-3 * fineOvershoot));
        }

        /// <summary>
        /// Implicit FEM holds the plates' contact nodes in its solve (frictionless contacts), so the squashed cube settles at
        /// its law's homogeneous state, as the explicit step does: Neo-Hookean (the reference's law) to zero, co-rotational to
        /// its own uniaxial state, lateral stretch 1 + ν(1 − λ) (linear elasticity in the unrotated frame), volume error
        /// |λ(1 + ν(1 − λ))²/J − 1| = 16.6 %. Pushed out after the solve instead, the coupled solve lets the interior expand
        /// each 1/60 s substep: 13 % and 24 % (measured). Bound 2e-4: CG to 1e-5, float32 volumes 1e-6, the lateral motion
        /// of the start decays in the 1 s between the plates.
        /// </summary>
        [TestCase(FemMaterialModel.NeoHookean)]
        [TestCase(FemMaterialModel.CoRotational)]
        public void Measure_FemImplicit_SettlesAtItsLawsSquashedVolume(FemMaterialModel materialModel)
        {
            MethodBodySetup setup = SquashScene.CreateSetup(2);
            SquashTargets targets = SquashTargets.Compute(setup.Material, new[] { 1 }, new[] { 4 });
            IReadOnlyList<Metric> metrics = new SquashScene().Measure(setup,
                s => new FemMethodBody(s, materialModel, FemIntegrator.ImplicitEuler, 1, 2000, 1e-5f), targets);
            double volumeError = double.NaN;
            foreach (Metric metric in metrics)
                if (metric.Name == SquashScene.VolumeError)
                    volumeError = metric.Value;
            double nu = setup.Material.PoissonRatio, stretch = SquashScene.Stretch, lateral = 1 + nu * (1 - stretch);
            double expected = materialModel == FemMaterialModel.NeoHookean ? 0 : Math.Abs(stretch * lateral * lateral / targets.VolumeRatio - 1);
            Assert.That(volumeError, Is.EqualTo(expected).Within(2e-4));
        }

        /// <summary>
        /// The scene's measurement of explicit Neo-Hookean FEM (2 cells per edge, 128 substeps, against targets from the
        /// coarsest reference run): every metric is finite, nothing resets, the cube recovers, and the squashed volume error
        /// is zero: linear tetrahedra represent the homogeneous squash exactly and the reference has the element's law
        /// (<see cref="SquashReference.Law"/>; the classical law's J would put it at 1.36 %). Bound 2e-4: float32 volumes
        /// 1e-6, the lateral motion the start excites decays by e^(−3) in the 1 s between the plates from ~1e-3 of L.
        /// The worst error is at least that.
        /// </summary>
        [Test]
        public void Measure_FemNeoHookeanExplicit_KeepsTheExactSquashedVolume()
        {
            MethodBodySetup setup = SquashScene.CreateSetup(2);
            SquashTargets targets = SquashTargets.Compute(setup.Material, new[] { 1 }, new[] { 4 });
            IReadOnlyList<Metric> metrics = new SquashScene().Measure(setup,
                s => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.SymplecticEuler, 128), targets);
            var values = new Dictionary<string, double>();
            foreach (Metric metric in metrics)
            {
                values[metric.Name] = metric.Value;
                TestContext.WriteLine($"{metric.Name} = {metric.Value}");
                Assert.IsTrue(double.IsFinite(metric.Value), metric.Name);
            }
            Assert.That(values[SquashScene.VolumeError], Is.LessThan(2e-4));
            Assert.AreEqual(0, values[StudyScene.Resets]);
            Assert.AreEqual(1, values[SquashScene.Recovered]);
            Assert.That(values[StudyScene.Error], Is.GreaterThanOrEqualTo(values[SquashScene.VolumeError]));
        }
    }
}
