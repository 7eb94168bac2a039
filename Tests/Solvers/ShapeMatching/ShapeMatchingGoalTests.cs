using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Goal transforms of one cluster. Tolerance: positions are O(1) m and each goal is a 3-term
    /// product of float32 values carrying a few ulp, plus the rotation's 1e-6 stopping tolerance:
    /// 1e-5 m.
    /// </summary>
    public class ShapeMatchingGoalTests
    {
        const float k_PositionTolerance = 1e-5f;

        static float3[] Cube()
        {
            var p = new float3[8];
            for (int i = 0; i < 8; i++) p[i] = new float3(i & 1, (i >> 1) & 1, (i >> 2) & 1) - 0.5f;
            return p;
        }

        static float[] Masses(int n, uint seed)
        {
            var rng = new Unity.Mathematics.Random(seed);
            var m = new float[n];
            for (int i = 0; i < n; i++) m[i] = rng.NextFloat(0.5f, 2f);
            return m;
        }

        static void AssertGoalsMatch(float3[] rest, float[] mass, float3[] x, ShapeMatchingMode mode, float beta)
        {
            ClusterRestData data = ShapeMatching.ComputeRestData(rest, mass);
            float3 c = ShapeMatching.CenterOfMass(x, mass);
            float3x3 apq = ShapeMatching.Apq(x, mass, c, rest, data.RestCenter);
            quaternion q = quaternion.identity;
            float3x3 t = ShapeMatching.GoalTransform(apq, data, mode, beta, ref q, out bool fallback);
            Assert.That(fallback, Is.False);
            for (int i = 0; i < rest.Length; i++)
            {
                float3 goal = math.mul(t, rest[i] - data.RestCenter) + c;
                Assert.That(math.length(goal - x[i]), Is.LessThan(k_PositionTolerance), $"particle {i}");
            }
        }

        [Test]
        public void Goals_EqualPositions_ForRigidlyMovedCluster([Values(ShapeMatchingMode.Rigid, ShapeMatchingMode.Linear)] ShapeMatchingMode mode)
        {
            float3[] rest = Cube();
            float[] mass = Masses(rest.Length, 1u);
            quaternion rot = quaternion.AxisAngle(math.normalize(new float3(1f, -2f, 0.5f)), 2.5f);
            float3[] x = Array.ConvertAll(rest, p => math.rotate(rot, p) + new float3(3f, -1f, 2f));
            AssertGoalsMatch(rest, mass, x, mode, 1f);
        }

        [Test]
        public void LinearGoals_ReproduceVolumePreservingShear()
        {
            // F = rotation · shear (det 1): with β = 1 the linear mode matches it exactly.
            float3[] rest = Cube();
            float[] mass = Masses(rest.Length, 2u);
            float3x3 f = math.mul(new float3x3(quaternion.AxisAngle(new float3(0f, 0f, 1f), 0.4f)),
                new float3x3(1f, 0.3f, 0f, 0f, 1f, 0.2f, 0f, 0f, 1f));
            float3[] x = Array.ConvertAll(rest, p => math.mul(f, p));
            AssertGoalsMatch(rest, mass, x, ShapeMatchingMode.Linear, 1f);
        }

        [Test]
        public void LinearMode_FallsBackToRigid_ForPlanarRestShape()
        {
            float3[] rest = { new float3(0f, 0f, 0f), new float3(1f, 0f, 0f), new float3(0f, 1f, 0f), new float3(1f, 1f, 0f) };
            float[] mass = { 1f, 1f, 1f, 1f };
            ClusterRestData data = ShapeMatching.ComputeRestData(rest, mass);
            Assert.That(data.LinearValid, Is.False);
            float3 c = ShapeMatching.CenterOfMass(rest, mass);
            float3x3 apq = ShapeMatching.Apq(rest, mass, c, rest, data.RestCenter);
            quaternion q = quaternion.identity;
            float3x3 t = ShapeMatching.GoalTransform(apq, data, ShapeMatchingMode.Linear, 0.5f, ref q, out bool fallback);
            Assert.That(fallback, Is.True);
            Assert.That(Finite.All(t), Is.True);
            Assert.That(math.determinant(t), Is.EqualTo(1f).Within(1e-5f));
        }

        [Test]
        public void LinearMode_FallsBackToRigid_ForInvertedCluster()
        {
            float3[] rest = Cube();
            float[] mass = Masses(rest.Length, 3u);
            float3[] x = Array.ConvertAll(rest, p => new float3(-p.x, p.y, p.z)); // mirrored: det Ã < 0
            ClusterRestData data = ShapeMatching.ComputeRestData(rest, mass);
            float3x3 apq = ShapeMatching.Apq(x, mass, ShapeMatching.CenterOfMass(x, mass), rest, data.RestCenter);
            quaternion q = quaternion.identity;
            float3x3 t = ShapeMatching.GoalTransform(apq, data, ShapeMatchingMode.Linear, 1f, ref q, out bool fallback);
            Assert.That(fallback, Is.True);
            Assert.That(math.determinant(t), Is.EqualTo(1f).Within(1e-5f), "a proper rotation, never a reflection");
        }
    }
}
