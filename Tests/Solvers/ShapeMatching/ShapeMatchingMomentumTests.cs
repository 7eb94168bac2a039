using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Momentum of free bodies (stability plan #3). Shape matching moves each cluster's particles by
    /// α(gᵢ − xᵢ) with weights wᵢ = mᵢ/nᵢ about the weighted centre, so Σ mᵢ Δxᵢ = 0, and for an exact
    /// polar rotation Σ wᵢ pᵢ × R qᵢ = axial(skew(A_pq Rᵀ)) = 0 (stability-plan §2.1). The solver also
    /// removes the float32 residue of both sums from every pull, so what remains is the round-off of the
    /// velocity increments themselves (a few ulp of |v| per particle and substep, unbiased). The plan's
    /// thresholds are asserted: |ΔP|/Σm|v| ≤ 1e-5 and |ΔL|/|L₀| ≤ 1e-3 over 1000 steps.
    /// </summary>
    public class ShapeMatchingMomentumTests
    {
        static ShapeMatchingInstance SpinningBlob(ShapeMatchingMode mode, int clusterSize, float damping, uint seed)
        {
            var model = LatticeBody.Create(new int3(5, 5, 5), 0.1f, clusterSize, 2f, mode == ShapeMatchingMode.Quadratic);
            var p = ShapeMatchingParameters.Default;
            p.Mode = mode;
            p.Frequency = 16f;
            p.Body.Acceleration = float3.zero;
            p.DampingRatio = damping;
            p.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, p, new float3(0f, 1f, 0f), quaternion.identity);
            var rng = new Random(seed);
            float3 omega = rng.NextFloat3Direction() * 3f;
            float3 drift = rng.NextFloat3Direction() * 0.5f;
            for (int i = 0; i < body.Positions.Length; i++)
            {
                // Deformed start: every particle jittered by up to 20% of the spacing.
                body.Positions[i] += (rng.NextFloat3() - 0.5f) * 0.04f;
                float3 r = body.Positions[i] - new float3(0f, 1f, 0f);
                body.Velocities[i] = drift + math.cross(omega, r) + (rng.NextFloat3() - 0.5f) * 0.2f;
            }
            return body;
        }

        /// <summary>
        /// Free spinning blob in every mode, with one cluster (5) and with overlapping clusters (3), undamped and damped.
        /// The pull and the damping are made free of momentum and angular momentum to round-off (see the class comment), so
        /// L changes only by the rounding of the updates themselves. A substep rounds each velocity update (the pull, the
        /// damping) to ≲ 3ε|vᵢ| and each position update xᵢ + h vᵢ to ≲ ε|xᵢ|, so particle i changes L = Σ mᵢ rᵢ × vᵢ by
        /// at most aᵢ = ε mᵢ |vᵢ| (3|rᵢ| + |xᵢ|), with |xᵢ| taken where the drift carries the body by the end (it moves 8 m
        /// in the 16.7 s). These roundings are unbiased and independent from particle to particle and from substep to
        /// substep, so they add like a random walk: over N substeps |ΔL| ≤ 5√N·√(Σaᵢ²) (five standard deviations). |ΔP| / Σ m|v| ≤ 1e-5 as in the plan: Σ mᵢ Δvᵢ is
        /// projected to zero every substep and only the rounding of the velocities themselves remains.
        /// </summary>
        [TestCase(ShapeMatchingMode.Rigid, 5, 0f, 11u)]
        [TestCase(ShapeMatchingMode.Rigid, 3, 0f, 12u)]
        [TestCase(ShapeMatchingMode.Rigid, 3, 0.5f, 13u)]
        [TestCase(ShapeMatchingMode.Linear, 5, 0f, 14u)]
        [TestCase(ShapeMatchingMode.Linear, 3, 0f, 15u)]
        [TestCase(ShapeMatchingMode.Linear, 3, 0.5f, 16u)]
        [TestCase(ShapeMatchingMode.Quadratic, 5, 0f, 17u)]
        [TestCase(ShapeMatchingMode.Quadratic, 3, 0f, 18u)]
        [TestCase(ShapeMatchingMode.Quadratic, 5, 0.5f, 19u)]
        public void Momentum_IsConservedByFreeSpinningBlob(ShapeMatchingMode mode, int clusterSize, float damping, uint seed)
        {
            ShapeMatchingInstance body = SpinningBlob(mode, clusterSize, damping, seed);
            var masses = body.Model.Masses;
            Vector3d p0 = BodyMeasures.Momentum(body.Velocities, masses);
            double scale = BodyMeasures.MomentumScale(body.Velocities, masses);
            Vector3d l0 = BodyMeasures.AngularMomentum(body.Positions, body.Velocities, masses);
            const int steps = 1000;
            const float dt = 1f / 60f;
            int substeps = ShapeMatchingSolver.SubstepCount(body.Parameters, dt);
            Vector3d c0 = BodyMeasures.Center(body.Positions, masses);
            double travel = (p0.Length / TotalMass(masses)) * steps * dt;
            double perSubstep = 0;
            for (int i = 0; i < body.Positions.Length; i++)
            {
                double r = ((Vector3d)body.Positions[i] - c0).Length;
                double x = ((Vector3d)body.Positions[i]).Length + travel;
                double a = masses[i] * math.length(body.Velocities[i]) * (3.0 * r + x);
                perSubstep += a * a;
            }
            perSubstep = 1.1920929e-7 * System.Math.Sqrt(perSubstep);
            double angularBound = 5.0 * System.Math.Sqrt(steps * substeps) * perSubstep / l0.Length;
            double worstP = 0, worstL = 0;
            for (int step = 0; step < steps; step++)
            {
                ShapeMatchingStepReport report = body.Step(dt);
                Assert.That(report.Reset, Is.False, $"step {step}");
                worstP = System.Math.Max(worstP, (BodyMeasures.Momentum(body.Velocities, masses) - p0).Length / scale);
                worstL = System.Math.Max(worstL,
                    (BodyMeasures.AngularMomentum(body.Positions, body.Velocities, masses) - l0).Length / l0.Length);
            }
            Assert.That(worstP, Is.LessThanOrEqualTo(1e-5), "|ΔP| / Σ m|v|");
            Assert.That(worstL, Is.LessThanOrEqualTo(angularBound), "|ΔL| / |L0|");
        }

        static double TotalMass(float[] masses)
        {
            double m = 0;
            foreach (float x in masses)
                m += x;
            return m;
        }

        [Test]
        public void Momentum_LinearIsConservedInLinearAndQuadraticModes()
        {
            foreach (var mode in new[] { ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic })
            {
                ShapeMatchingInstance body = SpinningBlob(mode, 3, 0f, 21u);
                var masses = body.Model.Masses;
                Vector3d p0 = BodyMeasures.Momentum(body.Velocities, masses);
                double scale = BodyMeasures.MomentumScale(body.Velocities, masses);
                for (int step = 0; step < 1000; step++)
                    body.Step(1f / 60f);
                Assert.That((BodyMeasures.Momentum(body.Velocities, masses) - p0).Length / scale, Is.LessThanOrEqualTo(1e-5), mode.ToString());
            }
        }

        /// <summary>
        /// A stiff (100 Hz) rigid-mode body in free flight, one cluster. Momenta are kept, and the shape stays at
        /// the rest shape up to the continuous model's own centrifugal stretch: a particle at r from the spin axis
        /// needs the pull ω²·δ = Ω²·r, so δ ≤ Ω²R/ω², and the undamped start can overshoot that once more.
        /// </summary>
        [Test]
        public void RigidBodyInFreeFlight_KeepsMomentaAndShape()
        {
            var model = LatticeBody.Create(new int3(4, 3, 2), 0.2f, 8, 1f);
            var p = ShapeMatchingParameters.Default;
            p.Mode = ShapeMatchingMode.Rigid;
            p.Frequency = 100f;
            p.Body.Acceleration = float3.zero;
            p.DampingRatio = 0f;
            p.Body.SleepSpeed = 0f;
            var body = new ShapeMatchingInstance(model, p, float3.zero, quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.3f));
            float3 omega = new float3(1f, 2f, -0.5f); // not a principal axis: the body tumbles
            for (int i = 0; i < body.Positions.Length; i++)
                body.Velocities[i] = new float3(0.3f, 0f, 0f) + math.cross(omega, body.Positions[i]);
            Vector3d p0 = BodyMeasures.Momentum(body.Velocities, model.Masses);
            double scale = BodyMeasures.MomentumScale(body.Velocities, model.Masses);
            Vector3d l0 = BodyMeasures.AngularMomentum(body.Positions, body.Velocities, model.Masses);
            for (int step = 0; step < 1000; step++)
                body.Step(1f / 60f);
            Assert.That((BodyMeasures.Momentum(body.Velocities, model.Masses) - p0).Length / scale, Is.LessThanOrEqualTo(1e-5));
            Assert.That((BodyMeasures.AngularMomentum(body.Positions, body.Velocities, model.Masses) - l0).Length / l0.Length,
                Is.LessThanOrEqualTo(1e-3));
            // The pull must supply each particle's rigid acceleration |Ω × (Ω × r) + Ω̇ × r| ≤ (Ω² + |Ω̇|) R, so the
            // stretch is δ ≤ (Ω² + |Ω̇|) R / ω² (twice that with the undamped overshoot). Torque-free tumbling keeps
            // Ω ≤ |L| / I_min and |Ω̇| = |I⁻¹ (L × Ω)| ≤ |L| Ω / I_min. Plus float32 round-off of O(1) m coordinates
            // after the goal product (a few ulp, ≤ 1e-6 m).
            float3x3 inertia = float3x3.zero;
            Vector3d c = BodyMeasures.Center(body.Positions, model.Masses);
            var center = new float3((float)c.X, (float)c.Y, (float)c.Z);
            for (int i = 0; i < body.Positions.Length; i++)
            {
                float3 r = body.Positions[i] - center;
                inertia += model.Masses[i] * (math.lengthsq(r) * float3x3.identity - new float3x3(r.x * r, r.y * r, r.z * r));
            }
            double inertiaMin = Svd3x3Double.Decompose(inertia).Sigma3;
            double spinMax = l0.Length / inertiaMin;
            double radius = 0.5 * math.length(new float3(0.6f, 0.4f, 0.2f));
            double stretch = 2.0 * spinMax * spinMax * radius / (p.AngularFrequency * (double)p.AngularFrequency);
            Assert.That(BodyMeasures.ShapeError(body.Positions, model.AsModel()), Is.LessThanOrEqualTo(2.0 * stretch + 1e-6));
        }
    }
}
