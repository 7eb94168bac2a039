using System;
using NUnit.Framework;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.MathematicsStandIn
{
    /// <summary>
    /// float3x3 and quaternion in the stand-in against double-precision evaluations of their definitions:
    /// the matrix product, determinant and inverse; the conversions between rotation matrices and unit
    /// quaternions (including the sign Unity's quaternion(float3x3) picks); the Hamilton product, inverse,
    /// conjugate, rotation and normalization of quaternions. Tolerances are a few float32 ulps of the
    /// magnitudes involved.
    /// </summary>
    public class MatrixQuaternionConformanceTests
    {
        const int k_Cases = 500;

        static float3x3 F(double[,] m) => Reference.ToFloat(m);
        static float3 F(double[] v) => new float3((float)v[0], (float)v[1], (float)v[2]);
        static quaternion Q(double[] q) => new quaternion((float)q[0], (float)q[1], (float)q[2], (float)q[3]);

        [Test]
        public void Mul_MatrixMatrix_And_MatrixVector_AreTheProducts()
        {
            var rng = new System.Random(1);
            for (int c = 0; c < k_Cases; c++)
            {
                double[,] a = Reference.RandomMatrix(rng), b = Reference.RandomMatrix(rng);
                double[] v = Reference.RandomVector(rng);
                Reference.AreClose(Reference.Multiply(a, b), math.mul(F(a), F(b)), 4e-6, $"case {c}: mul(a, b)");
                Reference.AreClose(Reference.Multiply(a, v), math.mul(F(a), F(v)), 4e-6, $"case {c}: mul(a, v)");
            }
        }

        [Test]
        public void Constructor_TakesRowMajorArguments_AndStoresColumns()
        {
            var m = new float3x3(1f, 2f, 3f, 4f, 5f, 6f, 7f, 8f, 9f);
            Assert.That(m.c0, Is.EqualTo(new float3(1f, 4f, 7f)));
            Assert.That(m.c1, Is.EqualTo(new float3(2f, 5f, 8f)));
            Assert.That(m.c2, Is.EqualTo(new float3(3f, 6f, 9f)));
            Assert.That(math.transpose(m).c0, Is.EqualTo(new float3(1f, 2f, 3f)));
            Assert.That(math.mul(m, new float3(1f, 0f, 0f)), Is.EqualTo(m.c0), "mul(m, e0) is the first column");
        }

        [Test]
        public void Determinant_And_Inverse_MatchCofactors()
        {
            var rng = new System.Random(2);
            for (int c = 0; c < k_Cases; c++)
            {
                double[,] a = Reference.RandomMatrix(rng);
                float3x3 f = F(a);
                Assert.That(math.determinant(f), Is.EqualTo(Reference.Determinant(a)).Within(1e-5), $"case {c}: det");
                // |det| ≥ 0.5 and entries ≤ 2: the inverse's entries stay below 16, its float error below ~1e-5.
                Reference.AreClose(Reference.Inverse(a), math.inverse(f), 2e-5, $"case {c}: inverse");
            }
            Assert.That(math.determinant(float3x3.identity), Is.EqualTo(1f));
            Assert.That(math.inverse(float3x3.identity), Is.EqualTo(float3x3.identity));
        }

        [Test]
        public void Float3x3OfQuaternion_IsTheRotationMatrix()
        {
            var rng = new System.Random(3);
            for (int c = 0; c < k_Cases; c++)
            {
                double[] q = Reference.RandomRotation(rng);
                Reference.AreClose(Reference.RotationMatrix(q), new float3x3(Q(q)), 1e-6, $"case {c}");
                Reference.AreClose(Reference.RotationMatrix(q), math.float3x3(Q(q)), 1e-6, $"case {c} (math.float3x3)");
            }
            Assert.That(new float3x3(quaternion.identity), Is.EqualTo(float3x3.identity), "identity, exactly");
        }

        [Test]
        public void QuaternionOfFloat3x3_IsTheRotation_WithUnitysSign()
        {
            var rng = new System.Random(4);
            for (int c = 0; c < 4 * k_Cases; c++)
            {
                float3x3 m = F(Reference.RotationMatrix(Reference.RandomRotation(rng)));
                double[] expected = Reference.QuaternionOf(m);
                Reference.AreClose(expected, new quaternion(m), 1e-6, $"case {c}");
                Reference.AreClose(expected, math.quaternion(m), 1e-6, $"case {c} (math.quaternion)");
            }
        }

        [Test]
        public void QuaternionOfFloat3x3_CoversEveryLaneChoice()
        {
            // One rotation per branch of Unity's lane selection: which of w, x, y, z comes out positive.
            var cases = new (quaternion rotation, int positive)[]
            {
                (quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.3f), 3),                         // m00 ≥ 0, m11 + m22 ≥ 0 → w
                (quaternion.AxisAngle(new float3(1f, 0f, 0f), 2.8f), 0),                         // m00 ≥ 0, m11 + m22 < 0 → x
                (quaternion.AxisAngle(new float3(0f, 1f, 0f), 2.8f), 1),                         // m00 < 0, m11 − m22 ≥ 0 → y
                (quaternion.AxisAngle(new float3(0f, 0f, 1f), 2.8f), 2),                         // m00 < 0, m11 − m22 < 0 → z
            };
            foreach (var (rotation, positive) in cases)
            {
                foreach (float sign in new[] { 1f, -1f })
                {
                    // q and −q give the same matrix; the result must not depend on which one built it.
                    var q = new quaternion(sign * rotation.value);
                    quaternion back = new quaternion(new float3x3(q));
                    double[] expected = Reference.QuaternionOf(new float3x3(q));
                    Assert.That(expected[positive], Is.GreaterThan(0.5), $"lane {positive} is the one Unity keeps positive");
                    Reference.AreClose(expected, back, 1e-6, $"lane {positive}, sign {sign}");
                }
            }
        }

        [Test]
        public void Mul_QuaternionQuaternion_IsTheHamiltonProduct()
        {
            var rng = new System.Random(5);
            for (int c = 0; c < k_Cases; c++)
            {
                double[] a = Reference.RandomRotation(rng), b = Reference.RandomRotation(rng);
                Reference.AreClose(Reference.Hamilton(a, b), math.mul(Q(a), Q(b)), 1e-6, $"case {c}");
                // Apply b, then a.
                double[] v = Reference.RandomVector(rng);
                double[] expected = Reference.Multiply(Reference.RotationMatrix(a), Reference.Multiply(Reference.RotationMatrix(b), v));
                Reference.AreClose(expected, math.rotate(math.mul(Q(a), Q(b)), F(v)), 4e-6, $"case {c}: rotate(mul(a, b), v)");
            }
        }

        [Test]
        public void Rotate_And_MulQuaternionVector_AreRqTimesV()
        {
            var rng = new System.Random(6);
            for (int c = 0; c < k_Cases; c++)
            {
                double[] q = Reference.RandomRotation(rng);
                double[] v = Reference.RandomVector(rng);
                double[] expected = Reference.Multiply(Reference.RotationMatrix(q), v);
                Reference.AreClose(expected, math.rotate(Q(q), F(v)), 4e-6, $"case {c}: rotate");
                Reference.AreClose(expected, math.mul(Q(q), F(v)), 4e-6, $"case {c}: mul(q, v)");
            }
        }

        [Test]
        public void Inverse_Conjugate_Normalize_OfAQuaternion()
        {
            var rng = new System.Random(7);
            for (int c = 0; c < k_Cases; c++)
            {
                double[] unit = Reference.RandomRotation(rng);
                double scale = 0.25 + 3 * rng.NextDouble();
                double[] q = { scale * unit[0], scale * unit[1], scale * unit[2], scale * unit[3] };
                double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
                quaternion f = Q(q);

                Reference.AreClose(new[] { -q[0] / n2, -q[1] / n2, -q[2] / n2, q[3] / n2 }, math.inverse(f), 2e-6 / scale, $"case {c}: inverse");
                Reference.AreClose(new double[] { -f.value.x, -f.value.y, -f.value.z, f.value.w }, math.conjugate(f), 0, $"case {c}: conjugate (exact)");
                double n = Math.Sqrt(n2);
                Reference.AreClose(new[] { q[0] / n, q[1] / n, q[2] / n, q[3] / n }, math.normalize(f), 1e-6, $"case {c}: normalize");
                Reference.AreClose(new[] { q[0] / n, q[1] / n, q[2] / n, q[3] / n }, math.normalizesafe(f), 1e-6, $"case {c}: normalizesafe");
                Assert.That(math.lengthsq(f), Is.EqualTo(n2).Within(1e-5 * n2), $"case {c}: lengthsq");
                Assert.That(math.length(f), Is.EqualTo(n).Within(1e-6 * n), $"case {c}: length");
            }
            Assert.That(math.normalizesafe(new quaternion(0f, 0f, 0f, 0f)), Is.EqualTo(quaternion.identity), "zero → identity");
            Assert.That(math.normalizesafe(new quaternion(1e-30f, 0f, 0f, 0f)), Is.EqualTo(quaternion.identity),
                "|q|² below FLT_MIN_NORMAL → identity");
        }

        [Test]
        public void AxisAngle_IsHalfAngleSinCos()
        {
            var rng = new System.Random(8);
            for (int c = 0; c < k_Cases; c++)
            {
                double[] axis = Reference.RandomVector(rng);
                double len = Math.Sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
                for (int i = 0; i < 3; i++) axis[i] /= len;
                double angle = (rng.NextDouble() * 2 - 1) * 2 * Math.PI;
                float3 a = F(axis);
                float fa = (float)angle;
                double s = Math.Sin(0.5 * fa), co = Math.Cos(0.5 * fa);
                Reference.AreClose(new[] { a.x * s, a.y * s, a.z * s, co }, quaternion.AxisAngle(a, fa), 1e-6, $"case {c}");
            }
        }
    }
}
