#if SBD_PERFORMANCE_TESTING
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Compute;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Mathematics;
using Unity.PerformanceTesting;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// One XPBD substep (one iteration over every colour) of a stretched jelly cube of 16³ and 32³ cells on the GPU
    /// (<see cref="SoftBodyComputeSolver"/>), fenced by waiting for a read-back of the predicted positions: the GPU's work
    /// plus one round trip. Divide the springs by the median for springs per second. Ignored on a device without compute
    /// shaders or asynchronous read-back.
    /// </summary>
    public class SoftBodyComputePerformanceTests
    {
        const string k_ShaderPath = "Packages/com.softbodydynamics.dots/Shaders/SoftBodySolver.compute";

        [Test, Performance]
        public void Xpbd_Substep_Gpu([Values(16, 32)] int cells)
        {
            if (!SystemInfo.supportsComputeShaders || !SystemInfo.supportsAsyncGPUReadback)
                Assert.Ignore("This device runs no compute shaders or asynchronous read-backs.");
            var shader = (ComputeShader)AssetDatabase.LoadAssetAtPath(k_ShaderPath, typeof(ComputeShader));
            Assert.That(shader, Is.Not.Null, k_ShaderPath);
            var issues = new List<ValidationIssue>();
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(1f), new int3(cells), float3.zero);
            MassSpringModelData body = MassSpringModelData.FromMesh(mesh, ElasticMaterial.Jelly, MassSpringBuildSettings.Default, issues, out _);
            int n = body.ParticleCount, m = body.SpringCount;
            var x = new NativeArray<float4>(n, Allocator.Persistent);
            var rest = new NativeArray<float4>(n, Allocator.Persistent);
            var inverseMass = new NativeArray<float>(body.InverseMasses, Allocator.Persistent);
            var springs = new NativeArray<float4>(2 * m, Allocator.Persistent);
            var colorSprings = new NativeArray<int>(body.Coloring.Elements, Allocator.Persistent);
            SoftBodyComputeStep.PackVectors(body.RestPositions, rest.AsSpan());
            for (int i = 0; i < n; i++)
                x[i] = new float4(1.05f * body.RestPositions[i], 0f);
            SoftBodyComputeStep.PackSprings(body.Springs, springs.AsSpan());
            var solver = new SoftBodyComputeSolver(shader);
            try
            {
                solver.SetData(SoftBodyComputeBuffer.X, x, 16);
                solver.SetData(SoftBodyComputeBuffer.V, new NativeArray<float4>(n, Allocator.Temp), 16);
                solver.SetData(SoftBodyComputeBuffer.Rest, rest, 16);
                solver.SetData(SoftBodyComputeBuffer.InverseMass, inverseMass, 4);
                solver.SetData(SoftBodyComputeBuffer.Springs, springs, 16);
                solver.SetData(SoftBodyComputeBuffer.ColorSprings, colorSprings, 4);
                solver.Allocate(SoftBodyComputeBuffer.Multipliers, m, 4);
                solver.Allocate(SoftBodyComputeBuffer.P, n, 16);
                Measure.Method(() =>
                    {
                        var commands = solver;
                        SoftBodyComputeStep.RecordXpbdSubstep(ref commands, n, m, body.Coloring.ColorOffsets, 1, 1f / 240f);
                        AsyncGPUReadback.Request(solver.Buffer(SoftBodyComputeBuffer.P)).WaitForCompletion();
                    })
                    .SampleGroup(new SampleGroup($"XPBD substep x{m} springs GPU", SampleUnit.Millisecond))
                    .WarmupCount(5)
                    .MeasurementCount(20)
                    .Run();
            }
            finally
            {
                solver.Dispose();
                x.Dispose();
                rest.Dispose();
                inverseMass.Dispose();
                springs.Dispose();
                colorSprings.Dispose();
            }
        }
    }
}
#endif
