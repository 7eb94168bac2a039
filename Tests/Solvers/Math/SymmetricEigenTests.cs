using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The Jacobi eigen-decomposition of symmetric 3×3 matrices: S = V diag(e) Vᵀ with V a proper rotation.</summary>
    public class SymmetricEigenTests
    {
        static float3x3 Diag(float3 d) => new float3x3(d.x, 0f, 0f, 0f, d.y, 0f, 0f, 0f, d.z);

        static void Check(float3x3 s, string label)
        {
            int sweeps = SymmetricEigen.Decompose(s, out float3x3 v, out float3 e);
            float3x3 back = math.mul(math.mul(v, Diag(e)), math.transpose(v));
            float scale = math.max(Matrix3.MaxAbs(s), 1e-30f);
            float reconstruction = Matrix3.MaxAbs(back - s) / scale;
            float orthogonality = Matrix3.MaxAbs(math.mul(math.transpose(v), v) - float3x3.identity);
            TestContext.WriteLine($"{label}: {sweeps} sweeps, |VΛVᵀ − S|/|S| {reconstruction:G3}, |VᵀV − I| {orthogonality:G3}");
            // Each rotation is backward stable (a few ε = 6e-8 of |S| per rotation), at most 3 × 8 of them: the measured
            // worst is ~3e-7; 2e-6 leaves room for the sums in the reconstruction itself.
            Assert.That(reconstruction, Is.LessThan(2e-6f), label);
            Assert.That(orthogonality, Is.LessThan(2e-6f), label);
            Assert.That(math.determinant(v), Is.EqualTo(1f).Within(2e-6f), label + ": a proper rotation");
            Assert.That(sweeps, Is.LessThanOrEqualTo(SymmetricEigen.MaxSweeps));
        }

        [Test]
        public void Decompose_RandomSymmetric_ReconstructsWithAProperRotation([Values(1, 2, 3, 4, 5)] int seed)
        {
            var random = new System.Random(seed);
            float R() => (float)(random.NextDouble() * 2 - 1);
            for (int trial = 0; trial < 20; trial++)
            {
                var a = new float3x3(R(), R(), R(), R(), R(), R(), R(), R(), R());
                Check(0.5f * (a + math.transpose(a)), $"seed {seed}, trial {trial}");
            }
        }

        [Test]
        public void Decompose_RepeatedOrZeroEigenvalues_IsExactOrIdentity()
        {
            Check(float3x3.identity, "identity");
            Check(default, "zero");
            Check(Diag(new float3(2f, -1f, 0.5f)), "diagonal");
            // Two equal eigenvalues: rotate diag(1, 1, 3) and diag(−2, 0, 0).
            var q = new float3x3(quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 3f)), 0.7f));
            Check(math.mul(math.mul(q, Diag(new float3(1f, 1f, 3f))), math.transpose(q)), "double eigenvalue");
            Check(math.mul(math.mul(q, Diag(new float3(-2f, 0f, 0f))), math.transpose(q)), "rank one");
            // Widely spread scales.
            Check(math.mul(math.mul(q, Diag(new float3(1e6f, 1f, 1e-6f))), math.transpose(q)), "ill-conditioned");
        }
    }
}
