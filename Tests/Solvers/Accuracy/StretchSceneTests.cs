using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The stretch scene of the method study: its float64 reference (the hanging rubber bar) and one method measured against it.</summary>
    public class StretchSceneTests
    {
        /// <summary>Q2 elements across the section of the tests' reference (the study extrapolates 1, 2, 3).</summary>
        const int TestResolution = 2;

        /// <summary>
        /// Bound on the discretisation error of the Q2 reference at 2 elements across, relative: Q2 approaches from below (too stiff)
        /// and the study's run measured it 0.75–0.9 % below the Richardson value of 1, 2, 3 elements (observed order ≈ 1.5, limited
        /// by the clamp's edge singularity).
        /// </summary>
        const double ReferenceDiscretisation = 0.015;

        static double[] s_Reference;

        /// <summary>The reference bar's extension (m) at the scene's three loads, 2 Q2 elements across, computed once for the tests (a few s).</summary>
        static double[] Reference()
        {
            if (s_Reference != null)
                return s_Reference;
            ElasticMaterial m = StretchScene.Material;
            var g = new double[StretchScene.Loads.Length];
            for (int k = 0; k < g.Length; k++)
                g[k] = StretchScene.Gravity * StretchScene.Loads[k];
            HangingBarResult r = HangingBarReference.Extensions(StretchScene.Length, StretchScene.Thickness, m.YoungsModulus, m.PoissonRatio,
                m.Density, g, TestResolution);
            Assert.IsTrue(r.Converged);
            TestContext.WriteLine($"reference at {TestResolution} across: {string.Join(", ", r.Extensions)} m, {r.NewtonIterations} Newton iterations");
            return s_Reference = r.Extensions;
        }

        /// <summary>
        /// The closed form of the uniform-section extension, [(λ_max − 1) P_max − Ψ(λ_max)]/(ρg), is the integral it replaces,
        /// ∫₀ᴸ (λ(ρg(L − X)) − 1) dX, evaluated by composite Simpson on 200 intervals (λ(P) is smooth: the rule's error is ~1e-10
        /// relative; the bisection's 1e-15): they agree to 1e-8 at every load of the scene.
        /// </summary>
        [Test]
        public void UniformSectionExtension_IsTheIntegralOfTheStretch()
        {
            ElasticMaterial m = StretchScene.Material;
            double e = m.YoungsModulus, nu = m.PoissonRatio, rho = m.Density, l = StretchScene.Length;
            foreach (double load in StretchScene.Loads)
            {
                double g = StretchScene.Gravity * load;
                const int n = 200;
                double sum = 0;
                for (int i = 0; i <= n; i++)
                {
                    double x = l * i / n;
                    double w = i == 0 || i == n ? 1 : i % 2 == 1 ? 4 : 2;
                    sum += w * (HangingBarReference.StretchAtNominalStress(rho * g * (l - x), e, nu) - 1);
                }
                double integral = sum * l / n / 3;
                Assert.That(HangingBarReference.UniformSectionExtension(l, e, nu, rho, g) / integral, Is.EqualTo(1).Within(1e-8));
            }
        }

        /// <summary>
        /// Small load (2 g: strain at the clamp ε_max = ρgL/E = 0.86 %): the reference's extension is the linear bar's ρgL²/(2E)
        /// within the stated bounds: above it by at most the material nonlinearity (the Neo-Hookean bar softens in tension,
        /// δ/δ_lin − 1 ≈ (2/3) ε_max, bounded here by ε_max), below it by at most the clamp's end effect
        /// (<see cref="HangingBarReference.EndEffectBound"/>, 4.4 %) plus the 2-element discretisation (1.5 %). Measured −2.0 %.
        /// </summary>
        [Test]
        public void HangingBarReference_SmallLoadMatchesTheLinearBar()
        {
            ElasticMaterial m = StretchScene.Material;
            double g = StretchScene.Gravity * StretchScene.Loads[0];
            double linear = HangingBarReference.LinearExtension(StretchScene.Length, m.YoungsModulus, m.Density, g);
            double strain = m.Density * g * StretchScene.Length / m.YoungsModulus;
            double endEffect = HangingBarReference.EndEffectBound(StretchScene.Length, StretchScene.Thickness, m.YoungsModulus, m.PoissonRatio,
                m.Density, g);
            double ratio = Reference()[0] / linear - 1;
            TestContext.WriteLine($"δ/δ_lin − 1 = {ratio}; bounds −{endEffect + ReferenceDiscretisation} … +{strain}");
            Assert.That(ratio, Is.LessThan(strain));
            Assert.That(ratio, Is.GreaterThan(-(endEffect + ReferenceDiscretisation)));
        }

        /// <summary>
        /// At every load the clamped bar is shorter than the uniform-section Neo-Hookean curve (its clamp keeps the section from
        /// contracting, a stiffer support), by less than the Saint-Venant estimate of that end effect
        /// (<see cref="HangingBarReference.EndEffectBound"/>: 4.4, 4.7, 5.1 % at 2, 30, 80 g) plus the 2-element discretisation
        /// (1.5 %, the same sign). Measured 2.6, 2.8, 3.0 % at 2 elements across (1.8, 2.0, 2.2 % extrapolated).
        /// </summary>
        [Test]
        public void HangingBarReference_MatchesTheUniformSectionCurveWithinTheEndEffect()
        {
            ElasticMaterial m = StretchScene.Material;
            double[] reference = Reference();
            for (int k = 0; k < reference.Length; k++)
            {
                double g = StretchScene.Gravity * StretchScene.Loads[k];
                double uniform = HangingBarReference.UniformSectionExtension(StretchScene.Length, m.YoungsModulus, m.PoissonRatio, m.Density, g);
                double bound = HangingBarReference.EndEffectBound(StretchScene.Length, StretchScene.Thickness, m.YoungsModulus, m.PoissonRatio,
                    m.Density, g);
                double deficit = 1 - reference[k] / uniform;
                TestContext.WriteLine($"{StretchScene.Loads[k]} g: uniform {uniform} m, deficit {deficit}, bound {bound}");
                Assert.That(deficit, Is.GreaterThan(0));
                Assert.That(deficit, Is.LessThan(bound + ReferenceDiscretisation));
            }
        }

        /// <summary>
        /// Co-rotational FEM (implicit Euler, 1 cell across: 36 particles) measured by the scene. Its law is linear in the
        /// stretch: for F = diag(λ, s, s) with free sides, P = R(2με + λ_L tr(ε) I), ε = sym(RᵀF) − I, gives s − 1 = −ν(λ − 1) and
        /// P₁₁ = E(λ − 1) exactly, so its uniform-section bar extends as the linear bar, ρgL²/(2E), at any load. Against the
        /// Neo-Hookean reference its curve must bend away by the laws' ratio, (1 + e_large)/(1 + e_small) =
        /// (δ_lin/δ_uniform)_large / (δ_lin/δ_uniform)_small = 0.808 (the tetrahedra's discretisation error, which a linear law
        /// would make independent of the load, cancels in the ratio), a Neo-Hookean law would give 1. What remains is the change
        /// of the two bars' clamp end effects with the load (finite rotations of the tapering clamp region): the reference's grows
        /// by 0.5 % from the small to the large load (<see cref="HangingBarReference_MatchesTheUniformSectionCurveWithinTheEndEffect"/>),
        /// and one cell across spreads the clamp's restraint over a whole cell instead of the continuum's ~h/4.2, about 4× as far,
        /// so ~4 × 0.5 % = 2 % for the tetrahedra: the ratio is asserted within 4 % of the law's (measured −2.4 % against the
        /// 2-element reference; in the study's run, against the extrapolated one, −2.6, −0.9, −0.5, −0.3 % at 1, 2, 3, 4 cells across),
        /// six times tighter than the gap to a Neo-Hookean curve (+24 %).
        /// Metrics are finite, no resets.
        /// </summary>
        [Test]
        public void FemCoRotational_StretchCurveIsTheLinearLaw()
        {
            var scene = new StretchScene();
            MethodBodySetup setup = scene.SetupAt(1);
            ElasticMaterial m = setup.Material;
            double[] reference = Reference();
            var targets = new StretchTargets { Extensions = reference };
            IReadOnlyList<Metric> metrics = scene.Measure(setup,
                s => new FemMethodBody(s, FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, 1, 2000, 1e-5f), targets);
            var values = new Dictionary<string, double>();
            foreach (Metric metric in metrics)
            {
                Assert.IsTrue(double.IsFinite(metric.Value), metric.Name);
                values[metric.Name] = metric.Value;
                TestContext.WriteLine($"{metric.Name} = {metric.Value}");
            }
            Assert.AreEqual(0, values[StudyScene.Resets]);
            int last = StretchScene.Loads.Length - 1;
            double Law(int k)
            {
                double g = StretchScene.Gravity * StretchScene.Loads[k];
                return HangingBarReference.LinearExtension(StretchScene.Length, m.YoungsModulus, m.Density, g)
                       / HangingBarReference.UniformSectionExtension(StretchScene.Length, m.YoungsModulus, m.PoissonRatio, m.Density, g);
            }
            double predicted = Law(last) / Law(0);
            double measured = (1 + values[StretchScene.LevelError(last)]) / (1 + values[StretchScene.LevelError(0)]);
            TestContext.WriteLine($"curve ratio {measured}, linear law {predicted}");
            Assert.That(measured / predicted, Is.EqualTo(1).Within(0.04));
        }
    }
}
