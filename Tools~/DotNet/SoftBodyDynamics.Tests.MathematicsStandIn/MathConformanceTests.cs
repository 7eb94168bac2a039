using System;
using System.Reflection;
using NUnit.Framework;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.MathematicsStandIn
{
    /// <summary>
    /// The scalar and vector functions of the stand-in's <c>math</c> and the declarations of its vector types,
    /// against com.unity.mathematics 1.3.2: the edge cases Unity defines explicitly (NaN in min/max, sign of
    /// zero in abs, int.MinValue in abs, the FLT_MIN_NORMAL threshold of normalizesafe) and the vector formulas
    /// recomputed in double.
    /// </summary>
    public class MathConformanceTests
    {
        [Test]
        public void Abs_ClearsTheSignBit_AndKeepsIntMinValue()
        {
            Assert.That(math.abs(int.MinValue), Is.EqualTo(int.MinValue), "max(−x, x) wraps instead of throwing");
            Assert.That(math.abs(-5), Is.EqualTo(5));
            Assert.That(BitConverter.SingleToInt32Bits(math.abs(-0f)), Is.EqualTo(0), "−0 → +0");
            Assert.That(math.abs(-2.5f), Is.EqualTo(2.5f));
            Assert.That(float.IsNaN(math.abs(float.NaN)), Is.True);
            Assert.That(math.abs(-2.5), Is.EqualTo(2.5));
            Assert.That(math.abs(float3.zero - new float3(1f, -2f, 3f)), Is.EqualTo(new float3(1f, 2f, 3f)));
        }

        [Test]
        public void MinMax_ReturnTheFirstArgument_WhenTheSecondIsNaN()
        {
            // Unity: min(x, y) = IsNaN(y) || x < y ? x : y.
            Assert.That(math.min(1f, float.NaN), Is.EqualTo(1f));
            Assert.That(math.min(float.NaN, 1f), Is.EqualTo(1f));
            Assert.That(math.max(1f, float.NaN), Is.EqualTo(1f));
            Assert.That(math.max(float.NaN, 1f), Is.EqualTo(1f));
            Assert.That(math.max(2.0, double.NaN), Is.EqualTo(2.0));
            Assert.That(math.clamp(5f, 0f, 1f), Is.EqualTo(1f));
            Assert.That(math.clamp(-5, 0, 3), Is.EqualTo(0));
            Assert.That(math.saturate(-0.5f), Is.EqualTo(0f));
        }

        [Test]
        public void Sign_Lerp_Select_Rcp_Rsqrt()
        {
            Assert.That(math.sign(-3f), Is.EqualTo(-1f));
            Assert.That(math.sign(0f), Is.EqualTo(0f));
            Assert.That(math.sign(float.NaN), Is.EqualTo(0f), "(x > 0 ? 1 : 0) − (x < 0 ? 1 : 0)");
            Assert.That(math.lerp(2f, 6f, 0.25f), Is.EqualTo(3f));
            Assert.That(math.select(1f, 2f, true), Is.EqualTo(2f));
            Assert.That(math.rcp(4f), Is.EqualTo(0.25f));
            Assert.That(math.rsqrt(4f), Is.EqualTo(0.5f));
            Assert.That(math.round(2.5f), Is.EqualTo(2f), "System.Math.Round: halves to even");
            Assert.That(math.floor(-1.5f), Is.EqualTo(-2f));
        }

        [Test]
        public void Sqrt_GivesTheBitsOfUnitysDoubleRoundedFormula()
        {
            // Unity's managed sqrt(float) is (float)System.Math.Sqrt(x); the stand-in's single-precision root must match it
            // bit for bit: every float of a random bit-pattern sweep, subnormals, powers of two, ±0, ∞, NaN and −1.
            var random = new System.Random(7);
            var bits = new byte[4];
            float[] edges = { 0f, -0f, 1f, 2f, 0.5f, float.Epsilon, 1.17549435e-38f, float.MaxValue, float.PositiveInfinity, float.NaN, -1f, 4f };
            for (int n = 0; n < 200000 + edges.Length; n++)
            {
                float x;
                if (n < edges.Length)
                    x = edges[n];
                else
                {
                    random.NextBytes(bits);
                    x = BitConverter.ToSingle(bits, 0);
                }
                float expected = (float)Math.Sqrt(x);
                float actual = math.sqrt(x);
                if (BitConverter.SingleToInt32Bits(actual) != BitConverter.SingleToInt32Bits(expected) && !(float.IsNaN(actual) && float.IsNaN(expected)))
                    Assert.Fail($"sqrt({x:R}) = {actual:R}, Unity's formula gives {expected:R}");
            }
        }

        [Test]
        public void IsFinite_IsNaN()
        {
            Assert.That(math.isfinite(float.MaxValue), Is.True);
            Assert.That(math.isfinite(float.PositiveInfinity), Is.False);
            Assert.That(math.isfinite(float.NaN), Is.False);
            Assert.That(math.isnan(float.NaN), Is.True);
            Assert.That(math.isnan(float.NegativeInfinity), Is.False);
            Assert.That(math.all(math.isfinite(new float3(1f, 2f, 3f))), Is.True);
            Assert.That(math.any(math.isnan(new float3(1f, float.NaN, 3f))), Is.True);
        }

        [Test]
        public void VectorFormulas_MatchDouble()
        {
            var rng = new System.Random(9);
            for (int c = 0; c < 500; c++)
            {
                double[] a = Reference.RandomVector(rng), b = Reference.RandomVector(rng);
                var fa = new float3((float)a[0], (float)a[1], (float)a[2]);
                var fb = new float3((float)b[0], (float)b[1], (float)b[2]);
                double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
                Assert.That(math.dot(fa, fb), Is.EqualTo(dot).Within(4e-6), $"case {c}: dot");
                Reference.AreClose(Reference.Cross(a, b), math.cross(fa, fb), 4e-6, $"case {c}: cross");
                double len = Math.Sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
                Assert.That(math.length(fa), Is.EqualTo(len).Within(1e-6 * Math.Max(1, len)), $"case {c}: length");
                Assert.That(math.lengthsq(fa), Is.EqualTo(len * len).Within(4e-6), $"case {c}: lengthsq");
                double[] d = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
                Assert.That(math.distance(fa, fb), Is.EqualTo(Math.Sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])).Within(4e-6), $"case {c}: distance");
                Reference.AreClose(new[] { a[0] / len, a[1] / len, a[2] / len }, math.normalize(fa), 1e-6, $"case {c}: normalize");
                Reference.AreClose(new[] { a[0] / len, a[1] / len, a[2] / len }, math.normalizesafe(fa), 1e-6, $"case {c}: normalizesafe");
                Assert.That(math.csum(fa), Is.EqualTo(a[0] + a[1] + a[2]).Within(4e-6), $"case {c}: csum");
                Assert.That(math.cmax(fa), Is.EqualTo(Math.Max(a[0], Math.Max(a[1], a[2]))), $"case {c}: cmax");
                Assert.That(math.cmin(fa), Is.EqualTo(Math.Min(a[0], Math.Min(a[1], a[2]))), $"case {c}: cmin");
            }
        }

        [Test]
        public void NormalizeSafe_ReturnsTheDefault_BelowFltMinNormal()
        {
            var fallback = new float3(0f, 1f, 0f);
            Assert.That(math.normalizesafe(float3.zero, fallback), Is.EqualTo(fallback));
            Assert.That(math.normalizesafe(new float3(1e-20f, 0f, 0f), fallback), Is.EqualTo(fallback), "|x|² = 1e-40 < FLT_MIN_NORMAL");
            Assert.That(math.normalizesafe(float3.zero), Is.EqualTo(float3.zero), "default default: zero");
            Assert.That(math.normalizesafe(new float3(0f, 0f, 3f), fallback), Is.EqualTo(new float3(0f, 0f, 1f)));
        }

        [Test]
        public void GetHashCode_IsMathHash_AsInUnity()
        {
            // Unity: (int)math.hash(v), hash(float3 v) = csum(asuint(v) * uint3(0x9B13B92D, 0x4ABF0813, 0x86068063)) + 0xD75513F9.
            var v = new float3(1f, -2f, 0.5f);
            ulong h = ((ulong)Bits(1f) * 0x9B13B92Dul + (ulong)Bits(-2f) * 0x4ABF0813ul + (ulong)Bits(0.5f) * 0x86068063ul + 0xD75513F9ul) & 0xFFFFFFFFul;
            Assert.That(math.hash(v), Is.EqualTo((uint)h));
            Assert.That(v.GetHashCode(), Is.EqualTo((int)(uint)h));
            Assert.That(new float3(1f, -2f, 0.5f).GetHashCode(), Is.EqualTo(v.GetHashCode()), "stable across instances and runs");

            var i = new int3(-1, 2, 3);
            ulong hi = (0xFFFFFFFFul * 0x4C7F6DD1ul + 2ul * 0x4822A3E9ul + 3ul * 0xAAC3C25Dul + 0xD21D0945ul) & 0xFFFFFFFFul;
            Assert.That(i.GetHashCode(), Is.EqualTo((int)(uint)hi));
            Assert.That(quaternion.identity.GetHashCode(), Is.EqualTo(new float4(0f, 0f, 0f, 1f).GetHashCode()), "hash(q) = hash(q.value)");
        }

        static uint Bits(float f) => (uint)BitConverter.SingleToInt32Bits(f);

        [Test]
        public void Float3Indexer_IsByValue_WithAGetterAndASetter()
        {
            // Unity.Mathematics 1.3.2: `unsafe public float this[int index] { get; set; }` (float3x3's returns ref float3).
            PropertyInfo item = typeof(float3).GetProperty("Item");
            Assert.That(item.PropertyType, Is.EqualTo(typeof(float)), "not a ref return");
            Assert.That(item.CanRead && item.CanWrite, Is.True);
            Assert.That(typeof(float3x3).GetProperty("Item").PropertyType, Is.EqualTo(typeof(float3).MakeByRefType()));

            var v = new float3(1f, 2f, 3f);
            v[1] = 5f;
            v[2] += 1f;
            Assert.That(v, Is.EqualTo(new float3(1f, 5f, 4f)));
            Assert.That(v[0], Is.EqualTo(1f));
            Assert.Throws<ArgumentException>(() => { float unused = v[3]; });

            var m = float3x3.identity;
            m[1] = new float3(7f, 8f, 9f);
            m[2].x = 4f;
            Assert.That(m.c1, Is.EqualTo(new float3(7f, 8f, 9f)));
            Assert.That(m.c2.x, Is.EqualTo(4f), "float3x3's indexer is a ref to the column");
        }

        [Test]
        public void Swizzles_ReadAndWrite()
        {
            var v = new float3(1f, 2f, 3f);
            Assert.That(v.yzx, Is.EqualTo(new float3(2f, 3f, 1f)));
            Assert.That(v.zxy, Is.EqualTo(new float3(3f, 1f, 2f)));
            v.xz = new float2(7f, 9f);
            Assert.That(v, Is.EqualTo(new float3(7f, 2f, 9f)));
            v.yzx = new float3(4f, 5f, 6f);
            Assert.That(v, Is.EqualTo(new float3(6f, 4f, 5f)));
        }

        [Test]
        public void IntegerVectorIndexers_ReadAndWriteTheFieldsInOrder_AndRejectOutOfRange()
        {
            var a = new int4(10, 20, 30, 40);
            Assert.That(new[] { a[0], a[1], a[2], a[3] }, Is.EqualTo(new[] { 10, 20, 30, 40 }));
            a[2] = -7;
            Assert.That(a.z, Is.EqualTo(-7), "the setter writes the field of that index");
            Assert.Throws<ArgumentException>(() => { int _ = a[4]; });
            Assert.Throws<ArgumentException>(() => { int _ = a[-1]; });
            var b = new int2(5, 6);
            b[1] = 9;
            Assert.That(new[] { b[0], b[1], b.y }, Is.EqualTo(new[] { 5, 9, 9 }));
            Assert.Throws<ArgumentException>(() => { int _ = b[2]; });
        }
    }
}
