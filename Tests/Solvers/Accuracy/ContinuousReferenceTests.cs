using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The float64 reference (<see cref="ShapeMatchingContinuousReference"/>) is the model the solver discretises, and it
    /// is converged: the accuracy suite's errors are the solver's, not the reference's.
    /// </summary>
    public class ContinuousReferenceTests
    {
        internal static readonly object[] Families =
        {
            new object[] { ShapeMatchingMode.Rigid, ShapeMatchingClusterLayout.Single },
            new object[] { ShapeMatchingMode.Linear, ShapeMatchingClusterLayout.Single },
            new object[] { ShapeMatchingMode.Quadratic, ShapeMatchingClusterLayout.Single },
            new object[] { ShapeMatchingMode.Rigid, ShapeMatchingClusterLayout.Overlapping },
            new object[] { ShapeMatchingMode.Linear, ShapeMatchingClusterLayout.Overlapping },
            new object[] { ShapeMatchingMode.Quadratic, ShapeMatchingClusterLayout.Overlapping },
        };

        /// <summary>The convergence suite's released body of a mode and layout.</summary>
        internal static ConvergenceRelease Release(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout)
        {
            const int edge = ConvergenceStudy.Edge;
            const float size = ConvergenceStudy.BodySize;
            ShapeMatchingModelData model = ShapeMatchingBenchmarkBody.Lattice(edge, size, layout, mode);
            ShapeMatchingParameters p = ShapeMatchingBenchmarkBody.Parameters(mode, 1, float3.zero, ShapeMatchingBenchmarkBody.ParticleRadius(edge, size));
            return new ConvergenceRelease(model, p, ShapeMatchingBenchmarkBody.Spacing(edge, size), ConvergenceStudy.Seed);
        }

        /// <summary>
        /// Same model: at the deformed start, the reference's float64 goals and the solver's float32 goals
        /// (<see cref="ClusterGoals.Compute"/>, rotation from a cold start) agree to float32 accuracy. Bound: each goal is a
        /// weighted sum over the n members of a cluster (centre and A_pq: ≤ n·u relative each, u = 2⁻²⁴), times T, whose
        /// rotation stops at 10⁻⁶ rad (<see cref="RotationExtraction.DefaultTolerance"/>) and whose linear or quadratic part
        /// carries the rounding of the float32 A_qq⁻¹ times its condition number; all relative to the extent X of |x|:
        /// |Δg| ≤ (2n·u·(1 + cond) + 10⁻⁶)·X. The quadratic goals include their volume treatment, so a change of it in
        /// one of the two places fails here.
        /// </summary>
        [TestCaseSource(nameof(Families))]
        public void ReferenceGoals_EqualSolverGoals(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout)
        {
            ConvergenceRelease release = Release(mode, layout);
            ShapeMatchingModelData model = release.Model;
            var body = new ShapeMatchingInstance(model, release.Parameters, float3.zero, quaternion.identity);
            release.Start.CopyTo(body.Positions, 0);
            ClusterGoals.Compute(model.AsModel(), release.Parameters.Sanitized(), body.State, body.Positions, 0f);
            float3[] solverGoals = body.State.Goals.ToArray();

            var reference = new ShapeMatchingContinuousReference(model, release.Parameters);
            reference.SetState(release.Start, new float3[release.Start.Length], float3.zero);
            var goals = new Vector3d[release.Start.Length];
            reference.Goals(reference.X, goals);

            double extent = 0, worst = 0;
            foreach (float3 x in release.Start)
                extent = Math.Max(extent, math.cmax(math.abs(x)));
            for (int i = 0; i < goals.Length; i++)
                worst = Math.Max(worst, ((Vector3d)solverGoals[i] - goals[i]).Length);
            int members = 0;
            double condition = 1;
            for (int c = 0; c < model.ClusterCount; c++)
            {
                members = Math.Max(members, model.ClusterOffsets[c + 1] - model.ClusterOffsets[c]);
                if (mode == ShapeMatchingMode.Quadratic)
                    condition = Math.Max(condition, QuadraticCondition(model, c));
            }
            double bound = (2 * members * AccuracyTolerances.Unit * (1 + condition) + RotationExtraction.DefaultTolerance) * extent;
            TestContext.WriteLine($"max |g_solver − g_ref| = {worst:E2} m, bound {bound:E2} m (n = {members}, cond = {condition:F1})");
            Assert.That(worst, Is.LessThanOrEqualTo(bound));
            // The deformation is large enough that the goals are far from the positions (the test compares something).
            double pull = 0;
            for (int i = 0; i < goals.Length; i++)
                pull = Math.Max(pull, (goals[i] - (Vector3d)release.Start[i]).Length);
            Assert.That(pull, Is.GreaterThan(1000 * bound));
        }

        static double QuadraticCondition(ShapeMatchingModelData model, int c)
        {
            int start = model.ClusterOffsets[c], count = model.ClusterOffsets[c + 1] - start;
            var blocks = new float3x3[QuadraticShapeMatching.BlocksPerCluster];
            ClusterRestData rest = model.ClusterRest[c];
            QuadraticShapeMatching.ComputeRestInverse(model.RestPositions, new ReadOnlySpan<int>(model.ClusterParticles, start, count),
                new ReadOnlySpan<float>(model.ClusterWeights, start, count), rest.RestCenter, float3x3.identity, rest.LengthScale,
                blocks, out double condition, out _, out _);
            return condition;
        }

        /// <summary>
        /// Converged reference (Richardson): halving the RK4 step changes the trajectory by d(K) (RMS over particles and
        /// frames, over the size). For a 4th-order method d(K)/d(2K) → 16, so the observed order log₂ of it must be ≥ 3.5
        /// (the quadratic goals pass positions through float32, ≈ 10⁻⁸ of a cluster, which has not mattered at these d).
        /// The change at the suite's step (<see cref="ConvergenceStudy.ReferenceChange"/>, between
        /// <see cref="ConvergenceStudy.ReferenceStepsPerFrame"/> and twice as many steps per frame) must be below 10⁻³ of the
        /// solver's smallest error (32 substeps), so the reference's error (≈ d/15) is negligible in every error the suite reports.
        /// </summary>
        [TestCaseSource(nameof(Families))]
        public void Reference_IsConverged(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout)
        {
            ConvergenceStudy study = ConvergenceStudy.For(mode, layout);
            ConvergenceRelease release = study.Release;
            int k = ConvergenceStudy.ReferenceStepsPerFrame;
            Vector3d[][] coarse = release.ReferenceTrajectory(k / 2);
            double d1 = release.Error(coarse, study.CoarseReference), d2 = study.ReferenceChange;
            double smallestSolverError = study.Error(32);
            TestContext.WriteLine($"d({k / 2}) = {d1:E2}, d({k}) = {d2:E2}, order {Math.Log(d1 / d2, 2):F2}; solver error at 32 substeps {smallestSolverError:E2}");
            Assert.That(d2, Is.LessThanOrEqualTo(1e-3 * smallestSolverError));
            Assert.That(Math.Log(d1 / d2, 2), Is.GreaterThanOrEqualTo(3.5));
        }

        /// <summary>
        /// The reference integrates what it says: in the fully resisted mode of the rigid body (<see cref="FullyResistedMode"/>)
        /// every particle must follow the damped oscillator's closed form y(t) = y₀e^{−ζωt}(cos ω_d t + ζω/ω_d sin ω_d t) to
        /// RK4 accuracy, and not move along y or z at all (below 10⁻¹² m, float64 round-off of 0.25 m coordinates). RK4's
        /// phase error is (ωh)⁵/120 per step, ωt·(ωh)⁴/120 after a time t, on an amplitude e^{−ζωt}: the largest error,
        /// at t = 1/(ζω), is (ωh)⁴/(120·ζ·e) (1.8·10⁻⁸ at ωh = 0.029, 32 steps per 1/60 s frame); twice that is allowed.
        /// </summary>
        [Test]
        public void Reference_FollowsTheOscillatorInAFullyResistedMode()
        {
            ConvergenceRelease release = Release(ShapeMatchingMode.Rigid, ShapeMatchingClusterLayout.Single);
            ShapeMatchingModelData model = release.Model;
            double[] s = FullyResistedMode.Find(model, ShapeMatchingMode.Rigid);
            // The model's own rest positions: the reference's goals of them are exactly themselves (a float32 placement
            // would round them by up to half an ulp, which the goals would then pull back).
            float3[] rest = model.RestPositions;
            const double amplitude = 0.01;
            var reference = new ShapeMatchingContinuousReference(model, release.Parameters);
            reference.SetState(rest, new float3[rest.Length], float3.zero);
            // Displaced in float64: a float32 start would round each displacement by ~ulp(x) off the mode.
            for (int i = 0; i < rest.Length; i++)
                reference.X[i] = reference.X[i] + new Vector3d(amplitude * s[i], 0, 0);
            double omega = reference.AngularFrequency, zeta = release.Parameters.DampingRatio;
            double damped = omega * Math.Sqrt(1 - zeta * zeta);
            double worst = 0, across = 0;
            for (int frame = 1; frame <= 60; frame++)
            {
                reference.Advance(1.0 / 60, 32);
                double t = reference.Time;
                double expected = Math.Exp(-zeta * omega * t) * (Math.Cos(damped * t) + zeta * omega / damped * Math.Sin(damped * t));
                for (int i = 0; i < rest.Length; i++)
                {
                    if (s[i] == 0)
                        continue;
                    double y = (reference.X[i].X - rest[i].x) / (amplitude * s[i]);
                    worst = Math.Max(worst, Math.Abs(y - expected));
                    across = Math.Max(across, Math.Abs(reference.X[i].Y - rest[i].y) + Math.Abs(reference.X[i].Z - rest[i].z));
                }
            }
            double wh = omega / 60 / 32;
            Assert.That(worst, Is.LessThanOrEqualTo(2 * Math.Pow(wh, 4) / (120 * zeta * Math.E)));
            Assert.That(across, Is.LessThanOrEqualTo(1e-12));
        }
    }
}
