#if SBD_PERFORMANCE_TESTING
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
    /// The fluid step on the GPU (<see cref="FluidComputeSolver"/>): one CFL substep of the resting cube of
    /// <see cref="FluidBurstPerformanceTests"/> (the FluidThroughput workload) at 22³ ≈ 10k, 46³ ≈ 100k and 64³ ≈ 262k
    /// particles. Each measured step is dispatched and then fenced by waiting for an asynchronous read-back of the counters,
    /// so the time is the GPU's work plus one round trip to the CPU (a frame that does not wait pays only the dispatch).
    /// The cube is put back on its lattice every 60 steps, outside the timed region. Ignored on a device without compute
    /// shaders or asynchronous read-back.
    /// </summary>
    public class FluidComputePerformanceTests
    {
        const string k_ShaderPath = "Packages/com.softbodydynamics.dots/Shaders/FluidSolver.compute";

        [Test, Performance]
        public void Fluid_Substep_Gpu([Values(22, 46, 64)] int side)
        {
            if (!SystemInfo.supportsComputeShaders || !SystemInfo.supportsAsyncGPUReadback)
                Assert.Ignore("This device runs no compute shaders or asynchronous read-backs.");
            var shader = (ComputeShader)AssetDatabase.LoadAssetAtPath(k_ShaderPath, typeof(ComputeShader));
            Assert.That(shader, Is.Not.Null, k_ShaderPath);
            FluidParameters p = Scenarios.FluidThroughputScenario.CubeParameters(side);
            var c = new FluidConstants(p);
            int n = side * side * side;
            var positions = new NativeArray<float4>(n, Allocator.Persistent);
            var velocities = new NativeArray<float4>(n, Allocator.Persistent);
            var extras = new NativeArray<FluidComputeExtras>(n, Allocator.Persistent);
            for (int z = 0, i = 0; z < side; z++)
            for (int y = 0; y < side; y++)
            for (int x = 0; x < side; x++, i++)
            {
                positions[i] = new float4((new float3(x, y, z) + 0.5f) * p.ParticleSpacing, 0f);
                extras[i] = new FluidComputeExtras { Id = i };
            }
            var solver = new FluidComputeSolver(shader, c, n);
            float dt = 0.9f * FluidSolver.CflSubstep(c, 0f, 1f);
            try
            {
                StepCycleMeasure.Steps(() =>
                {
                    solver.Step(dt);
                    AsyncGPUReadback.Request(solver.Buffer(FluidComputeBuffer.Stats)).WaitForCompletion();
                }, () => solver.Upload(positions, velocities, extras, n), 60, $"Fluid WCSPH substep x{n} GPU", 5, 20);
                AsyncGPUReadback.WaitAllRequests();
                Assert.That(solver.LastKnownCount, Is.EqualTo(n), "no particle lost");
            }
            finally
            {
                solver.Dispose();
                positions.Dispose();
                velocities.Dispose();
                extras.Dispose();
            }
        }
    }
}
#endif
