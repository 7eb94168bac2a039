using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Bake validation gives specific codes; element passes give the same bits for any split and colour order.</summary>
    public class FemBakeAndDeterminismTests
    {
        static readonly ElasticMaterial Jelly = new ElasticMaterial(1e4f, 0.45f, 1000f, 0.1f);

        static List<ValidationIssue> Issues(TetrahedralMesh mesh, ElasticMaterial material, out FemModelData data)
        {
            var issues = new List<ValidationIssue>();
            data = FemModelData.Create(mesh, material, ReadOnlySpan<bool>.Empty, issues);
            return issues;
        }

        static readonly float3[] UnitTet = { new float3(0f, 0f, 0f), new float3(1f, 0f, 0f), new float3(0f, 1f, 0f), new float3(0f, 0f, 1f) };

        [Test]
        public void Bake_GoodBox_NoIssues_MassesSumToDensityTimesVolume()
        {
            List<ValidationIssue> issues = Issues(FemTestBodies.Box(2, 3, 1, new float3(0.2f, 0.3f, 0.1f)), Jelly, out FemModelData data);
            Assert.That(issues, Is.Empty);
            double mass = 0;
            foreach (float m in data.Masses)
                mass += m;
            Assert.That(mass, Is.EqualTo(1000.0 * 0.2 * 0.3 * 0.1).Within(1e-5));
            Assert.That(data.Coloring.ColorCount, Is.GreaterThan(1));
        }

        [Test]
        public void Bake_ZeroVolumeTet_IsError()
        {
            var positions = new[] { UnitTet[0], UnitTet[1], UnitTet[2], new float3(1f, 1f, 0f) };
            List<ValidationIssue> issues = Issues(new TetrahedralMesh(positions, new[] { new int4(0, 1, 2, 3) }), Jelly, out FemModelData data);
            Assert.That(data, Is.Null);
            Assert.That(issues.Exists(i => i.Code == FemIssueCode.TetrahedronDegenerate && i.Index == 0 && i.Severity == IssueSeverity.Error));
        }

        [Test]
        public void Bake_InvertedTet_IsError()
        {
            var mesh = new TetrahedralMesh((float3[])UnitTet.Clone(), new[] { new int4(0, 2, 1, 3) });
            List<ValidationIssue> issues = Issues(mesh, Jelly, out FemModelData data);
            Assert.That(data, Is.Null);
            Assert.That(issues.Exists(i => i.Code == FemIssueCode.TetrahedronInverted && i.Index == 0 && i.Severity == IssueSeverity.Error));
        }

        [Test]
        public void Bake_SliverTet_IsWarning()
        {
            // Apex 0.02 above the base: quality ≈ 0.04 < 0.1 but far from flat.
            var positions = new[] { UnitTet[0], UnitTet[1], UnitTet[2], new float3(0.3f, 0.3f, 0.02f) };
            List<ValidationIssue> issues = Issues(new TetrahedralMesh(positions, new[] { new int4(0, 1, 2, 3) }), Jelly, out FemModelData data);
            Assert.That(data, Is.Not.Null);
            Assert.That(issues.Exists(i => i.Code == FemIssueCode.TetrahedronSliver && i.Index == 0 && i.Severity == IssueSeverity.Warning));
            // The measure is 1 for a regular tetrahedron.
            float regular = FemModelData.Quality(new float3(1f, 1f, 1f), new float3(1f, -1f, -1f), new float3(-1f, 1f, -1f), new float3(-1f, -1f, 1f));
            Assert.That(math.abs(regular), Is.EqualTo(1f).Within(1e-5f));
        }

        [Test]
        public void Bake_UnusedNode_IsWarnedAndPinned()
        {
            var positions = new[] { UnitTet[0], UnitTet[1], UnitTet[2], UnitTet[3], new float3(5f, 5f, 5f) };
            List<ValidationIssue> issues = Issues(new TetrahedralMesh(positions, new[] { new int4(0, 1, 2, 3) }), Jelly, out FemModelData data);
            Assert.That(data, Is.Not.Null);
            Assert.That(issues.Exists(i => i.Code == FemIssueCode.NodeUnused && i.Index == 4));
            Assert.That(data.InverseMasses[4], Is.EqualTo(0f));
            Assert.That(data.Masses[4], Is.GreaterThan(0f));
        }

        [Test]
        public void Bake_InvalidMaterial_IsErrorNamingTheRange([Values(0.5f, 0.6f, -0.1f, float.NaN)] float poisson)
        {
            var mesh = new TetrahedralMesh((float3[])UnitTet.Clone(), new[] { new int4(0, 1, 2, 3) });
            List<ValidationIssue> issues = Issues(mesh, new ElasticMaterial(1e4f, poisson, 1000f, 0.1f), out FemModelData data);
            Assert.That(data, Is.Null);
            ValidationIssue issue = issues.Find(i => i.Code == FemIssueCode.MaterialInvalid);
            Assert.That(issue.Severity, Is.EqualTo(IssueSeverity.Error));
            StringAssert.Contains("0 ≤ ν < 0.5", issue.Message);
        }

        [Test]
        public void Bake_BadNodeIndexOrPinCount_IsError()
        {
            var mesh = new TetrahedralMesh((float3[])UnitTet.Clone(), new[] { new int4(0, 1, 2, 7) });
            Assert.That(Issues(mesh, Jelly, out _).Exists(i => i.Code == FemIssueCode.TetrahedronNodeInvalid && i.Index == 0));
            var issues = new List<ValidationIssue>();
            var good = new TetrahedralMesh((float3[])UnitTet.Clone(), new[] { new int4(0, 1, 2, 3) });
            Assert.That(FemModelData.Create(good, Jelly, new bool[3], issues), Is.Null);
            Assert.That(issues.Exists(i => i.Code == FemIssueCode.PinnedCountMismatch));
        }

        static (uint, uint, uint) Bits(float3 v) => (math.asuint(v.x), math.asuint(v.y), math.asuint(v.z));

        static float3[] DeformedPositions(FemModelData data, int seed)
        {
            var random = new System.Random(seed);
            var x = new float3[data.RestPositions.Length];
            for (int i = 0; i < x.Length; i++)
                x[i] = data.RestPositions[i] + 0.02f * new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f);
            return x;
        }

        [Test]
        public void ElementForces_SameBits_ForAnyBatchSplitAndOrder([Values] FemMaterialModel materialModel)
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(3, 3, 2, new float3(0.3f, 0.3f, 0.2f)), Jelly);
            float3[] x = DeformedPositions(data, 1), v = DeformedPositions(data, 2);
            float3[] Run(int batch, bool reverse)
            {
                FemModel model = data.AsModel();
                var rotations = new quaternion[model.ElementCount];
                Array.Fill(rotations, quaternion.identity);
                var slots = new float3[4 * model.ElementCount];
                var f = new float3[model.ParticleCount];
                int elementBatches = (model.ElementCount + batch - 1) / batch, nodeBatches = (model.ParticleCount + batch - 1) / batch;
                for (int b = 0; b < elementBatches; b++)
                {
                    int k = reverse ? elementBatches - 1 - b : b;
                    FemForces.Elastic(model, materialModel, x, v, 0.01f, rotations, 20, slots, k * batch, math.min(model.ElementCount, (k + 1) * batch));
                }
                for (int b = 0; b < nodeBatches; b++)
                {
                    int k = reverse ? nodeBatches - 1 - b : b;
                    FemForces.Gather(model, slots, f, k * batch, math.min(model.ParticleCount, (k + 1) * batch));
                }
                return f;
            }
            float3[] whole = Run(100000, false);
            foreach (int batch in new[] { 1, 7, 33 })
            {
                float3[] split = Run(batch, true);
                for (int i = 0; i < whole.Length; i++)
                    Assert.That(Bits(split[i]), Is.EqualTo(Bits(whole[i])), $"node {i}, batch {batch}");
            }
        }

        [Test]
        public void XpbdProjection_SameBits_ForAnyOrderWithinAColour()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(3, 3, 2, new float3(0.3f, 0.3f, 0.2f)), Jelly);
            float3[] x = DeformedPositions(data, 3);
            float3[] Run(bool reverse)
            {
                FemModel model = data.AsModel();
                var d = new float3[model.ParticleCount];
                for (int i = 0; i < d.Length; i++)
                    d[i] = new float3(0f, -0.001f * (i % 5), 0.0005f * (i % 3));
                var multipliers = new float3[model.ElementCount];
                for (int c = 0; c < model.ColorCount; c++)
                {
                    int start = model.ColorOffsets[c], end = model.ColorOffsets[c + 1];
                    for (int k = 0; k < end - start; k++)
                    {
                        int e = reverse ? end - 1 - k : start + k;
                        FemXpbd.Project(model, model.ColorElements, x, d, multipliers, 1f / 240f, 0.01f, e, e + 1);
                    }
                }
                return d;
            }
            float3[] forward = Run(false), backward = Run(true);
            for (int i = 0; i < forward.Length; i++)
                Assert.That(Bits(backward[i]), Is.EqualTo(Bits(forward[i])), $"node {i}");
        }

        [Test]
        public void Step_SameInput_SameBits([Values] FemIntegrator integrator)
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(2, 2, 2, new float3(0.2f)), Jelly);
            FemParameters p = FemParameters.Default;
            p.Integrator = integrator;
            p.Model = integrator == FemIntegrator.Xpbd ? FemMaterialModel.NeoHookean : FemMaterialModel.CoRotational;
            p.Body.Substeps = 8;
            var colliders = new[] { ColliderShape.Plane(new float3(0f, -0.3f, 0f), new float3(0f, 1f, 0f)) };
            FemTestBody a = new FemTestBody(data, p), b = new FemTestBody(data, p);
            for (int step = 0; step < 30; step++)
            {
                a.Step(1f / 60f, colliders);
                b.Step(1f / 60f, colliders);
            }
            for (int i = 0; i < a.Positions.Length; i++)
                Assert.That(Bits(a.Positions[i]), Is.EqualTo(Bits(b.Positions[i])));
        }
    }
}
