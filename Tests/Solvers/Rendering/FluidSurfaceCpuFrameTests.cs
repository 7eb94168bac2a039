using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The C# reference frame driven by the pass list (FluidSurfaceCpuFrame, what the renderer's effect rows time): it runs
    /// the same passes as calling the references stage by stage, dispatches exactly the list, and its composite reads no
    /// target whose pass is off.
    /// </summary>
    public class FluidSurfaceCpuFrameTests
    {
        const int Width = 64, Height = 36;

        static FluidSurfaceScene s_Scene;
        static FluidSurfaceScene Scene => s_Scene ??= FluidSurfaceScene.Sphere(Width, Height);

        [Test]
        public void RecordedFrame_IsTheReferenceStageByStage([Values(FluidSurfaceFilter.NarrowRange, FluidSurfaceFilter.Bilateral, FluidSurfaceFilter.CurvatureFlow)] FluidSurfaceFilter filter)
        {
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(Scene.Radius);
            s.Filter = filter;
            s.Iterations = filter == FluidSurfaceFilter.CurvatureFlow ? 3 : 1;
            var frame = new FluidSurfaceCpuFrame(Scene, s, FluidLook.Water);
            frame.Render();
            Assert.That(frame.Dispatches, Is.EqualTo(frame.Passes.TotalDispatches));

            FluidSurfaceConstants k = frame.Constants;
            var a = new float[frame.DepthA.Length];
            var b = new float[a.Length];
            var thickness = new float2[frame.Thickness.Length];
            var normals = new uint[a.Length];
            var colour = new float4[frame.Colour.Length];
            FluidSurfacePasses.SplatDepth(k, Scene.Particles, a);
            FluidSurfacePasses.SplatThickness(k, Scene.Particles, thickness);
            FluidSurfacePasses.Smooth(k, s, a, b);
            float[] depth = FluidSurfaceFrame.SmoothedDepth(frame.Passes) == FluidSurfaceBuffer.DepthA ? a : b;
            FluidSurfacePasses.Normals(k, depth, normals);
            FluidSurfaceComposite.Composite(k, new FluidSurfaceComposite.Inputs(depth, normals, thickness, Scene.SceneColour, Scene.SceneEyeDepth), colour);

            Assert.That(frame.SmoothedDepth, Is.EqualTo(depth), "the same float32 expressions in the same order: the same bits");
            Assert.That(frame.Normals, Is.EqualTo(normals));
            Assert.That(frame.Thickness, Is.EqualTo(thickness));
            Assert.That(frame.Colour, Is.EqualTo(colour));
            int covered = 0;
            foreach (float4 c in colour)
                covered += c.w > 0f ? 1 : 0;
            Assert.That(covered, Is.GreaterThan(50), "the ball is on screen");
        }

        [Test]
        public void Composite_ReadsNoThicknessWhenItsPassIsOff()
        {
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(Scene.Radius);
            var frame = new FluidSurfaceCpuFrame(Scene, s, FluidSurfacePassListTests.ClearWater);
            Assert.That(frame.Passes.Thickness, Is.False);
            frame.Render();
            Assert.That(frame.DispatchesOf(FluidSurfaceKernel.SplatThickness), Is.Zero);
            // What a target holds when its pass did not run is undefined: here +∞, which a read would turn into a NaN
            // colour (e^(−0 · ∞)); NaN itself would not do: the composite skips thickness texels that are not positive.
            Array.Fill(frame.Thickness, new float2(float.PositiveInfinity));
            var colour = new float4[frame.Colour.Length];
            FluidSurfaceComposite.Composite(frame.Constants, new FluidSurfaceComposite.Inputs(frame.SmoothedDepth, frame.Normals, frame.Thickness,
                Scene.SceneColour, Scene.SceneEyeDepth), colour);
            Assert.That(colour, Is.EqualTo(frame.Colour), "the colour does not depend on the thickness target");
            foreach (float4 c in colour)
                Assert.That(math.all(math.isfinite(c)), Is.True);
        }

        [Test]
        public void Composite_ReadsNoNormalsWhenTheirPassIsOff()
        {
            FluidSurfaceSettings s = FluidSurfaceSettings.Desktop(Scene.Radius);
            var frame = new FluidSurfaceCpuFrame(Scene, s, FluidLook.ThicknessTint);
            Assert.That(frame.Passes.Normals, Is.False);
            frame.Render();
            Assert.That(frame.DispatchesOf(FluidSurfaceKernel.Normals), Is.Zero);
            Assert.That(frame.DispatchesOf(FluidSurfaceKernel.SplatThickness), Is.EqualTo(1));
            Array.Fill(frame.Normals, 0xDEADBEEFu);
            var colour = new float4[frame.Colour.Length];
            FluidSurfaceComposite.Composite(frame.Constants, new FluidSurfaceComposite.Inputs(frame.SmoothedDepth, frame.Normals, frame.Thickness,
                Scene.SceneColour, Scene.SceneEyeDepth), colour);
            Assert.That(colour, Is.EqualTo(frame.Colour));
        }
    }
}
