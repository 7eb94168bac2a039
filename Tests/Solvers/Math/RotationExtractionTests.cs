using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Rotation extraction (stability plan tests 1 and 2). Tolerances:
    /// <list type="bullet">
    /// <item>det and orthonormality: R is built from a float32 unit quaternion; each entry of RᵀR is
    /// a 3-term dot product of entries carrying ~4 ulp each, so the error is a few tens of ε
    /// (ε = 1.19e-7). We allow 1e-5 (≈ 84 ε).</item>
    /// <item>skew residual ‖skew(A Rᵀ)‖/‖A‖: the iteration stops when |ω| &lt; 1e-6 rad, and |ω| is the
    /// residual divided by tr(RᵀA)/‖A‖ ≤ √3, so a converged result leaves ≤ ~2e-6 plus the float32
    /// round-off of forming A Rᵀ (~1e-6). The plan's 1e-4 bound is used for warm starts capped at
    /// 20 iterations, where slow cases may stop before the tolerance.</item>
    /// <item>objective gap (optimal minus achieved tr(RᵀA), relative to Σσ): quadratic in the angle
    /// error, so 1e-5 corresponds to a few milliradians on the worst-conditioned axis.</item>
    /// </list>
    /// </summary>
    public class RotationExtractionTests
    {
        const double k_DetTolerance = 1e-5;
        const double k_OrthTolerance = 1e-5;
        const double k_SkewTolerance = 1e-4;
        const double k_GapTolerance = 1e-5;

        /// <summary>Rotation angle between two unit quaternions, accurate for small angles (asin of the relative vector part).</summary>
        static float AngleBetween(quaternion a, quaternion b)
        {
            quaternion rel = math.mul(math.conjugate(a), b);
            return 2f * math.asin(math.min(1f, math.length(rel.value.xyz)));
        }

        static IEnumerable<RotationCaseKind> AllKinds() => (RotationCaseKind[])Enum.GetValues(typeof(RotationCaseKind));

        static void AssertProperRotation(in RotationCase c, in quaternion q, string how)
        {
            RotationError e = RotationMetrics.Evaluate(c.A, q);
            Assert.That(e.Finite, Is.True, $"{how}: non-finite rotation for {c}");
            Assert.That(e.Determinant, Is.LessThanOrEqualTo(k_DetTolerance), $"{how}: det for {c}; {e}");
            Assert.That(e.Orthonormality, Is.LessThanOrEqualTo(k_OrthTolerance), $"{how}: orthonormality for {c}; {e}");
        }

        /// <summary>200 seeded cases of one kind: proper, optimal (gap), and for warm starts also stationary (skew).</summary>
        static void AssertKindSolved(RotationCaseKind kind, uint baseSeed, bool warm, int maxIterations)
        {
            for (int i = 0; i < 200; i++)
            {
                RotationCase c = RotationCases.Make(RotationCases.SeedOf(baseSeed, i), kind);
                quaternion q = warm ? c.WarmStart : quaternion.identity;
                RotationExtraction.Extract(c.A, ref q, maxIterations);
                AssertProperRotation(c, q, warm ? "warm" : "cold");
                RotationError e = RotationMetrics.Evaluate(c.A, q);
                if (warm)
                    Assert.That(e.SkewResidual, Is.LessThanOrEqualTo(k_SkewTolerance), $"skew for {c}; {e}");
                Assert.That(e.ObjectiveGap, Is.LessThanOrEqualTo(k_GapTolerance), $"gap for {c}; {e}");
            }
        }

        [Test]
        public void Rotation_IsProperAndOptimal_ForEveryHardCaseKind_WarmStarted([ValueSource(nameof(AllKinds))] RotationCaseKind kind) =>
            AssertKindSolved(kind, 101u, warm: true, RotationExtraction.DefaultMaxIterations);

        [Test]
        public void Rotation_IsProperAndOptimal_ForEveryHardCaseKind_ColdStarted([ValueSource(nameof(AllKinds))] RotationCaseKind kind) =>
            AssertKindSolved(kind, 202u, warm: false, RotationExtraction.DefaultMaxIterations);

        [Test]
        public void Rotation_Fuzz10000SeededMatrices_StaysProperWithBoundedIterations()
        {
            const int count = 10000;
            var iterations = new int[count];
            for (int i = 0; i < count; i++)
            {
                uint seed = RotationCases.SeedOf(20261122u, i);
                RotationCase c = RotationCases.Make(seed);
                quaternion q = c.WarmStart;
                iterations[i] = RotationExtraction.Extract(c.A, ref q);
                RotationError e = RotationMetrics.Evaluate(c.A, q);
                bool ok = e.Finite && e.Determinant <= k_DetTolerance && e.Orthonormality <= k_OrthTolerance
                          && e.SkewResidual <= k_SkewTolerance && e.ObjectiveGap <= k_GapTolerance;
                if (!ok)
                    Assert.Fail($"Fuzz case failed; reproduce with RotationCases.Make({seed}u). {c}; {e}; iterations {iterations[i]}");
            }
            Array.Sort(iterations);
            int p99 = iterations[(int)(0.99 * (count - 1))];
            Assert.That(p99, Is.LessThanOrEqualTo(20), "p99 of iterations with a warm start");
        }

        [Test]
        public void Rotation_RecoversTheRotationOfARotatedStretchedCloud()
        {
            // A = R·S with S symmetric positive definite: the polar rotation is exactly R.
            var rng = new Unity.Mathematics.Random(7u);
            for (int i = 0; i < 100; i++)
            {
                quaternion truth = rng.NextQuaternionRotation();
                float3x3 w = new float3x3(rng.NextQuaternionRotation());
                float3 s = rng.NextFloat3(new float3(0.5f), new float3(2f));
                float3x3 spd = math.mul(w, math.mul(new float3x3(s.x, 0, 0, 0, s.y, 0, 0, 0, s.z), math.transpose(w)));
                float3x3 a = math.mul(new float3x3(truth), spd);
                quaternion q = quaternion.identity;
                RotationExtraction.Extract(a, ref q, maxIterations: 100);
                // Angle between q and truth; float32 quaternion round-off plus the 1e-6 rad stopping
                // tolerance scaled by the conditioning (σmax/σmin ≤ 4) stays below 1e-4 rad.
                float angle = AngleBetween(q, truth);
                Assert.That(angle, Is.LessThan(1e-4f), $"case {i}");
            }
        }

        [Test]
        public void Rotation_LeavesSaddle_ForSymmetricInvertedMatrixFromColdStart()
        {
            // A = diag(-3, 2, 1) is symmetric, so ω = 0 at R = I and the plain iteration stops there
            // with tr(RᵀA) = 0. The optimum is the half turn about y: tr = 3 + 2 − 1 = 4.
            var a = new float3x3(-3f, 0f, 0f, 0f, 2f, 0f, 0f, 0f, 1f);
            quaternion q = quaternion.identity;
            RotationExtraction.Extract(a, ref q);
            float3x3 r = new float3x3(q);
            float trace = math.dot(r.c0, a.c0) + math.dot(r.c1, a.c1) + math.dot(r.c2, a.c2);
            Assert.That(trace, Is.EqualTo(4f).Within(1e-5f));
            Assert.That(math.determinant(r), Is.EqualTo(1f).Within(1e-5f));
        }

        [Test]
        public void Rotation_IsScaleInvariant_From1em4To1e4()
        {
            var rng = new Unity.Mathematics.Random(11u);
            for (int i = 0; i < 50; i++)
            {
                float3x3 a = new float3x3(rng.NextFloat3(-1f, 1f), rng.NextFloat3(-1f, 1f), rng.NextFloat3(-1f, 1f));
                quaternion q1 = quaternion.identity;
                RotationExtraction.Extract(a, ref q1, maxIterations: 100);
                foreach (float scale in new[] { 1e-4f, 1e4f })
                {
                    // A cluster of size L gives A ~ L², from 1e-8 to 1e8.
                    quaternion qs = quaternion.identity;
                    RotationExtraction.Extract(a * (scale * scale), ref qs, maxIterations: 100);
                    float angle = AngleBetween(q1, qs);
                    // Both runs stop at |ω| < 1e-6; the angle to the optimum is then ≲ 1e-6·κ with
                    // κ = tr S / λmin(H) ≤ 7.7 for these 50 seeds (float64 SVD), so the two results differ
                    // by ≲ 1.6e-5 rad to first order; 5e-5 leaves room for second-order terms and round-off.
                    Assert.That(angle, Is.LessThan(5e-5f), $"case {i}, scale {scale}");
                }
            }
        }

        [Test]
        public void Rotation_KeepsWarmStart_ForCoincidentCluster()
        {
            quaternion warm = math.normalize(new quaternion(0.1f, 0.2f, 0.3f, 0.9f));
            quaternion q = warm;
            int iterations = RotationExtraction.Extract(float3x3.zero, ref q);
            Assert.That(iterations, Is.EqualTo(0));
            Assert.That(math.abs(math.dot(q, warm)), Is.EqualTo(1f).Within(1e-6f));
        }

        [Test]
        public void Rotation_KeepsWarmStart_ForNonFiniteInput([Values(float.NaN, float.PositiveInfinity, float.NegativeInfinity)] float bad)
        {
            quaternion warm = math.normalize(new quaternion(0.1f, 0.2f, 0.3f, 0.9f));
            quaternion q = warm;
            var a = float3x3.identity;
            a.c1.z = bad;
            RotationExtraction.Extract(a, ref q);
            Assert.That(math.all(math.isfinite(q.value)), Is.True);
            Assert.That(math.abs(math.dot(q, warm)), Is.EqualTo(1f).Within(1e-6f));
        }

        [Test]
        public void Rotation_ResetsNonFiniteWarmStart_AndStillConverges()
        {
            quaternion q = new quaternion(float.NaN, 0f, 0f, 1f);
            quaternion truth = quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 3f)), 0.7f);
            RotationExtraction.Extract(new float3x3(truth), ref q, maxIterations: 100);
            Assert.That(math.abs(math.dot(q, truth)), Is.EqualTo(1f).Within(1e-6f));
        }

        [Test]
        public void Rotation_ConvergesInOneOrTwoIterations_WhenWarmStartIsExact()
        {
            var rng = new Unity.Mathematics.Random(3u);
            for (int i = 0; i < 100; i++)
            {
                quaternion truth = rng.NextQuaternionRotation();
                quaternion q = truth;
                int it = RotationExtraction.Extract(new float3x3(truth), ref q);
                Assert.That(it, Is.LessThanOrEqualTo(2), $"case {i}");
            }
        }

        [Test]
        public void Rotation_GivesTheSameBits_ForTheSameInput()
        {
            RotationCase c = RotationCases.Make(RotationCases.SeedOf(5u, 0), RotationCaseKind.Mirrored);
            quaternion q1 = c.WarmStart, q2 = c.WarmStart;
            RotationExtraction.Extract(c.A, ref q1);
            RotationExtraction.Extract(c.A, ref q2);
            Assert.That(math.asuint(q1.value.x) == math.asuint(q2.value.x) && math.asuint(q1.value.y) == math.asuint(q2.value.y)
                        && math.asuint(q1.value.z) == math.asuint(q2.value.z) && math.asuint(q1.value.w) == math.asuint(q2.value.w),
                Is.True);
        }
    }
}
