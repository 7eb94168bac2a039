using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Linear-mode volume normalisation A / ∛det A (stability plan test 6).</summary>
    public class VolumePreservationTests
    {
        static float3x3 Diag(float x, float y, float z) => new float3x3(x, 0f, 0f, 0f, y, 0f, 0f, 0f, z);

        [Test]
        public void LinearGoal_FallsBackToRigid_ForDegenerateOrInvertedDeterminant([Values(1e-12f, 0f, -0.5f)] float det)
        {
            // diag(det, 1, 1) has exactly that determinant.
            float3x3 aLinear = Diag(det, 1f, 1f);
            float3x3 r = new float3x3(quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.3f));
            float3x3 goal = VolumePreservation.LinearGoalTransform(aLinear, r, 0.5f, out bool fallback);
            Assert.That(fallback, Is.True);
            Assert.That(Finite.All(goal), Is.True);
            Assert.That(goal.Equals(r), Is.True, "the rigid fallback returns R unchanged");
        }

        [Test]
        public void LinearGoal_FallsBackToRigid_ForNonFiniteInput([Values(float.NaN, float.PositiveInfinity)] float bad)
        {
            float3x3 aLinear = Diag(1f, bad, 1f);
            VolumePreservation.LinearGoalTransform(aLinear, float3x3.identity, 1f, out bool fallback);
            Assert.That(fallback, Is.True);
        }

        [Test]
        public void Normalize_GivesUnitDeterminant_AcrossScales([Values(1e-6f, 1e-2f, 1f, 1e2f, 1e6f)] float scale)
        {
            float3x3 a = math.mul(new float3x3(quaternion.AxisAngle(math.normalize(new float3(1f, 1f, 0f)), 1f)),
                Diag(0.5f, 1.5f, 3f)) * scale;
            Assert.That(VolumePreservation.TryNormalize(a, out float3x3 n), Is.True);
            // det of a float32 matrix with entries O(1) carries a few ε of relative error.
            Assert.That(math.determinant(n), Is.EqualTo(1f).Within(1e-5f));
            // Same direction as A: n = A / c for a positive scalar c.
            float c = a.c0.x / n.c0.x;
            Assert.That(c, Is.GreaterThan(0f));
            Assert.That(n.c1.y * c, Is.EqualTo(a.c1.y).Within(math.abs(a.c1.y) * 1e-5f));
        }

        [Test]
        public void LinearGoal_BlendsLinearAndRigid_ByBeta()
        {
            float3x3 aLinear = Diag(1.25f, 0.8f, 1f); // det 1 already; strain ‖Ã − I‖_F ≈ 0.32, below the limit
            float3x3 r = float3x3.identity;
            float3x3 half = VolumePreservation.LinearGoalTransform(aLinear, r, 0.5f, out bool fallback);
            Assert.That(fallback, Is.False);
            Assert.That(half.c0.x, Is.EqualTo(1.125f).Within(1e-6f));
            Assert.That(half.c1.y, Is.EqualTo(0.9f).Within(1e-6f));
            float3x3 rigid = VolumePreservation.LinearGoalTransform(aLinear, r, 0f, out _);
            Assert.That(rigid.Equals(r), Is.True);
        }

        /// <summary>
        /// A cluster squashed to 1e-4 of its height: A / ∛det would ask for a 21-fold in-plane stretch.
        /// The strain handed to the goals is limited to <see cref="VolumePreservation.MaxGoalStrain"/>.
        /// </summary>
        [Test]
        public void LinearGoal_LimitsTheStrainOfASquashedCluster()
        {
            float3x3 squashed = Diag(1f, 1e-4f, 1f);
            float3x3 goal = VolumePreservation.LinearGoalTransform(squashed, float3x3.identity, 1f, out bool fallback);
            Assert.That(fallback, Is.False);
            float3x3 strain = goal - float3x3.identity;
            float norm = math.sqrt(math.lengthsq(strain.c0) + math.lengthsq(strain.c1) + math.lengthsq(strain.c2));
            Assert.That(norm, Is.LessThanOrEqualTo(VolumePreservation.MaxGoalStrain * (1f + 1e-6f)));
        }

        /// <summary>
        /// Just above the determinant floor the strain has faded to nothing, so crossing the floor (where R
        /// takes over) does not make the goals jump: the goal transform is continuous there to within the
        /// fade's slope × the float32 step of det (~1e-7 of the 9e-6 ramp ≈ 1e-2 · 1e-6), asserted < 1e-4.
        /// </summary>
        [Test]
        public void LinearGoal_IsContinuousAtTheFallback()
        {
            float floor = VolumePreservation.DefaultRelativeDeterminantFloor;
            float3x3 above = VolumePreservation.LinearGoalTransform(Diag(1f, floor * 1.0001f, 1f), float3x3.identity, 1f, out bool f1);
            VolumePreservation.LinearGoalTransform(Diag(1f, floor * 0.9999f, 1f), float3x3.identity, 1f, out bool f2);
            Assert.That(f1, Is.False);
            Assert.That(f2, Is.True);
            float3x3 jump = above - float3x3.identity;
            Assert.That(math.cmax(math.abs(jump.c0)) + math.cmax(math.abs(jump.c1)) + math.cmax(math.abs(jump.c2)), Is.LessThan(1e-4f));
        }
    }
}
