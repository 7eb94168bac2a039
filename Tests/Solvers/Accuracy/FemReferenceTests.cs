using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The float64 finite-element reference (<see cref="FemReferenceModel"/> and its scenarios) is correct and converged: exact
    /// for homogeneous states, a consistent tangent, the beam limits of Euler–Bernoulli, the Turek–Hron CSM3 benchmark
    /// and the closed-form uniaxial curve. The soft-body comparison measures its methods' errors against these values.
    /// </summary>
    public class FemReferenceTests
    {
        static readonly FemMaterialLaw[] Laws = { FemMaterialLaw.NeoHookean, FemMaterialLaw.StVenantKirchhoff, FemMaterialLaw.StableNeoHookean };
        static readonly FemMaterialLaw[] NeoHookeanLaws = { FemMaterialLaw.NeoHookean, FemMaterialLaw.StableNeoHookean };

        /// <summary>
        /// Patch test: u = (F₀ − I)X on every node of a 2 × 2 × 2 box gives F = F₀ at every Gauss point (Q2 reproduces
        /// linear fields), so f_a = ∮ N_a P n dA exactly: zero on interior nodes, and on a boundary face the uniform
        /// traction P n times the face's consistent weights (per element edge of length ℓ: ℓ/6 at a vertex, 4ℓ/6 at
        /// the midpoint, products over the face's two directions). Bound: round-off of sums of element forces of size
        /// |P|·ℓ², relative 1e-16 × a few hundred terms: 1e-12 |P|max ℓ².
        /// </summary>
        [TestCaseSource(nameof(Laws))]
        public void Fem_HomogeneousDeformationGivesExactNodalForces(FemMaterialLaw law)
        {
            FemBoxMesh mesh = FemBoxMesh.Box(0.3, 0.2, 0.25, 2, 2, 2);
            var material = new FemMaterial(law, 1e6, 0.3);
            var model = new FemReferenceModel(mesh, material, 1000, new bool[mesh.DofCount]);
            double[] h = { 0.12, -0.05, 0.03, 0.04, -0.08, 0.06, -0.02, 0.07, 0.1 };
            var u = new double[mesh.DofCount];
            for (int n = 0; n < mesh.NodeCount; n++)
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    u[n * 3 + i] += h[3 * i + j] * mesh.Positions[n * 3 + j];
            var p = new double[9];
            Assert.IsTrue(material.Evaluate(h, p, Span<double>.Empty, out _));
            double pMax = 0;
            foreach (double v in p)
                pMax = Math.Max(pMax, Math.Abs(v));
            var force = new double[mesh.DofCount];
            model.InternalForce(u, force, null);

            double[] ell = { mesh.ElementSizeX, mesh.ElementSizeY, mesh.ElementSizeZ };
            int[] counts = { mesh.NodesX, mesh.NodesY, mesh.NodesZ };
            double worst = 0;
            for (int gi = 0; gi < mesh.NodesX; gi++)
            for (int gj = 0; gj < mesh.NodesY; gj++)
            for (int gk = 0; gk < mesh.NodesZ; gk++)
            {
                int[] g = { gi, gj, gk };
                var expected = new double[3];
                for (int axis = 0; axis < 3; axis++)
                {
                    int sign = g[axis] == 0 ? -1 : g[axis] == counts[axis] - 1 ? 1 : 0;
                    if (sign == 0)
                        continue;
                    double weight = 1;
                    for (int other = 0; other < 3; other++)
                        if (other != axis)
                            weight *= FaceWeight(g[other], counts[other], ell[other]);
                    for (int i = 0; i < 3; i++)
                        expected[i] += sign * p[3 * i + axis] * weight;
                }
                int node = mesh.Node(gi, gj, gk);
                for (int i = 0; i < 3; i++)
                    worst = Math.Max(worst, Math.Abs(force[node * 3 + i] - expected[i]));
            }
            Assert.That(worst, Is.LessThan(1e-12 * pMax * ell[0] * ell[1]), "largest nodal force error (N)");
        }

        /// <summary>∫ N_a over a 1-D quadratic element chain at grid index g of count nodes: ℓ/6 per element at a vertex, 4ℓ/6 at a midpoint.</summary>
        static double FaceWeight(int g, int count, double ell)
        {
            if (g % 2 == 1)
                return 4 * ell / 6;
            return (g == 0 || g == count - 1 ? 1 : 2) * ell / 6;
        }

        /// <summary>
        /// The material's P is the gradient of Ψ and 𝔸 the gradient of P, by central differences at a finite strain
        /// (step ε = 1e-6: truncation ε² |Ψ'''| ~ 1e-12 E, round-off 1e-16 |Ψ|/ε ~ 1e-10 E). Tolerance 1e-7 E.
        /// </summary>
        [TestCaseSource(nameof(Laws))]
        public void FemMaterial_StressAndTangentAreEnergyDerivatives(FemMaterialLaw law)
        {
            const double e = 1e6, eps = 1e-6;
            var material = new FemMaterial(law, e, 0.35);
            double[] h = { 0.2, -0.1, 0.05, 0.15, -0.25, 0.1, -0.05, 0.08, 0.3 };
            var p = new double[9];
            var a = new double[81];
            material.Evaluate(h, p, a, out _);
            var hp = new double[9];
            var pp = new double[9];
            var pm = new double[9];
            double worstP = 0, worstA = 0;
            for (int k = 0; k < 9; k++)
            {
                Array.Copy(h, hp, 9);
                hp[k] += eps;
                material.Evaluate(hp, pp, Span<double>.Empty, out double psiP);
                hp[k] -= 2 * eps;
                material.Evaluate(hp, pm, Span<double>.Empty, out double psiM);
                worstP = Math.Max(worstP, Math.Abs((psiP - psiM) / (2 * eps) - p[k]));
                for (int m = 0; m < 9; m++)
                    worstA = Math.Max(worstA, Math.Abs((pp[m] - pm[m]) / (2 * eps) - a[9 * m + k]));
            }
            Assert.That(worstP, Is.LessThan(1e-7 * e), "P − ∂Ψ/∂F (Pa)");
            Assert.That(worstA, Is.LessThan(1e-7 * e), "𝔸 − ∂P/∂F (Pa)");
        }

        /// <summary>
        /// The assembled tangent K is the derivative of the assembled forces: K v = (f(u + εv) − f(u − εv))/(2ε) for random
        /// u (up to 8 % strain) and v on a clamped 2 × 1 × 1 mesh. ε = 1e-6 of the box size: truncation ~1e-12, round-off
        /// ~1e-16/1e-6 relative to |f|; tolerance 1e-7 |K v|∞.
        /// </summary>
        [TestCaseSource(nameof(Laws))]
        public void Fem_TangentIsFiniteDifferenceOfForces(FemMaterialLaw law)
        {
            FemReferenceModel model = CantileverReference.Model(0.4, 0.2, 0.2, 1e6, 0.3, 1000, 1, law);
            int dofs = model.Mesh.DofCount, n = model.FreeCount;
            var random = new System.Random(7);
            var u = new double[dofs];
            var v = new double[dofs];
            foreach (int d in model.FreeDofs)
            {
                u[d] = 0.016 * (2 * random.NextDouble() - 1);
                v[d] = 2 * random.NextDouble() - 1;
            }
            FemCsrMatrix k = model.NewMatrix();
            var f = new double[dofs];
            model.InternalForce(u, f, k);
            var kv = new double[n];
            k.Multiply(model.Gather(v), kv);
            const double eps = 1e-6 * 0.4;
            var up = new double[dofs];
            var um = new double[dofs];
            var fp = new double[dofs];
            var fm = new double[dofs];
            for (int d = 0; d < dofs; d++)
            {
                up[d] = u[d] + eps * v[d];
                um[d] = u[d] - eps * v[d];
            }
            model.InternalForce(up, fp, null);
            model.InternalForce(um, fm, null);
            double worst = 0, scale = 0;
            for (int r = 0; r < n; r++)
            {
                int d = model.FreeDofs[r];
                worst = Math.Max(worst, Math.Abs((fp[d] - fm[d]) / (2 * eps) - kv[r]));
                scale = Math.Max(scale, Math.Abs(kv[r]));
            }
            Assert.That(worst, Is.LessThan(1e-7 * scale));
            // Symmetry of K (hyperelastic): every stored entry equals its transpose to round-off.
            double asym = 0, kMax = 0;
            for (int r = 0; r < n; r++)
                for (int q = k.RowStart[r]; q < k.RowStart[r + 1]; q++)
                {
                    asym = Math.Max(asym, Math.Abs(k.Values[q] - k.Get(k.Columns[q], r)));
                    kMax = Math.Max(kMax, Math.Abs(k.Values[q]));
                }
            Assert.That(asym, Is.LessThan(1e-13 * kMax));
        }

        /// <summary>
        /// Small load (δ/L = 1.5·10⁻³, geometric nonlinearity ~(δ/L)² negligible), L = 1, h = w = 0.1, ν = 0.3: the
        /// self-weight tip deflection at resolution 2 is Euler–Bernoulli's qL⁴/(8EI) to within the Timoshenko shear
        /// term 0.8(1 + ν)(h/L)² = 1.04 %, which the clamp's restraint of the Poisson contraction partly cancels (measured:
        /// −0.18 % at resolution 2, +0.14 % extrapolated).
        /// </summary>
        [Test]
        public void Cantilever_SmallLoadMatchesEulerBernoulliWithinShearCorrection()
        {
            const double length = 1, height = 0.1, width = 0.1, e = 1e9, nu = 0.3, rho = 1000, g = 9.81;
            CantileverStaticResult r = CantileverReference.StaticTipDeflection(length, height, width, e, nu, rho, g, 2);
            double eb = EulerBernoulli.TipDeflectionUnderSelfWeight(rho * g * height * width, length, e, width * height * height * height / 12);
            Assert.IsTrue(r.Solve.Converged);
            Assert.That(Math.Abs(r.TipDeflection / eb - 1), Is.LessThan(EulerBernoulli.ShearCorrectionRatio(height, length, nu)));
        }

        /// <summary>
        /// Mesh convergence of the tip deflection (L = 0.5, h = w = 0.1, resolutions 1, 2, 3): observed order ≥ 1.5 (Q2
        /// smooth-solution order is higher; the clamped edge's corner singularity limits it, measured 1.84 here and 1.6 for
        /// L = 1 at resolutions 2, 3, 4), and the finest
        /// value within 0.5 % of the extrapolated one.
        /// </summary>
        [Test]
        public void Cantilever_TipDeflectionConvergesAtOrderAboveOneAndHalf()
        {
            MeshConvergenceResult c = CantileverReference.TipDeflectionConvergence(0.5, 0.1, 0.1, 1e8, 0.3, 1000, 9.81, new[] { 1, 2, 3 });
            TestContext.WriteLine($"tip deflections {string.Join(", ", c.Values)}; order {c.Estimate.Order}, extrapolated {c.Estimate.Extrapolated}, error {c.Estimate.ErrorEstimate}");
            Assert.That(c.Estimate.Order, Is.GreaterThanOrEqualTo(1.5));
            Assert.That(Math.Abs(c.Values[2] / c.Estimate.Extrapolated - 1), Is.LessThan(5e-3));
        }

        /// <summary>
        /// First bending frequency (L = 1, h = w = 0.1, resolution 2, at rest, consistent mass) against Euler–Bernoulli's
        /// f₁ = 1.8751²/(2π) √(EI/(ρAL⁴)): the 3-D beam is softened by shear and rotary inertia, terms of order (h/L)²
        /// (the shear ratio 0.8(1 + ν)(h/L)² = 1.04 % bounds them here; measured −0.18 %).
        /// </summary>
        [Test]
        public void Cantilever_FirstFrequencyMatchesEulerBernoulli()
        {
            const double length = 1, height = 0.1, width = 0.1, e = 1e7, nu = 0.3, rho = 1000;
            CantileverFrequencyResult r = CantileverReference.FirstFrequency(length, height, width, e, nu, rho, 2);
            double eb = EulerBernoulli.FirstFrequency(length, e, width * height * height * height / 12, rho, width * height);
            Assert.That(Math.Abs(r.Frequency / eb - 1), Is.LessThan(EulerBernoulli.ShearCorrectionRatio(height, length, nu)));
        }

        /// <summary>
        /// CSM3 at resolution 2 (35 × 2 quadratic elements, plane strain), h = 5 ms, 3 s (three periods): tip u_y mean and
        /// amplitude within 5 % and frequency within 3 % of Turek–Hron's −63.607 ± 65.160 mm at 1.0995 Hz, and u_x mean and
        /// amplitude within 5 % of −14.305 ± 14.305 mm. The margins cover the straight clamp and this resolution (finer
        /// meshes and steps: see the report of <see cref="Csm3Reference"/>).
        /// </summary>
        [Test]
        public void Csm3_MatchesTurekHronWithinFewPercent()
        {
            Csm3Result r = Csm3Reference.Run(2, 0.005, 3);
            TestContext.WriteLine($"uy {r.UyMean} ± {r.UyAmplitude} at {r.UyFrequency} Hz; ux {r.UxMean} ± {r.UxAmplitude}; {r.Seconds} s");
            Assert.IsTrue(r.Converged);
            Assert.That(r.UyMean / Csm3Reference.PublishedUyMean, Is.EqualTo(1).Within(0.05));
            Assert.That(r.UyAmplitude / Csm3Reference.PublishedUyAmplitude, Is.EqualTo(1).Within(0.05));
            Assert.That(r.UyFrequency / Csm3Reference.PublishedUyFrequency, Is.EqualTo(1).Within(0.03));
            Assert.That(r.UxMean / Csm3Reference.PublishedUxMean, Is.EqualTo(1).Within(0.05));
            Assert.That(r.UxAmplitude / Csm3Reference.PublishedUxAmplitude, Is.EqualTo(1).Within(0.05));
        }

        /// <summary>
        /// Newmark average acceleration conserves the total energy ½vᵀMv + W(u) − f_extᵀu of a linear problem (the CSM3
        /// beam 100× stiffer, δ/L ~ 10⁻³: the nonlinearity is ~10⁻⁶ of the motion; measured drift 2·10⁻⁸ of the peak kinetic
        /// energy, bound 10⁻⁶), and for the large-deflection beam its energy error falls at second order in h (measured
        /// 4.9·10⁻⁵ → 1.1·10⁻⁵ for h = 5 → 2.5 ms; asserted: at least a factor 3).
        /// </summary>
        [Test]
        public void Newmark_ConservesEnergyWhenLinearAndToSecondOrderWhenNot()
        {
            Assert.That(EnergyDrift(1.4e8, 0.001, 400), Is.LessThan(1e-6));
            double coarse = EnergyDrift(Csm3Reference.YoungModulus, 0.005, 200);
            double fine = EnergyDrift(Csm3Reference.YoungModulus, 0.0025, 400);
            Assert.That(fine, Is.LessThan(coarse / 3));
        }

        /// <summary>Largest |E(t) − E(0)| over the run, relative to the peak kinetic energy (9 × 1 quadratic elements).</summary>
        static double EnergyDrift(double youngModulus, double timeStep, int steps)
        {
            FemBoxMesh mesh = FemBoxMesh.Rectangle(Csm3Reference.Length, Csm3Reference.Height, 9, 1);
            var fixedDofs = new bool[mesh.DofCount];
            for (int j = 0; j < mesh.NodesY; j++)
                fixedDofs[mesh.Node(0, j, 0) * 2] = fixedDofs[mesh.Node(0, j, 0) * 2 + 1] = true;
            var model = new FemReferenceModel(mesh, new FemMaterial(FemMaterialLaw.StVenantKirchhoff, youngModulus, Csm3Reference.PoissonRatio),
                Csm3Reference.Density, fixedDofs);
            var integrator = new FemNewmark(model, model.BodyForce(new[] { 0, -Csm3Reference.Gravity }), timeStep);
            (double k0, double w0, double p0) = integrator.Energies();
            double total0 = k0 + w0 + p0, peak = 0, worst = 0;
            for (int s = 0; s < steps; s++)
            {
                Assert.IsTrue(integrator.Step().Converged);
                (double k, double w, double p) = integrator.Energies();
                peak = Math.Max(peak, k);
                worst = Math.Max(worst, Math.Abs(k + w + p - total0));
            }
            return worst / peak;
        }

        /// <summary>
        /// Uniaxial Neo-Hookean (both laws): the nominal stress is dΨ/dλ along the curve (central difference, step 1e-5:
        /// truncation ~1e-10 E, round-off 1e-16 Ψ/1e-5), lateral traction is zero, and small stretch gives Young's modulus.
        /// </summary>
        [TestCaseSource(nameof(NeoHookeanLaws))]
        public void UniaxialNeoHookean_StressIsEnergyDerivative(FemMaterialLaw law)
        {
            const double e = 2e5, nu = 0.45, step = 1e-5;
            foreach (double stretch in new[] { 0.5, 0.8, 1.0, 1.3, 2.0 })
            {
                UniaxialResult r = UniaxialNeoHookean.Stress(stretch, e, nu, law);
                double derivative = (UniaxialNeoHookean.Stress(stretch + step, e, nu, law).Energy -
                                     UniaxialNeoHookean.Stress(stretch - step, e, nu, law).Energy) / (2 * step);
                Assert.That(r.NominalStress, Is.EqualTo(derivative).Within(1e-7 * e), $"λ = {stretch}");
                // Lateral traction P₂₂ of the full material, and its energy.
                var m = new FemMaterial(law, e, nu);
                double s = r.LateralStretch;
                var p = new double[9];
                m.Evaluate(new[] { stretch - 1, 0, 0, 0, s - 1, 0, 0, 0, s - 1 }, p, Span<double>.Empty, out double energy);
                Assert.That(p[4], Is.EqualTo(0).Within(1e-9 * e));
                Assert.That(p[0], Is.EqualTo(r.NominalStress).Within(1e-9 * e));
                Assert.That(energy, Is.EqualTo(r.Energy).Within(1e-9 * e));
                Assert.That(r.VolumeRatio, Is.EqualTo(stretch * s * s).Within(1e-15 * r.VolumeRatio));
            }
            // Linear limit: P = E ε + O(ε²), ε = 1e-4.
            Assert.That(UniaxialNeoHookean.Stress(1 + 1e-4, e, nu, law).NominalStress / (e * 1e-4), Is.EqualTo(1).Within(1e-3));
        }

        /// <summary>
        /// The reference's stable law is the package's Neo-Hookean element law: P of <see cref="FemMaterial"/> (float64)
        /// against <see cref="SoftBodyDynamics.Solvers.FemElasticity.NeoHookeanStress"/> (float32, λ_snh = λ + μ) at finite
        /// strains, one in 50 % compression. The float32 stress cancels μF against λ(J − α) cof F, terms of size ≤ λ'|cof F|
        /// ~ 5E at these strains, so its round-off is ~1e-6 of 5E; bound 1e-5 E.
        /// </summary>
        [Test]
        public void StableNeoHookean_IsThePackagesNeoHookeanStress()
        {
            const double e = 1e4, nu = 0.45;
            var m = new FemMaterial(FemMaterialLaw.StableNeoHookean, e, nu);
            float mu = (float)m.Mu, lambda = SoftBodyDynamics.Solvers.FemElasticity.NeoHookeanLambda((float)m.Mu, (float)m.Lambda);
            double[][] strains =
            {
                new[] { 0.2, -0.1, 0.05, 0.15, -0.25, 0.1, -0.05, 0.08, 0.3 },
                new[] { 0.34, 0, 0, 0, -0.5, 0, 0, 0, 0.34 },
            };
            foreach (double[] h in strains)
            {
                var p = new double[9];
                m.Evaluate(h, p, Span<double>.Empty, out _);
                var f = new Unity.Mathematics.float3x3(
                    (float)(1 + h[0]), (float)h[1], (float)h[2],
                    (float)h[3], (float)(1 + h[4]), (float)h[5],
                    (float)h[6], (float)h[7], (float)(1 + h[8]));
                Unity.Mathematics.float3x3 q = SoftBodyDynamics.Solvers.FemElasticity.NeoHookeanStress(f, mu, lambda);
                for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    Assert.That(q[j][i], Is.EqualTo(p[3 * i + j]).Within(1e-5 * e), $"P[{i},{j}]");
            }
        }
    }
}
