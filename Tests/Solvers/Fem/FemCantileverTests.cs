using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>A clamped cantilever under its own weight against Euler–Bernoulli beam theory.</summary>
    public class FemCantileverTests
    {
        /// <summary>
        /// Static tip deflection of a 1 m × 0.1 m × 0.1 m co-rotational beam (E 100 MPa, ν 0.25, ρ 1000 kg/m³), its x = 0 face
        /// pinned, under gravity, at δ/L ≈ 1.5 % (small load: linear theory applies). Euler–Bernoulli: δ = qL⁴/(8EI),
        /// q = ρgA. Linear tetrahedra lock in bending (their strain is constant per element), so the mesh is stiffer than
        /// the beam and approaches it from below as it is refined; the clamped face (which also stops the Poisson
        /// contraction there) and shear deformation (Timoshenko, + ~1 % at L/h = 10) shift it by a few percent.
        /// The static state is found with implicit Euler at large steps: its fixed point is exactly f(x) + Mg = 0.
        /// Measured: 10×1×1 cubes (60 tets) δ/δ_EB ≈ 0.24, 20×2×2 (480 tets) ≈ 0.52–0.53 (±2 % between 3 and 10 steps of 1 s:
        /// the CG tolerance). What is derived: the ratio must grow with resolution and stay below 1 + the clamp and Timoshenko
        /// shifts (1.05). The lower bounds 0.2 and 0.45 are not derived (locking has no closed-form size): they are regression
        /// guards set about 15 % below the measured ratios, so that a change which stiffens the elements fails here.
        /// </summary>
        [Test]
        public void Cantilever_TipSag_ApproachesEulerBernoulli_WithResolution()
        {
            double previous = 0.0;
            var lowerBounds = new[] { 0.2, 0.45 };
            foreach (int n in new[] { 1, 2 })
            {
                double ratio = SagOverEulerBernoulli(n, FemElementOrder.Linear, false);
                Assert.That(ratio, Is.GreaterThan(previous), "refining the mesh softens it toward the beam");
                Assert.That(ratio, Is.LessThan(1.05));
                Assert.That(ratio, Is.GreaterThan(lowerBounds[n - 1]), "bending locking of linear tetrahedra, within its known size");
                previous = ratio;
            }
        }

        /// <summary>
        /// The same beam with one quadratic element across: linear tetrahedra lock to ~0.24 of Euler–Bernoulli's sag there,
        /// quadratic ones bend. Expected: δ_EB (1 + 1 %) for the shear of a beam of L/h = 10 (Timoshenko, 4EI/(κGAL²) with
        /// κ = 5/6), less the clamped face's stiffening; ±5 % holds both and the element's own O(h²) error at one element across.
        /// </summary>
        [Test]
        public void Cantilever_OneQuadraticElementAcross_BendsLikeTheBeam()
        {
            Assert.That(SagOverEulerBernoulli(1, FemElementOrder.Quadratic, true), Is.EqualTo(1.01).Within(0.05));
        }

        /// <summary>Mean static sag of the tip face's mesh nodes over Euler–Bernoulli's, after 10 implicit steps of 1 s.</summary>
        static double SagOverEulerBernoulli(int n, FemElementOrder order, bool restFactor)
        {
            const float length = 1f, side = 0.1f;
            var material = new ElasticMaterial(1e8f, 0.25f, 1000f, 0f);
            double q = 1000.0 * 9.81 * side * side, inertia = side * side * side * side / 12.0;
            double eulerBernoulli = q * length * length * length * length / (8.0 * 1e8 * inertia);
            TetrahedralMesh mesh = FemTestBodies.Box(10 * n, n, n, new float3(length, side, side));
            var pinned = new bool[mesh.NodeCount];
            for (int i = 0; i < pinned.Length; i++)
                pinned[i] = mesh.Positions[i].x == 0f;
            FemModelData data = FemTestBodies.Bake(mesh, material, pinned, order);
            if (restFactor)
                Assert.That(data.BuildRestFactor(1f, 0f), Is.True);
            FemParameters p = FemParameters.Default;
            p.Body.Substeps = 1;
            p.Body.SleepSpeed = 0f;
            p.CgIterations = 2000;
            p.CgTolerance = 1e-6f;
            var body = new FemTestBody(data, p);
            float3 startCenter = body.Status.LocalCenter;
            int cg = 0;
            for (int step = 0; step < 10; step++)
                cg += body.Step(1f).TotalCgIterations;
            double ratio = body.MeanSag(mesh, length, startCenter) / eulerBernoulli;
            TestContext.WriteLine($"{order} {10 * n}×{n}×{n} cubes: tip sag / Euler–Bernoulli {ratio:G4}, CG iterations {cg}");
            return ratio;
        }
    }
}
