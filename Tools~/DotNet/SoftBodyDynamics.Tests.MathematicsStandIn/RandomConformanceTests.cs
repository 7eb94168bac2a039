using System;
using NUnit.Framework;
using Unity.Mathematics;
using Random = Unity.Mathematics.Random;

namespace SoftBodyDynamics.Tests.MathematicsStandIn
{
    /// <summary>
    /// Unity.Mathematics.Random in the stand-in against the generator of com.unity.mathematics 1.3.2
    /// (Unity.Mathematics/random.cs): the xorshift32 state sequence of a seed, and every draw the package makes,
    /// recomputed from that sequence with the documented formulas.
    /// </summary>
    public class RandomConformanceTests
    {
        static readonly uint[] s_Seeds = { 1u, 3u, 7u, 11u, 12345u, 0x6E624EB7u, 0xFFFFFFFFu };

        [Test]
        public void Xorshift32_OfOne_IsMarsaglias270369()
        {
            // 1 ^ 1<<13 = 8193; 8193 >> 17 = 0; 8193 ^ 8193<<5 = 270369.
            Assert.That(Reference.Xorshift32(1u), Is.EqualTo(270369u));
            Assert.That(new Random(1u).state, Is.EqualTo(270369u), "the constructor advances the seed once");
        }

        [Test]
        public void StateSequence_OfASeed_IsXorshift32([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var rng = new Random(seed);
            uint[] expected = Reference.States(seed, 1000);
            for (int i = 0; i < expected.Length; i++)
            {
                Assert.That(rng.state, Is.EqualTo(expected[i]), $"state before draw {i}");
                Assert.That(rng.NextUInt(), Is.EqualTo(expected[i] - 1u), $"NextUInt() = state − 1, draw {i}");
            }
        }

        [Test]
        public void InitState_StartsTheSameSequenceAsTheConstructor([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var a = new Random(seed);
            var b = new Random(99u);
            b.InitState(seed);
            Assert.That(b.state, Is.EqualTo(a.state));
            Assert.That(new Random(0x6E624EB7u).state, Is.EqualTo(Reference.Xorshift32(0x6E624EB7u)), "InitState's default seed");
        }

        [Test]
        public void ZeroSeed_Throws_AsInTheEditor()
        {
            Assert.Throws<ArgumentException>(() => new Random(0u));
            var r = new Random(1u);
            Assert.Throws<ArgumentException>(() => r.InitState(0u));
            var unset = default(Random);
            Assert.Throws<ArgumentException>(() => unset.NextFloat(), "a default Random has state 0");
        }

        [Test]
        public void NextFloat_IsTheTop23BitsOfTheState_BitForBit([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var rng = new Random(seed);
            foreach (uint s in Reference.States(seed, 1000))
            {
                float f = rng.NextFloat();
                Assert.That((double)f, Is.EqualTo(Reference.UnitFloat(s)), "exact: a 23-bit fraction is a float");
                Assert.That(f, Is.GreaterThanOrEqualTo(0f).And.LessThan(1f));
            }
        }

        [Test]
        public void NextFloatMinMax_IsNextFloatTimesRangePlusMin([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var rng = new Random(seed);
            foreach (uint s in Reference.States(seed, 200))
            {
                double expected = Reference.UnitFloat(s) * (2.0 - 0.5) + 0.5;
                Assert.That(rng.NextFloat(0.5f, 2f), Is.EqualTo(expected).Within(2.5e-7));
            }
        }

        [Test]
        public void NextFloat3_DrawsXThenYThenZ([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var rng = new Random(seed);
            uint[] s = Reference.States(seed, 9);
            float3 plain = rng.NextFloat3();
            Reference.AreClose(new[] { Reference.UnitFloat(s[0]), Reference.UnitFloat(s[1]), Reference.UnitFloat(s[2]) }, plain, 0, "NextFloat3()");

            float3 max = new float3(2f, 3f, 4f);
            float3 scaled = rng.NextFloat3(max);
            Reference.AreClose(new[] { 2 * Reference.UnitFloat(s[3]), 3 * Reference.UnitFloat(s[4]), 4 * Reference.UnitFloat(s[5]) },
                scaled, 3e-7, "NextFloat3(max) = NextFloat3() * max (one float rounding)");

            float3 min = new float3(-1f, -2f, 0.5f);
            float3 ranged = rng.NextFloat3(min, max);
            double[] expected =
            {
                Reference.UnitFloat(s[6]) * 3.0 - 1.0, Reference.UnitFloat(s[7]) * 5.0 - 2.0, Reference.UnitFloat(s[8]) * 3.5 + 0.5,
            };
            Reference.AreClose(expected, ranged, 1e-6, "NextFloat3(min, max) = NextFloat3() * (max − min) + min");
        }

        [Test]
        public void NextInt_IsTheHigh32BitsOfStateTimesRange([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var rng = new Random(seed);
            foreach (uint s in Reference.States(seed, 500))
            {
                long expected = (long)(((ulong)s * 9ul) >> 32) - 3;
                Assert.That(rng.NextInt(-3, 6), Is.EqualTo(expected));
            }
        }

        [Test]
        public void NextFloat3Direction_IsZAndAngleFromTwoDraws([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var rng = new Random(seed);
            uint[] s = Reference.States(seed, 400);
            for (int i = 0; i < s.Length; i += 2)
            {
                double z = Reference.UnitFloat(s[i]) * 2 - 1;
                double r = Math.Sqrt(Math.Max(1 - z * z, 0));
                double angle = Reference.UnitFloat(s[i + 1]) * 2 * Math.PI;
                float3 d = rng.NextFloat3Direction();
                Reference.AreClose(new[] { Math.Cos(angle) * r, Math.Sin(angle) * r, z }, d, 2e-6, $"direction {i / 2}");
            }
        }

        /// <summary>
        /// Unity: rnd = NextFloat3(float3(2π, 2π, 1)) — the max-only overload, rnd = NextFloat3() · (2π, 2π, 1) —
        /// then q = (√(1−u)·sin θ, √(1−u)·cos θ, √u·sin ρ, √u·cos ρ) with (θ, ρ, u) = rnd, negated when w &lt; 0.
        /// </summary>
        [Test]
        public void NextQuaternionRotation_IsShoemakesFormulaOnThreeDraws([ValueSource(nameof(s_Seeds))] uint seed)
        {
            var rng = new Random(seed);
            uint[] s = Reference.States(seed, 600);
            for (int i = 0; i < s.Length; i += 3)
            {
                double theta = 2 * Math.PI * Reference.UnitFloat(s[i]);
                double rho = 2 * Math.PI * Reference.UnitFloat(s[i + 1]);
                double u = Reference.UnitFloat(s[i + 2]);
                double a = Math.Sqrt(1 - u), b = Math.Sqrt(u);
                double[] q = { a * Math.Sin(theta), a * Math.Cos(theta), b * Math.Sin(rho), b * Math.Cos(rho) };
                if (q[3] < 0)
                    for (int k = 0; k < 4; k++) q[k] = -q[k];

                quaternion actual = rng.NextQuaternionRotation();
                Reference.AreClose(q, actual, 2e-6, $"rotation {i / 3}");
                Assert.That(actual.value.w, Is.GreaterThanOrEqualTo(0f));
            }
        }
    }
}
