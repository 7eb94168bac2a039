using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>The soft-body kernels against the C# they port: XPBD springs by colour, and the shape-matching cluster sums.</summary>
    public class SoftBodyKernelTests
    {
        static LavapipeComputeShader s_Shader;

        [OneTimeSetUp]
        public void Compile() => s_Shader = new LavapipeComputeShader(Lavapipe.Device, LavapipeSoftBodyCommands.ComputePath());

        [OneTimeTearDown]
        public void Release() => s_Shader?.Dispose();

        static void Upload(LavapipeSoftBodyCommands g, SoftBodyComputeBuffer b, ReadOnlySpan<float3> v)
        {
            LavapipeBuffer buffer = g.Create(b, 16L * Math.Max(v.Length, 1));
            SoftBodyComputeStep.PackVectors(v, buffer.As<float4>());
        }

        static void Upload<T>(LavapipeSoftBodyCommands g, SoftBodyComputeBuffer b, ReadOnlySpan<T> v) where T : unmanaged
        {
            LavapipeBuffer buffer = g.Create(b, Math.Max(16L, (long)System.Runtime.CompilerServices.Unsafe.SizeOf<T>() * v.Length));
            v.CopyTo(buffer.As<T>());
        }

        /// <summary>
        /// Two XPBD substeps of a stretched, moving jelly box, two iterations each: the GPU's predicted positions,
        /// velocities and multipliers against SpringForces.ProjectColor run colour by colour (the XPBD branch of
        /// MassSpringSolveStage). The same operations in the same order per spring; differences come only from FMA
        /// contraction and the driver's division and square root (a few ulp per spring, accumulated over the ≤ 2 × 20
        /// springs that move a particle): |Δp| ≤ 1e-5 of the body's size, the multipliers within 1e-4 of their largest.
        /// </summary>
        [Test]
        public void XpbdSubstep_MatchesTheCpuProjection()
        {
            var issues = new List<ValidationIssue>();
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(0.4f, 0.3f, 0.2f), new int3(8, 6, 4), new float3(0.2f, 0.15f, 0.1f));
            MassSpringModelData body = MassSpringModelData.FromMesh(mesh, ElasticMaterial.Jelly, new MassSpringBuildSettings(), issues, out _, null);
            int n = body.ParticleCount, m = body.SpringCount;
            var random = new Unity.Mathematics.Random(17u);
            var x = new float3[n];
            var v = new float3[n];
            for (int i = 0; i < n; i++)
            {
                x[i] = body.RestPositions[i] * new float3(1.2f, 0.9f, 1f) + random.NextFloat3(-0.005f, 0.005f);
                v[i] = random.NextFloat3(-0.5f, 0.5f);
            }
            using var g = new LavapipeSoftBodyCommands(Lavapipe.Device, s_Shader);
            var springs = new float4[2 * m];
            SoftBodyComputeStep.PackSprings(body.Springs, springs);
            Upload(g, SoftBodyComputeBuffer.Rest, body.RestPositions);
            Upload<float>(g, SoftBodyComputeBuffer.InverseMass, body.InverseMasses);
            Upload<float4>(g, SoftBodyComputeBuffer.Springs, springs);
            Upload<int>(g, SoftBodyComputeBuffer.ColorSprings, body.Coloring.Elements);
            g.Create(SoftBodyComputeBuffer.Multipliers, 4L * m);
            g.Create(SoftBodyComputeBuffer.P, 16L * n);
            Upload(g, SoftBodyComputeBuffer.X, x);
            Upload(g, SoftBodyComputeBuffer.V, v);

            const float h = 1f / 240f;
            const int iterations = 2;
            var p = new float3[n];
            var lambda = new float3[2 * m];
            for (int substep = 0; substep < 2; substep++)
            {
                // GPU from the CPU's state.
                SoftBodyComputeStep.PackVectors(x, g.Buffer(SoftBodyComputeBuffer.X).As<float4>());
                SoftBodyComputeStep.PackVectors(v, g.Buffer(SoftBodyComputeBuffer.V).As<float4>());
                var commands = g;
                SoftBodyComputeStep.RecordXpbdSubstep(ref commands, n, m, body.Coloring.ColorOffsets, iterations, h);
                g.Flush();
                Lavapipe.AssertValid();
                // CPU.
                for (int i = 0; i < n; i++)
                    p[i] = x[i] + h * v[i];
                Array.Clear(lambda, 0, lambda.Length);
                for (int it = 0; it < iterations; it++)
                    for (int c = 0; c < body.Coloring.ColorCount; c++)
                        SpringForces.ProjectColor(body.Springs, body.Coloring.Elements, body.RestPositions, x, body.InverseMasses, h,
                            body.Coloring.ColorOffsets[c], body.Coloring.ColorOffsets[c + 1], p, lambda);
                float invH = 1f / h;
                var vNew = new float3[n];
                for (int i = 0; i < n; i++)
                    vNew[i] = (p[i] - x[i]) * invH;

                Span<float4> gp = g.Buffer(SoftBodyComputeBuffer.P).As<float4>();
                Span<float4> gv = g.Buffer(SoftBodyComputeBuffer.V).As<float4>();
                Span<float> gl = g.Buffer(SoftBodyComputeBuffer.Multipliers).As<float>();
                double dp = 0, dv = 0, dl = 0, vScale = 0, lScale = 0;
                for (int i = 0; i < n; i++)
                {
                    dp = Math.Max(dp, math.length(gp[i].xyz - p[i]));
                    dv = Math.Max(dv, math.length(gv[i].xyz - vNew[i]));
                    vScale = Math.Max(vScale, math.length(vNew[i]));
                }
                for (int e = 0; e < m; e++)
                {
                    dl = Math.Max(dl, Math.Abs(gl[e] - lambda[2 * e].x));
                    lScale = Math.Max(lScale, Math.Abs(lambda[2 * e].x));
                }
                TestContext.Out.WriteLine($"substep {substep}: {n} particles, {m} springs in {body.Coloring.ColorCount} colours; max |Δp| {dp:E2} m, |Δv| {dv:E2} m/s (of {vScale:G3}), |Δλ| {dl:E2} (of {lScale:G3})");
                Assert.That(dp, Is.LessThanOrEqualTo(1e-5 * 0.4), "predicted positions");
                Assert.That(dl, Is.LessThanOrEqualTo(1e-4 * lScale), "multipliers");
                // v = Δp/h: the position error divided by h.
                Assert.That(dv, Is.LessThanOrEqualTo(1e-5 * 0.4 / h + 1e-6 * vScale), "velocities");
                for (int i = 0; i < n; i++)
                {
                    x[i] = p[i];
                    v[i] = vNew[i];
                }
            }
        }

        /// <summary>
        /// Centre and A_pq of every cluster of a deformed lattice body (clusters of 3³ = 27 particles and, in a second
        /// body, one cluster of all 500 particles, so one group loops over its members) against float64 sums. A parallel
        /// sum of n terms differs from the exact one by at most γ_n·Σ|terms| (γ_n ≈ n·2⁻²⁴, n = members + the 8 tree levels),
        /// and the centre's error enters A_pq through Σ wᵢ|qᵢ|: that is the bound asserted, term by term.
        /// </summary>
        [TestCase(3)]
        [TestCase(10)]
        public void ClusterSums_AreTheWeightedSumsWithinRoundOff(int clusterSize)
        {
            ShapeMatchingModelData body = LatticeBody.Create(new int3(10, 10, 5), 0.05f, clusterSize, 2f);
            int n = body.ParticleCount, clusters = body.ClusterCount;
            var random = new Unity.Mathematics.Random(29u);
            var x = new float3[n];
            float3x3 deformation = new float3x3(1.1f, 0.2f, 0f, -0.1f, 0.9f, 0.05f, 0f, 0.1f, 1.05f);
            for (int i = 0; i < n; i++)
                x[i] = math.mul(deformation, body.RestPositions[i]) + new float3(1f, 2f, -0.5f) + random.NextFloat3(-0.002f, 0.002f);
            var rest = new float4[clusters];
            for (int c = 0; c < clusters; c++)
                rest[c] = new float4(body.ClusterRest[c].RestCenter, body.ClusterRest[c].TotalMass);
            using var g = new LavapipeSoftBodyCommands(Lavapipe.Device, s_Shader);
            Upload(g, SoftBodyComputeBuffer.X, x);
            Upload(g, SoftBodyComputeBuffer.Rest, body.RestPositions);
            Upload<int>(g, SoftBodyComputeBuffer.ClusterOffsets, body.ClusterOffsets);
            Upload<int>(g, SoftBodyComputeBuffer.ClusterParticles, body.ClusterParticles);
            Upload<float>(g, SoftBodyComputeBuffer.ClusterWeights, body.ClusterWeights);
            Upload<float4>(g, SoftBodyComputeBuffer.ClusterRest, rest);
            g.Create(SoftBodyComputeBuffer.ClusterCenters, 16L * clusters);
            g.Create(SoftBodyComputeBuffer.ClusterApq, 48L * clusters);
            var commands = g;
            SoftBodyComputeStep.RecordClusterSums(ref commands, clusters);
            g.Flush();
            Lavapipe.AssertValid();
            Span<float4> centres = g.Buffer(SoftBodyComputeBuffer.ClusterCenters).As<float4>();
            Span<float4> apq = g.Buffer(SoftBodyComputeBuffer.ClusterApq).As<float4>();
            double worst = 0;
            double u = Math.Pow(2, -24);
            for (int c = 0; c < clusters; c++)
            {
                int start = body.ClusterOffsets[c], end = body.ClusterOffsets[c + 1], members = end - start;
                double gamma = (members + 8) * u / (1 - (members + 8) * u);
                double mass = rest[c].w;
                var centre = new double[3];
                var centreBound = new double[3];
                for (int a = 0; a < 3; a++)
                {
                    double sum = 0, abs = 0;
                    for (int k = start; k < end; k++)
                    {
                        double xi = x[body.ClusterParticles[k]][a];
                        sum += body.ClusterWeights[k] * xi;
                        abs += body.ClusterWeights[k] * Math.Abs(xi);
                    }
                    centre[a] = sum / mass;
                    // The sum's round-off, then the division's.
                    centreBound[a] = 2 * gamma * abs / mass + 2 * u * Math.Abs(centre[a]);
                    double d = Math.Abs(centres[c].xyz[a] - centre[a]);
                    Assert.That(d, Is.LessThanOrEqualTo(centreBound[a]), $"cluster {c}: centre[{a}] {centres[c].xyz[a]} vs {centre[a]}");
                }
                for (int j = 0; j < 3; j++)
                    for (int a = 0; a < 3; a++)
                    {
                        double column = 0, columnAbs = 0, qAbs = 0;
                        for (int k = start; k < end; k++)
                        {
                            int i = body.ClusterParticles[k];
                            double w = body.ClusterWeights[k];
                            double pi = x[i][a] - centre[a];
                            double q = (double)body.RestPositions[i][j] - rest[c].xyz[j];
                            column += w * pi * q;
                            columnAbs += w * Math.Abs(pi) * Math.Abs(q);
                            qAbs += w * Math.Abs(q);
                        }
                        // Each term: the subtraction, two products (3u); the sum: γ; the centre's error times Σ w|q|.
                        double bound = (gamma + 4 * u) * columnAbs + qAbs * centreBound[a] + 1e-12;
                        double d = Math.Abs(apq[3 * c + j].xyz[a] - column);
                        worst = Math.Max(worst, d / bound);
                        Assert.That(d, Is.LessThanOrEqualTo(bound), $"cluster {c}: A_pq[{a},{j}] {apq[3 * c + j].xyz[a]} vs {column} (bound {bound:E2})");
                    }
            }
            TestContext.Out.WriteLine($"{clusters} clusters of size {clusterSize}: the largest error is {worst:P1} of its round-off bound");
        }
    }
}
