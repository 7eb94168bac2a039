using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The method study's resolution knob: co-rotational FEM's static sag approaches the float64 reference as cells are added across.</summary>
    public class CantileverResolutionTests
    {
        /// <summary>
        /// Tip sag of the study's rubber beam (0.4 × 0.05 × 0.05 m, 8n × n × n cells) under 0.05 g, co-rotational FEM,
        /// implicit Euler at one substep per 1/60 s solved to a relative residual of 1e-5 (as in the study), ζ = 1 for 1 s (critically damped first mode, ω₁ ≥ 9.6 rad/s: residual
        /// ≤ (1 + ω₁t)e^(−ω₁t) ≈ 7e-4 of the sag, and implicit Euler damps it further; far below the errors compared).
        /// </summary>
        static double SmallLoadSag(int across)
        {
            MethodBodySetup setup = CantileverScene.CreateSetup(CantileverScene.CellsAt(across));
            ElasticMaterial m = CantileverScene.Material;
            var body = new FemMethodBody(setup.With(new ElasticMaterial(m.YoungsModulus, m.PoissonRatio, m.Density, 1f)),
                FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, 1, 2000, 1e-5f);
            bool[] tip = StudyBox.NodesAt(setup.Mesh, 0, CantileverScene.Length, 1e-5f);
            var g = new float3(0f, -9.81f * CantileverScene.SmallLoad, 0f);
            double y0 = TipY(body, tip);
            for (int k = 0; k < 60; k++)
                body.Step(StudyScene.Dt, g, ReadOnlySpan<ColliderShape>.Empty);
            Assert.AreEqual(0, body.Resets);
            return y0 - TipY(body, tip);
        }

        static double TipY(IMethodBody body, bool[] tip)
        {
            double y = 0;
            int n = 0;
            for (int i = 0; i < tip.Length; i++)
                if (tip[i])
                {
                    y += body.Positions[i].y;
                    n++;
                }
            return y / n;
        }

        /// <summary>
        /// Linear tetrahedra lock in bending (ν = 0.45): the sag is too small, by less as cells are added across. The
        /// study's run measured errors against the Richardson-extrapolated Q2 reference of 88.1 % at n = 1 and 69.2 % at
        /// n = 2 (too stiff), an observed order p = log₂(e₁/e₂) ≈ 0.35 (locking: far below the order 2 of a smooth
        /// solution); the test asks for e₂ &lt; e₁·2^(−p/2), half the observed order in the exponent (0.78 here), so that it
        /// fails if refinement stops paying while leaving room for round-off and settling (both below 0.1 % of the sag).
        /// </summary>
        [Test]
        public void FemCoRotationalImplicit_SagErrorFallsFromOneToTwoCellsAcross()
        {
            double reference = ReferenceSag();
            double e1 = Math.Abs(SmallLoadSag(1) / reference - 1), e2 = Math.Abs(SmallLoadSag(2) / reference - 1);
            TestContext.WriteLine($"reference {reference} m; error n=1 {e1}, n=2 {e2}, observed order {Math.Log(e1 / e2, 2)}");
            Assert.That(e2, Is.LessThan(e1 * Math.Pow(2, -0.5 * ObservedOrder)));
        }

        /// <summary>
        /// Float64 reference sag (m) of this beam under 0.05 g: <see cref="CantileverReference.StaticTipDeflection"/> with 2
        /// Q2 elements across (the study extrapolates 1, 2, 3; the 2-element value, 8.05 mm, is 2 % below that, and an error of
        /// a few % in the reference would move e₁ and e₂ by ~0.01, below the margin).
        /// </summary>
        static double ReferenceSag()
        {
            ElasticMaterial m = CantileverScene.Material;
            return CantileverReference.StaticTipDeflection(CantileverScene.Length, CantileverScene.Thickness, CantileverScene.Thickness,
                m.YoungsModulus, m.PoissonRatio, m.Density, 9.81 * CantileverScene.SmallLoad, 2).TipDeflection;
        }

        /// <summary>Observed order log₂(e₁/e₂) of the co-rotational sag error between 1 and 2 cells across (measured, see the test).</summary>
        const double ObservedOrder = 0.35;
    }
}
