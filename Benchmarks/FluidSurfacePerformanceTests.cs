#if SBD_PERFORMANCE_TESTING
using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
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
    /// The screen-space fluid passes on the GPU (Shaders/FluidSurface.compute, the pass list of
    /// <see cref="FluidSurfaceFrame"/>) for the main job's dam-break frame: desktop settings at 1920 × 1080 and the
    /// mobile tier at 2400 × 1080. Each measured frame is dispatched and fenced by an asynchronous read-back of the
    /// counters, so the time is the GPU's work plus one round trip (the overlay blit onto the camera is not included).
    /// The scene textures are left as created (their content does not change the work). Ignored on a device without
    /// compute shaders or asynchronous read-back.
    /// </summary>
    public class FluidSurfacePerformanceTests
    {
        const string k_ShaderPath = "Packages/com.softbodydynamics.dots/Shaders/FluidSurface.compute";

        sealed class Commands : IFluidSurfaceCommands
        {
            public ComputeShader Shader;
            public int[] Kernels;
            public GraphicsBuffer[] Buffers;
            public int[] SlotIds;
            public GraphicsBuffer Constants;
            public NativeArray<FluidSurfaceConstants> ConstantData;

            public void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer) =>
                Shader.SetBuffer(Kernels[(int)kernel], SlotIds[(int)slot], Buffers[(int)buffer]);

            public void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY) => Shader.Dispatch(Kernels[(int)kernel], groupsX, groupsY, 1);

            public void SetConstants(in FluidSurfaceConstants constants)
            {
                ConstantData[0] = constants;
                Constants.SetData(ConstantData, 0, 0, 1);
                Shader.SetConstantBuffer(UnityEngine.Shader.PropertyToID(FluidSurfaceConstants.BufferName), Constants, 0, FluidSurfaceConstants.Bytes);
            }
        }

        [Test, Performance]
        public void FluidSurface_Frame_Gpu([Values("desktop 1920x1080", "mobile 2400x1080")] string tier)
        {
            if (!SystemInfo.supportsComputeShaders || !SystemInfo.supportsAsyncGPUReadback)
                Assert.Ignore("This device runs no compute shaders or asynchronous read-backs.");
            var shader = (ComputeShader)AssetDatabase.LoadAssetAtPath(k_ShaderPath, typeof(ComputeShader));
            Assert.That(shader, Is.Not.Null, k_ShaderPath);
            bool mobile = tier.StartsWith("mobile");
            int width = mobile ? 2400 : 1920, height = 1080;
            FluidSurfaceScene scene = FluidSurfaceScene.DamBreak(width, height);
            FluidSurfaceSettings settings = mobile ? FluidSurfaceSettings.Mobile(scene.Radius) : FluidSurfaceSettings.Desktop(scene.Radius);
            FluidSurfaceTargets targets = FluidSurfaceTargets.Of(scene.Camera, settings.DepthDivisor);
            FluidSurfacePassList passes = FluidSurfacePassList.Of(settings, FluidLook.Water);
            int count = scene.Particles.Length;
            var particles = new NativeArray<float4>(scene.Particles, Allocator.Persistent);
            int capacity = FluidSurfacePasses.TileEntries(
                FluidSurfaceConstants.Of(scene.Camera, settings, FluidLook.Water, scene.Lighting, count, 1), particles.AsReadOnlySpan());
            FluidSurfaceConstants constants = FluidSurfaceConstants.Of(scene.Camera, settings, FluidLook.Water, scene.Lighting, count, capacity,
                FluidSurfaceConstants.ZBufferParams(scene.Camera.Near, 100f, SystemInfo.usesReversedZBuffer), SystemInfo.graphicsUVStartsAtTop);

            var names = Enum.GetNames(typeof(FluidSurfaceKernel));
            var commands = new Commands
            {
                Shader = shader,
                Kernels = new int[names.Length],
                Buffers = new GraphicsBuffer[Enum.GetValues(typeof(FluidSurfaceBuffer)).Length],
                SlotIds = new int[FluidSurfaceLayout.DepthSlotNames.Length],
                Constants = new GraphicsBuffer(GraphicsBuffer.Target.Constant, 1, FluidSurfaceConstants.Bytes),
                ConstantData = new NativeArray<FluidSurfaceConstants>(1, Allocator.Persistent),
            };
            for (int k = 0; k < names.Length; k++)
                commands.Kernels[k] = shader.FindKernel(names[k]);
            for (int s = 0; s < commands.SlotIds.Length; s++)
                commands.SlotIds[s] = Shader.PropertyToID(FluidSurfaceLayout.DepthSlotNames[s]);
            string[] bufferNames = FluidSurfaceLayout.BufferNames;
            for (int b = 0; b < commands.Buffers.Length; b++)
            {
                var id = (FluidSurfaceBuffer)b;
                commands.Buffers[b] = new GraphicsBuffer(GraphicsBuffer.Target.Structured, FluidSurfaceLayout.Length(id, targets, count, capacity), FluidSurfaceLayout.Stride(id));
            }
            commands.Buffers[(int)FluidSurfaceBuffer.Particles].SetData(particles, 0, 0, count);
            var sceneColour = new RenderTexture(width, height, 0, RenderTextureFormat.ARGBHalf);
            var sceneDepth = new RenderTexture(width, height, 0, RenderTextureFormat.RFloat);
            var fluidColour = new RenderTexture(width, height, 0, RenderTextureFormat.ARGBHalf) { enableRandomWrite = true };
            sceneColour.Create();
            sceneDepth.Create();
            fluidColour.Create();
            try
            {
                commands.SetConstants(constants);
                foreach (int kernel in commands.Kernels)
                    for (int b = 0; b < bufferNames.Length; b++)
                        if (bufferNames[b] != null)
                            shader.SetBuffer(kernel, Shader.PropertyToID(bufferNames[b]), commands.Buffers[b]);
                int composite = commands.Kernels[(int)FluidSurfaceKernel.Composite];
                shader.SetTexture(composite, Shader.PropertyToID("_SceneColor"), sceneColour);
                shader.SetTexture(composite, Shader.PropertyToID("_SceneDepth"), sceneDepth);
                shader.SetTexture(composite, Shader.PropertyToID("_FluidColor"), fluidColour);
                GraphicsBuffer stats = commands.Buffers[(int)FluidSurfaceBuffer.Stats];
                StepCycleMeasure.Steps(() =>
                {
                    FluidSurfaceFrame.Record(ref commands, targets, passes, count);
                    AsyncGPUReadback.Request(stats).WaitForCompletion();
                }, () => { }, int.MaxValue, $"Fluid surface frame {tier}, {count} particles", 5, 20);
            }
            finally
            {
                foreach (GraphicsBuffer b in commands.Buffers)
                    b?.Release();
                commands.Constants.Release();
                commands.ConstantData.Dispose();
                sceneColour.Release();
                sceneDepth.Release();
                fluidColour.Release();
                particles.Dispose();
            }
        }
    }
}
#endif
