using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Particles of different bodies kept apart (<see cref="BodyContacts"/>).</summary>
    public class BodyContactsTests
    {
        const float Spacing = 0.02f, Radius = 0.5f * Spacing;

        /// <summary>
        /// A 5³ shape-matching cube 10 cm wide, 1000 kg/m³, particle radius half the spacing (faces meet flush), at 30 Hz: at
        /// the default 9 Hz the lower cube (one cluster) flattens under the falling one and the pair topples.
        /// </summary>
        static ShapeMatchingInstance Cube(float3 centre)
        {
            var model = LatticeBody.Create(new int3(5), Spacing, 5, 1f);
            var p = ShapeMatchingParameters.Default;
            p.Body.ParticleRadius = Radius;
            p.Frequency = 30f;
            return new ShapeMatchingInstance(model, p, centre, quaternion.identity);
        }

        /// <summary>
        /// A jelly cube (30 Hz) dropped from 1 cm onto another resting on the floor, a spacing's half off centre. Bodies step
        /// substep by substep with the contacts after each. After 8 s the upper rests on the lower: its lowest particle above
        /// the lower's highest (the layers not interleaved), its centre over the lower's top face, both centres still (drift
        /// under 1 mm/s over the last second); the deepest overlap any substep leaves over the last 7 s is the bound,
        /// 0.1 particle radius. Without the contacts the
        /// upper falls through.
        /// </summary>
        [Test]
        public void TwoCubesDroppedOnEachOther_ComeToRestStacked()
        {
            var floor = new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };
            var lower = Cube(new float3(0f, 0.05f, 0f));
            for (int f = 0; f < 120; f++)
                lower.Step(1f / 60f, floor);
            float top = float.MinValue;
            foreach (float3 x in lower.Positions)
                top = math.max(top, x.y);
            var upper = Cube(new float3(0.01f, top + 0.05f + 0.01f, 0f));
            var pile = new ShapeMatchingContacts(lower, upper);
            BodyContactReport report = default;
            float worst = 0f;
            float3 upperBefore = default, lowerBefore = default;
            for (int f = 0; f < 480; f++)
            {
                report = pile.Step(1f / 60f, floor, out float after);
                if (f >= 60)
                    worst = math.max(worst, after);
                if (f == 419)
                {
                    upperBefore = upper.Status.Center;
                    lowerBefore = lower.Status.Center;
                }
            }
            float lowestUpper = float.MaxValue, highestLower = float.MinValue;
            foreach (float3 x in upper.Positions)
                lowestUpper = math.min(lowestUpper, x.y);
            foreach (float3 x in lower.Positions)
                highestLower = math.max(highestLower, x.y);
            float3 offset = upper.Status.Center - lower.Status.Center;
            TestContext.Progress.WriteLine($"worst overlap {worst} m, gap {lowestUpper - highestLower} m, offset {offset}, drift {math.distance(upper.Status.Center, upperBefore)} {math.distance(lower.Status.Center, lowerBefore)} m/s, " +
                $"centre speeds {CentreSpeed(upper)} {CentreSpeed(lower)}, rms {RmsSpeed(upper)} {RmsSpeed(lower)} m/s");
            Assert.That(report.Pairs, Is.GreaterThan(0), "the cubes touch");
            Assert.That(lowestUpper, Is.GreaterThan(highestLower), "the upper's lowest layer above the lower's highest");
            Assert.That(math.abs(offset.x) < 0.05f && math.abs(offset.z) < 0.05f, $"upper centre over the lower's top face: {offset}");
            Assert.That(worst, Is.LessThanOrEqualTo(0.1f * Radius), "overlap after the contacts over the last 7 s");
            // At rest as wholes: the centres drift less than 1 mm/s over the last second.
            Assert.That(math.distance(upper.Status.Center, upperBefore), Is.LessThan(1e-3f), "upper centre's drift over the last second");
            Assert.That(math.distance(lower.Status.Center, lowerBefore), Is.LessThan(1e-3f), "lower centre's drift over the last second");
        }

        /// <summary>Speed (m/s) of the body's centre of mass (its particles' masses are equal).</summary>
        static float CentreSpeed(ShapeMatchingInstance b)
        {
            float3 sum = float3.zero;
            foreach (float3 v in b.Velocities)
                sum += v;
            return math.length(sum / b.Velocities.Length);
        }

        /// <summary>Root-mean-square particle speed (m/s).</summary>
        static float RmsSpeed(ShapeMatchingInstance b)
        {
            float sum = 0f;
            foreach (float3 v in b.Velocities)
                sum += math.lengthsq(v);
            return math.sqrt(sum / b.Velocities.Length);
        }

        static float MaxSpeed(ShapeMatchingInstance b)
        {
            float s = 0f;
            foreach (float3 v in b.Velocities)
                s = math.max(s, math.length(v));
            return s;
        }

        /// <summary>Two interpenetrating 3³ blocks of unequal particle masses, approaching and sliding, and a pinned particle.</summary>
        static (float3[] x, float3[] v, float[] w, float[] r, int[] body) Blocks()
        {
            int n = 2 * 27 + 1;
            var x = new float3[n];
            var v = new float3[n];
            var w = new float[n];
            var r = new float[n];
            var body = new int[n];
            int k = 0;
            for (int b = 0; b < 2; b++)
            for (int i = 0; i < 27; i++, k++)
            {
                var cell = new float3(i % 3, i / 3 % 3, i / 9);
                x[k] = Spacing * cell + (b == 0 ? float3.zero : new float3(2.6f * Spacing, 0.3f * Spacing, 0.1f * Spacing));
                v[k] = b == 0 ? new float3(0.5f, 0.1f, 0f) : new float3(-0.4f, 0f, 0.2f);
                w[k] = b == 0 ? 2f : 0.5f;
                r[k] = Radius;
                body[k] = b;
            }
            // A pinned particle of a third body, clear of the blocks (a pin takes momentum; Resolve_PinnedParticle_… pins it in contact).
            x[k] = new float3(8f * Spacing, 0f, 0f);
            v[k] = float3.zero;
            w[k] = 0f;
            r[k] = Radius;
            body[k] = 2;
            return (x, v, w, r, body);
        }

        static BodyContactReport Resolve(float3[] x, float3[] v, float[] w, float[] r, int[] body, int iterations)
        {
            var settings = BodyContactSettings.Default;
            settings.Iterations = iterations;
            return BodyContacts.Resolve(new BodyContactParticles(x, v, w, r, body), settings, 0f,
                new int[BodyContacts.TableSize(x.Length) + 1], new int[x.Length], new int[x.Length]);
        }

        /// <summary>
        /// Every push and impulse is a pair with weights wᵢ, wⱼ, so Σ m·x and Σ m·v of the free particles keep their values to
        /// float32 round-off (a few ulp of the sums, 1e-6 of their scale here) while the overlap falls with the sweeps
        /// and the approach between touching particles of different bodies is gone after one (no pair approaches after it
        /// that did not at its start, to round-off); the pinned particle stays put.
        /// </summary>
        [Test]
        public void Resolve_KeepsMomentumAndCentreOfMass_AndSeparatesWithSweeps()
        {
            var (x, v, w, r, body) = Blocks();
            Vector3d p0 = Momentum(v, w), c0 = Moment(x, w);
            BodyContactReport first = Resolve(x, v, w, r, body, 1);
            Assert.That(first.Pairs, Is.GreaterThan(10));
            Assert.That(first.MaxOverlapAfter, Is.LessThan(first.MaxOverlapBefore));
            Assert.That((Momentum(v, w) - p0).Length, Is.LessThan(1e-6 * 27 * 2.5), "momentum");
            Assert.That((Moment(x, w) - c0).Length, Is.LessThan(1e-6 * 27 * 0.5), "centre of mass");
            var (x2, v2, w2, r2, body2) = Blocks();
            BodyContactReport many = Resolve(x2, v2, w2, r2, body2, 32);
            Assert.That(many.MaxOverlapAfter, Is.LessThanOrEqualTo(first.MaxOverlapAfter), "more sweeps, no more overlap");
            Assert.That(many.MaxOverlapAfter, Is.LessThan(1e-3f * Radius), "the sweeps part the blocks");
            for (int i = 0; i < x2.Length; i++)
            for (int j = i + 1; j < x2.Length; j++)
                if (body2[i] != body2[j] && math.distance(x2[i], x2[j]) < 2f * Radius * 1.001f)
                    Assert.That(math.dot(v2[i] - v2[j], math.normalize(x2[i] - x2[j])), Is.GreaterThan(-1e-5f), $"pair {i} {j} still approaching");
        }

        [Test]
        public void Resolve_LeavesParticlesOfOneBodyAndNonFinitePositionsAlone()
        {
            var (x, v, w, r, body) = Blocks();
            for (int i = 0; i < body.Length; i++)
                body[i] = 0;
            x[3] = new float3(float.NaN);
            var x0 = (float3[])x.Clone();
            var v0 = (float3[])v.Clone();
            BodyContactReport report = Resolve(x, v, w, r, body, 4);
            Assert.AreEqual(0, report.Pairs);
            Assert.AreEqual(x0[0], x[0]);
            Assert.AreEqual(v0[40], v[40]);
            Assert.IsTrue(math.all(math.isnan(x[3])), "a NaN particle is not touched (and spreads nowhere)");
            for (int i = 0; i < x.Length; i++)
                if (i != 3)
                    Assert.IsTrue(math.all(math.isfinite(x[i])) && math.all(math.isfinite(v[i])), $"particle {i}");
        }

        [Test]
        public void Resolve_PinnedParticle_StaysAndPushesTheOtherOutWhole()
        {
            var x = new[] { float3.zero, new float3(0.5f * Radius, 0f, 0f) };
            var v = new[] { float3.zero, new float3(-1f, 0f, 0f) };
            var w = new[] { 0f, 1f };
            var r = new[] { Radius, Radius };
            var body = new[] { 0, 1 };
            Resolve(x, v, w, r, body, 1);
            Assert.AreEqual(float3.zero, x[0]);
            Assert.AreEqual(float3.zero, v[0]);
            Assert.AreEqual(2f * Radius, x[1].x, 1e-6f * Radius, "pushed out by the whole overlap");
            Assert.AreEqual(0f, v[1].x, 1e-6f, "its approach removed");
        }

        [Test]
        public void Resolve_WithTooShortScratch_SaysSoAndChangesNothing()
        {
            var (x, v, w, r, body) = Blocks();
            var x0 = (float3[])x.Clone();
            var report = BodyContacts.Resolve(new BodyContactParticles(x, v, w, r, body), BodyContactSettings.Default, 1f / 240f,
                new int[BodyContacts.TableSize(x.Length) + 1], new int[x.Length - 1], new int[x.Length]);
            Assert.IsTrue(report.ScratchTooSmall);
            Assert.AreEqual(x0, x);
        }

        static Vector3d Momentum(float3[] v, float[] w)
        {
            var sum = new Vector3d();
            for (int i = 0; i < v.Length; i++)
                if (w[i] > 0f)
                    sum = sum + (Vector3d)(v[i] / w[i]);
            return sum;
        }

        static Vector3d Moment(float3[] x, float[] w)
        {
            var sum = new Vector3d();
            for (int i = 0; i < x.Length; i++)
                if (w[i] > 0f)
                    sum = sum + (Vector3d)(x[i] / w[i]);
            return sum;
        }
    }
}
