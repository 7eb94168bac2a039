using System;
using NUnit.Framework;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.MathematicsStandIn
{
    /// <summary>
    /// The reference side of the conformance tests: the documented formulas of com.unity.mathematics 1.3.2,
    /// evaluated independently of the stand-in, in double (or in 64-bit integers for the generator), plus
    /// seeded test inputs and comparisons.
    /// </summary>
    static class Reference
    {
        /// <summary>One xorshift32 step with shifts 13, 17, 5 (Marsaglia 2003), in 64-bit arithmetic masked to 32 bits.</summary>
        public static uint Xorshift32(uint state)
        {
            ulong x = state;
            x ^= (x << 13) & 0xFFFFFFFFul;
            x ^= x >> 17;
            x ^= (x << 5) & 0xFFFFFFFFul;
            return (uint)x;
        }

        /// <summary>The values NextState() hands out after <c>new Random(seed)</c>: seed is advanced once, then each draw returns the state and advances it.</summary>
        public static uint[] States(uint seed, int count)
        {
            var states = new uint[count];
            uint s = Xorshift32(seed);
            for (int i = 0; i < count; i++)
            {
                states[i] = s;
                s = Xorshift32(s);
            }
            return states;
        }

        /// <summary>NextFloat of a drawn state: its top 23 bits as a fraction of 2²³, exactly (in double).</summary>
        public static double UnitFloat(uint state) => (state >> 9) / 8388608.0;

        // ---- double 3-vectors, quaternions (x, y, z, w) and column-major 3×3 matrices m[row, column]

        public static double[] Cross(double[] a, double[] b) =>
            new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };

        public static double[] Hamilton(double[] a, double[] b) => new[]
        {
            a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
            a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
            a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
            a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
        };

        /// <summary>R(q) of a unit quaternion: the standard rotation matrix, m[row, column].</summary>
        public static double[,] RotationMatrix(double[] q)
        {
            double x = q[0], y = q[1], z = q[2], w = q[3];
            return new double[,]
            {
                { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
                { 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
                { 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) },
            };
        }

        public static double[,] Multiply(double[,] a, double[,] b)
        {
            var c = new double[3, 3];
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++)
                    c[i, j] += a[i, k] * b[k, j];
            return c;
        }

        public static double[] Multiply(double[,] a, double[] v)
        {
            var r = new double[3];
            for (int i = 0; i < 3; i++)
                for (int k = 0; k < 3; k++)
                    r[i] += a[i, k] * v[k];
            return r;
        }

        /// <summary>Determinant by cofactor expansion along the first row.</summary>
        public static double Determinant(double[,] m) =>
            m[0, 0] * (m[1, 1] * m[2, 2] - m[1, 2] * m[2, 1])
            - m[0, 1] * (m[1, 0] * m[2, 2] - m[1, 2] * m[2, 0])
            + m[0, 2] * (m[1, 0] * m[2, 1] - m[1, 1] * m[2, 0]);

        /// <summary>Inverse as the transposed cofactor matrix over the determinant.</summary>
        public static double[,] Inverse(double[,] m)
        {
            double d = Determinant(m);
            var r = new double[3, 3];
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
            {
                int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
                r[i, j] = (m[i1, j1] * m[i2, j2] - m[i1, j2] * m[i2, j1]) / d;
            }
            return r;
        }

        /// <summary>
        /// The unit quaternion of a rotation matrix (Shepperd's method: divide by the largest of 4w², 4x², 4y², 4z²),
        /// with the sign Unity's quaternion(float3x3) gives, derived from its lane selection: when m00 has its sign
        /// bit clear, w ≥ 0 if m11 + m22 does too, else x ≥ 0; when m00 has it set, y ≥ 0 if m11 − m22 has it
        /// clear, else z ≥ 0. The sums are the float32 sums Unity's branch-free code tests.
        /// </summary>
        public static double[] QuaternionOf(float3x3 f)
        {
            double[,] m = ToDouble(f);
            double tw = 1 + m[0, 0] + m[1, 1] + m[2, 2];
            double tx = 1 + m[0, 0] - m[1, 1] - m[2, 2];
            double ty = 1 - m[0, 0] + m[1, 1] - m[2, 2];
            double tz = 1 - m[0, 0] - m[1, 1] + m[2, 2];
            double[] q;
            if (tw >= tx && tw >= ty && tw >= tz)
            {
                double s = 2 * Math.Sqrt(tw);
                q = new[] { (m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, s / 4 };
            }
            else if (tx >= ty && tx >= tz)
            {
                double s = 2 * Math.Sqrt(tx);
                q = new[] { s / 4, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s };
            }
            else if (ty >= tz)
            {
                double s = 2 * Math.Sqrt(ty);
                q = new[] { (m[0, 1] + m[1, 0]) / s, s / 4, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s };
            }
            else
            {
                double s = 2 * Math.Sqrt(tz);
                q = new[] { (m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, s / 4, (m[1, 0] - m[0, 1]) / s };
            }
            double n = Math.Sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            for (int i = 0; i < 4; i++) q[i] /= n;

            int positive;
            if (!SignBit(f.c0.x))
                positive = SignBit(f.c1.y + f.c2.z) ? 0 : 3;
            else
                positive = SignBit(f.c1.y - f.c2.z) ? 2 : 1;
            if (q[positive] < 0)
                for (int i = 0; i < 4; i++) q[i] = -q[i];
            return q;
        }

        static bool SignBit(float x) => (BitConverter.SingleToInt32Bits(x) & int.MinValue) != 0;

        public static double[,] ToDouble(float3x3 f) => new double[,]
        {
            { f.c0.x, f.c1.x, f.c2.x },
            { f.c0.y, f.c1.y, f.c2.y },
            { f.c0.z, f.c1.z, f.c2.z },
        };

        public static double[] ToDouble(float3 v) => new double[] { v.x, v.y, v.z };

        public static double[] ToDouble(quaternion q) => new double[] { q.value.x, q.value.y, q.value.z, q.value.w };

        public static float3x3 ToFloat(double[,] m) => new float3x3(
            (float)m[0, 0], (float)m[0, 1], (float)m[0, 2],
            (float)m[1, 0], (float)m[1, 1], (float)m[1, 2],
            (float)m[2, 0], (float)m[2, 1], (float)m[2, 2]);

        // ---- seeded inputs (System.Random, independent of the stand-in's generator)

        /// <summary>A unit quaternion uniform on the sphere of rotations (normalized Gaussian 4-vector).</summary>
        public static double[] RandomRotation(System.Random rng)
        {
            var q = new double[4];
            double n = 0;
            for (int i = 0; i < 4; i++)
            {
                double u1 = 1.0 - rng.NextDouble(), u2 = rng.NextDouble();
                q[i] = Math.Sqrt(-2 * Math.Log(u1)) * Math.Cos(2 * Math.PI * u2);
                n += q[i] * q[i];
            }
            n = Math.Sqrt(n);
            for (int i = 0; i < 4; i++) q[i] /= n;
            return q;
        }

        /// <summary>A 3×3 matrix with entries uniform in [−2, 2], rejected until |det| ≥ 0.5 (well conditioned enough for float).</summary>
        public static double[,] RandomMatrix(System.Random rng)
        {
            while (true)
            {
                var m = new double[3, 3];
                for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    m[i, j] = (double)(float)(4 * rng.NextDouble() - 2);
                if (Math.Abs(Determinant(m)) >= 0.5) return m;
            }
        }

        public static double[] RandomVector(System.Random rng) => new double[]
        {
            (float)(4 * rng.NextDouble() - 2), (float)(4 * rng.NextDouble() - 2), (float)(4 * rng.NextDouble() - 2),
        };

        // ---- comparisons

        public static void AreClose(double[] expected, float3 actual, double tolerance, string what)
        {
            Assert.That(actual.x, Is.EqualTo(expected[0]).Within(tolerance), what + ".x");
            Assert.That(actual.y, Is.EqualTo(expected[1]).Within(tolerance), what + ".y");
            Assert.That(actual.z, Is.EqualTo(expected[2]).Within(tolerance), what + ".z");
        }

        public static void AreClose(double[] expected, quaternion actual, double tolerance, string what)
        {
            Assert.That(actual.value.x, Is.EqualTo(expected[0]).Within(tolerance), what + ".x");
            Assert.That(actual.value.y, Is.EqualTo(expected[1]).Within(tolerance), what + ".y");
            Assert.That(actual.value.z, Is.EqualTo(expected[2]).Within(tolerance), what + ".z");
            Assert.That(actual.value.w, Is.EqualTo(expected[3]).Within(tolerance), what + ".w");
        }

        public static void AreClose(double[,] expected, float3x3 actual, double tolerance, string what)
        {
            double[,] a = ToDouble(actual);
            for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                Assert.That(a[i, j], Is.EqualTo(expected[i, j]).Within(tolerance), $"{what}[{i},{j}]");
        }
    }
}
