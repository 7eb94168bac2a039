using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using static SoftBodyDynamics.Tests.Solvers.DoubleMatrix3;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The linear goal transform T = R + β·fade(d)·limit(Ã − R) (<see cref="VolumePreservation.LinearGoalTransform"/>)
    /// against an oracle written here in float64 from its definition: Ã = A / ∛det A; d = det(A / max|Aᵢⱼ|), the
    /// relative determinant; fade(d) = clamp((d − floor) / (<see cref="VolumePreservation.FadeEnd"/> − floor), 0, 1);
    /// limit(S) = S · min(1, <see cref="VolumePreservation.MaxGoalStrain"/> / ‖S‖_F); and R when d ≤ floor.
    /// Tolerance: the float32 path takes a cube root, a determinant and a handful of 3×3 products of O(1) numbers
    /// (each ≲ 4ε relative, ε = 1.2e-7) and, near the floor, d itself is a difference of O(1) products known to ~1e-7,
    /// which moves fade by 20 × 1e-7: 1e-5 absolute on the O(1) entries of T covers both with a wide margin.
    /// </summary>
    public class ShapeMatchingStrainLimiterTests
    {
        const double k_Tolerance = 1e-5;
        const double k_Floor = VolumePreservation.DefaultRelativeDeterminantFloor;

        static readonly float3x3 s_Rotation = new float3x3(quaternion.AxisAngle(math.normalize(new float3(1f, -2f, 0.5f)), 0.8f));

        /// <summary>A cluster squashed to <paramref name="s"/> of its height (no volume kept), then rotated: A = R diag(1, s, 1).</summary>
        static float3x3 Squashed(float s) => math.mul(s_Rotation, new float3x3(1f, 0f, 0f, 0f, s, 0f, 0f, 0f, 1f));

        static double[,] ToDouble(in float3x3 m) => new double[,]
        {
            { m.c0.x, m.c1.x, m.c2.x },
            { m.c0.y, m.c1.y, m.c2.y },
            { m.c0.z, m.c1.z, m.c2.z },
        };

        static double Norm(double[,] m)
        {
            double s = 0;
            foreach (double x in m)
                s += x * x;
            return Math.Sqrt(s);
        }

        static double RelativeDeterminant(double[,] a)
        {
            double scale = 0;
            foreach (double x in a)
                scale = Math.Max(scale, Math.Abs(x));
            return Det(a) / (scale * scale * scale);
        }

        static double Fade(double d) => Math.Max(0, Math.Min(1, (d - k_Floor) / (VolumePreservation.FadeEnd - k_Floor)));

        /// <summary>Ã − R in float64 (valid for det A &gt; 0).</summary>
        static double[,] Strain(in float3x3 a, in float3x3 r)
        {
            double[,] ad = ToDouble(a), rd = ToDouble(r);
            double root = Math.Cbrt(Det(ad));
            var s = new double[3, 3];
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                s[i, j] = ad[i, j] / root - rd[i, j];
            return s;
        }

        /// <summary>The oracle: T = R + β·fade(d)·limit(Ã − R), or R at and below the floor.</summary>
        static double[,] Reference(in float3x3 a, in float3x3 r, double beta)
        {
            double[,] rd = ToDouble(r);
            double d = RelativeDeterminant(ToDouble(a));
            if (!(d > k_Floor))
                return rd;
            double[,] s = Strain(a, r);
            double norm = Norm(s);
            double k = beta * Fade(d) * Math.Min(1.0, VolumePreservation.MaxGoalStrain / norm);
            var t = new double[3, 3];
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                t[i, j] = rd[i, j] + k * s[i, j];
            return t;
        }

        static double MaxDifference(in float3x3 t, double[,] reference)
        {
            double[,] td = ToDouble(t);
            double worst = 0;
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                worst = Math.Max(worst, Math.Abs(td[i, j] - reference[i, j]));
            return worst;
        }

        /// <summary>Fade values at given relative determinants, from the formula in float64.</summary>
        [TestCase(-0.5)]
        [TestCase(0.0)]
        [TestCase(1e-6)]
        [TestCase(5e-6)]
        [TestCase(1e-3)]
        [TestCase(0.0125)]
        [TestCase(0.025)]
        [TestCase(0.0375)]
        [TestCase(0.049)]
        [TestCase(0.05)]
        [TestCase(0.2)]
        [TestCase(1.0)]
        public void BetaFade_IsTheLinearRampFromTheFloorToFadeEnd(double d)
        {
            Assert.That(VolumePreservation.BetaFade((float)d), Is.EqualTo(Fade((float)d)).Within(1e-6));
        }

        [Test]
        public void BetaFade_IsZeroAtTheFloorAndOneFromFadeEnd()
        {
            Assert.That(VolumePreservation.BetaFade(VolumePreservation.DefaultRelativeDeterminantFloor), Is.EqualTo(0f));
            Assert.That(VolumePreservation.BetaFade(VolumePreservation.FadeEnd), Is.EqualTo(1f));
            float middle = 0.5f * (VolumePreservation.DefaultRelativeDeterminantFloor + VolumePreservation.FadeEnd);
            Assert.That(VolumePreservation.BetaFade(middle), Is.EqualTo(0.5f).Within(1e-6f));
        }

        /// <summary>
        /// A cluster squashed to a tenth of its height: d = 0.1/max|Aᵢⱼ|³ is above FadeEnd, so fade = 1, and the strain
        /// Ã − R (an in-plane stretch of 10^⅓ and a squash of 10^−⅔) has norm 1.8 &gt; 1: the goal's strain T − R must have
        /// exactly the norm MaxGoalStrain·β and the direction of Ã − R.
        /// </summary>
        [Test]
        public void LinearGoal_LimitsTheStrainToMaxGoalStrainTimesBeta([Values(0.25f, 0.5f, 1f)] float beta)
        {
            float3x3 a = Squashed(0.1f);
            float3x3 t = VolumePreservation.LinearGoalTransform(a, s_Rotation, beta, out bool fallback);
            Assert.That(fallback, Is.False);
            double[,] strain = Strain(a, s_Rotation);
            Assert.That(Norm(strain), Is.GreaterThan(1.5), "the unlimited strain exceeds the bound");
            Assert.That(Fade(RelativeDeterminant(ToDouble(a))), Is.EqualTo(1.0));
            double[,] goal = ToDouble(t), r = ToDouble(s_Rotation);
            var limited = new double[3, 3];
            double dot = 0;
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
            {
                limited[i, j] = goal[i, j] - r[i, j];
                dot += limited[i, j] * strain[i, j];
            }
            double norm = Norm(limited);
            Assert.That(norm, Is.EqualTo(VolumePreservation.MaxGoalStrain * beta).Within(k_Tolerance), "‖T − R‖_F");
            Assert.That(dot / (norm * Norm(strain)), Is.EqualTo(1.0).Within(1e-6), "T − R parallel to Ã − R");
            Assert.That(MaxDifference(t, Reference(a, s_Rotation, beta)), Is.LessThanOrEqualTo(k_Tolerance));
        }

        /// <summary>
        /// Across the whole range, from unsquashed through the fade to below the floor and inverted, T matches the oracle;
        /// inside the fade the limited strain has norm MaxGoalStrain·β·fade(d).
        /// </summary>
        [Test]
        public void LinearGoal_MatchesTheOracleAcrossTheFade(
            [Values(1f, 0.8f, 0.3f, 0.1f, 0.06f, 0.04f, 0.02f, 0.01f, 1e-3f, 1e-4f, 1e-5f, 2e-6f, 5e-7f, 0f, -0.3f)] float s)
        {
            const float beta = 0.9f;
            float3x3 a = Squashed(s);
            float3x3 t = VolumePreservation.LinearGoalTransform(a, s_Rotation, beta, out bool fallback);
            double d = RelativeDeterminant(ToDouble(a));
            Assert.That(fallback, Is.EqualTo(!(d > k_Floor)), $"fallback at d = {d}");
            Assert.That(MaxDifference(t, Reference(a, s_Rotation, beta)), Is.LessThanOrEqualTo(k_Tolerance), $"d = {d}");
            if (d > k_Floor && d < VolumePreservation.FadeEnd)
            {
                double[,] goal = ToDouble(t), r = ToDouble(s_Rotation);
                var strain = new double[3, 3];
                for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    strain[i, j] = goal[i, j] - r[i, j];
                Assert.That(Norm(strain), Is.EqualTo(VolumePreservation.MaxGoalStrain * beta * Fade(d)).Within(k_Tolerance), "‖T − R‖_F");
            }
        }

        /// <summary>
        /// The goal is continuous at both ends of the fade: across d = FadeEnd and d = floor (±1e-4 relative) T changes
        /// by no more than the oracle does plus round-off, and the oracle changes by at most its slope times the step:
        /// |dT/dd| ≤ β(|fade'| + |d limit(Ã − R)/dd|) ≤ β(20 + 2|dÃ/dd| / ‖Ã − R‖); |dÃ/dd| ≤ d^(−4/3) / 3 + 2 d^(−1/3) / 3.
        /// A goal that jumped to R at a threshold would change by β·MaxGoalStrain there.
        /// </summary>
        [Test]
        public void LinearGoal_IsContinuousAtBothEndsOfTheFade([Values(true, false)] bool atFadeEnd)
        {
            const float beta = 1f;
            // A = diag(1, s, 1) up to rotation has max|Aᵢⱼ| = 1 only without the rotation: use the unrotated squash here,
            // so that d = s exactly and the two sides of each threshold are known.
            float end = atFadeEnd ? VolumePreservation.FadeEnd : VolumePreservation.DefaultRelativeDeterminantFloor;
            float below = end * (1f - 1e-4f), above = end * (1f + 1e-4f);
            float3x3 aBelow = new float3x3(1f, 0f, 0f, 0f, below, 0f, 0f, 0f, 1f);
            float3x3 aAbove = new float3x3(1f, 0f, 0f, 0f, above, 0f, 0f, 0f, 1f);
            float3x3 tBelow = VolumePreservation.LinearGoalTransform(aBelow, float3x3.identity, beta, out _);
            float3x3 tAbove = VolumePreservation.LinearGoalTransform(aAbove, float3x3.identity, beta, out _);
            double[,] rBelow = Reference(aBelow, float3x3.identity, beta), rAbove = Reference(aAbove, float3x3.identity, beta);
            double referenceJump = 0, jump = 0;
            double[,] tb = ToDouble(tBelow), ta = ToDouble(tAbove);
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
            {
                referenceJump = Math.Max(referenceJump, Math.Abs(rAbove[i, j] - rBelow[i, j]));
                jump = Math.Max(jump, Math.Abs(ta[i, j] - tb[i, j]));
            }
            double step = above - below;
            double strainNorm = Math.Max(Norm(Strain(aBelow, float3x3.identity)), 1.0);
            double slope = beta * (1.0 / (VolumePreservation.FadeEnd - k_Floor)
                                   + 2.0 * (Math.Pow(below, -4.0 / 3.0) / 3.0 + 2.0 * Math.Pow(below, -1.0 / 3.0) / 3.0) / strainNorm);
            Assert.That(referenceJump, Is.LessThanOrEqualTo(slope * step), "the oracle is continuous");
            Assert.That(jump, Is.LessThanOrEqualTo(referenceJump + 2.0 * k_Tolerance), "T follows the oracle across the threshold");
        }

        /// <summary>LimitStrain leaves a strain within the bound untouched and scales a larger one onto it, keeping its direction.</summary>
        [Test]
        public void LimitStrain_KeepsSmallStrainsAndScalesLargeOnesOntoTheBound()
        {
            var rng = new Unity.Mathematics.Random(9u);
            for (int k = 0; k < 200; k++)
            {
                float scale = rng.NextFloat(0.01f, 3f);
                float3x3 s = new float3x3(rng.NextFloat3() - 0.5f, rng.NextFloat3() - 0.5f, rng.NextFloat3() - 0.5f) * scale;
                double norm = Norm(ToDouble(s));
                float3x3 limited = VolumePreservation.LimitStrain(s);
                double[,] ld = ToDouble(limited), sd = ToDouble(s);
                if (norm <= VolumePreservation.MaxGoalStrain * (1 - 1e-6))
                {
                    Assert.That(limited.Equals(s), Is.True, $"norm {norm}: unchanged");
                    continue;
                }
                Assert.That(Norm(ld), Is.EqualTo(VolumePreservation.MaxGoalStrain).Within(1e-6), $"norm {norm}");
                double ratio = VolumePreservation.MaxGoalStrain / norm;
                for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    Assert.That(ld[i, j], Is.EqualTo(sd[i, j] * ratio).Within(1e-6), "same direction");
            }
        }
    }
}
