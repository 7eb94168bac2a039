using System;
using System.Linq;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>The GPU fluid hands the renderer one buffer (PackRender), and the renderer draws it as it draws the CPU's particles.</summary>
    public class FluidRenderPackTests
    {
        [Test]
        public void PackRender_GivesLiveParticlesAndNaNBeyond_AndTheSamePictureAsTheCpuParticles()
        {
            FluidSurfaceScene scene = SurfaceScenes.Get("two-blobs");
            int n = scene.Particles.Length;
            FluidParameters p = FluidParameters.Default;
            p.ParticleSpacing = 0.02f;
            p.DomainMin = new float3(-0.3f, 0f, -0.3f);
            p.DomainMax = new float3(0.3f, 0.4f, 0.3f);
            var constants = new FluidConstants(p);
            var b = new FluidBuffers(n + 37, constants.Grid);
            for (int i = 0; i < n; i++)
            {
                b.Positions[i] = scene.Particles[i].xyz;
                b.Attributes[i] = scene.Particles[i].w;
                b.Ids[i] = i;
            }
            using var gpu = new LavapipeFluidSolver(Lavapipe.Device, Lavapipe.FluidShader, constants, n + 37);
            gpu.Upload(b.Particles, n);
            gpu.PackRender();
            float4[] packed = gpu.Buffer(FluidComputeBuffer.RenderParticles).As<float4>().Slice(0, gpu.Capacity).ToArray();
            for (int i = 0; i < gpu.Capacity; i++)
            {
                if (i < n)
                    Assert.That(packed[i], Is.EqualTo(scene.Particles[i]), $"slot {i}");
                else
                    Assert.That(float.IsNaN(packed[i].x), $"slot {i} beyond the live particles must be NaN");
            }
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(scene.Radius);
            LavapipeFluidSurface.Frame fromCpu = SurfaceScenes.Render(scene, s, FluidLook.Lava);
            LavapipeFluidSurface.Frame fromGpu = Lavapipe.Surface.Render(scene.Camera, s, FluidLook.Lava, scene.Lighting, packed, scene.SceneColour, scene.SceneEyeDepth);
            Assert.That(fromGpu.Stats[FluidSurfaceLayout.StatDrawn], Is.EqualTo(n));
            Assert.That(fromGpu.Colour, Is.EqualTo(fromCpu.Colour));
            Lavapipe.AssertValid();
        }
    }
}
