using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Experimental.Rendering;
using UnityEngine.Rendering;
using UnityEngine.Rendering.RenderGraphModule;
using UnityEngine.Rendering.Universal;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// Draws every registered fluid in view of a camera, per fluid: one compute pass "Fluid Surface" that runs
    /// Shaders/FluidSurface.compute (tile lists, splats, smoothing, normals, composite: the passes
    /// <see cref="FluidSurfacePassList"/> lists for the fluid's settings and look, recorded by <see cref="FluidSurfaceFrame"/>) into a half-float colour texture (screen-sized, or half of it each way in the
    /// mobile tier) with coverage in alpha, then one
    /// raster pass "Fluid Overlay" that blends that texture over the camera colour (Shaders/FluidOverlay.shader).
    /// The composite refracts and depth-tests against the camera's opaque colour and depth textures, so it runs after
    /// the skybox, before transparents. Render graph only: URP's Compatibility Mode (render graph off) is not supported,
    /// and there this pass draws nothing (URP warns that Execute is not implemented).
    /// Fluids are drawn one after another, each refracting the opaque scene only, not the fluids drawn before it.
    /// Single-pass XR is not supported: the kernels read the camera textures as 2D textures, not texture arrays.
    /// </summary>
    sealed class FluidSurfacePass : ScriptableRenderPass, IDisposable
    {
        // Compute pass data. Render graph pools these objects, so the arrays are allocated once per pooled instance.
        sealed class ComputeData
        {
            public ComputeShader Shader;
            public int[] Kernels;
            public FluidSurfaceConstants Constants;
            public FluidSurfaceTargets Targets;
            public FluidSurfacePassList Passes;
            public int Particles;
            public readonly BufferHandle[] Buffers = new BufferHandle[k_BufferCount];
            public readonly GraphicsBuffer[] Resolved = new GraphicsBuffer[k_BufferCount];
            public FluidSurfaceConstantBuffer ConstantBuffer;
            public TextureHandle SceneColor, SceneDepth, FluidColor;
        }

        sealed class OverlayData
        {
            public TextureHandle FluidColor;
            public Material Material;
        }

        static readonly int k_BufferCount = Enum.GetValues(typeof(FluidSurfaceBuffer)).Length;
        // The fluid colour covers the whole target (1:1, or half resolution sampled bilinearly): no scale, no offset.
        static readonly Vector4 k_ScaleBias = new Vector4(1f, 1f, 0f, 0f);

        // Per fluid, by its source object (the systems keep one per fluid for the fluid's lifetime).
        readonly Dictionary<FluidRenderSource, FluidSurfaceResources> m_Resources = new Dictionary<FluidRenderSource, FluidSurfaceResources>();
        readonly Dictionary<FluidRenderSource, string> m_ReportedProblems = new Dictionary<FluidRenderSource, string>();
        readonly List<FluidRenderSource> m_Stale = new List<FluidRenderSource>();
        // Every world's sources, collected once per camera frame.
        readonly List<FluidRenderSource> m_Sources = new List<FluidRenderSource>();
        readonly Plane[] m_Frustum = new Plane[FluidRenderVisibility.PlaneCount];
        FluidRendererSettings m_Settings;
        FluidSurfaceKernels m_Kernels;
        Material m_Overlay;
        Shader m_OverlayShader;
        bool m_LoggedMissingTextures, m_LoggedDownsampled, m_LoggedKernels, m_LoggedMaterial;

        public FluidSurfacePass()
        {
            renderPassEvent = RenderPassEvent.BeforeRenderingTransparents;
        }

        /// <summary>The settings the next recordings use (set by the feature each frame).</summary>
        public void Setup(FluidRendererSettings settings) => m_Settings = settings;

        public override void RecordRenderGraph(RenderGraph renderGraph, ContextContainer frameData)
        {
            if (m_Settings == null || !EnsureShaders())
                return;
            UniversalResourceData resources = frameData.Get<UniversalResourceData>();
            UniversalCameraData cameraData = frameData.Get<UniversalCameraData>();
            // Preview and reflection cameras get no fluid; render graph passes read the camera from the frame data.
            if ((cameraData.cameraType & (CameraType.Preview | CameraType.Reflection)) != 0)
                return;
            TextureHandle sceneColor = resources.cameraOpaqueTexture, sceneDepth = resources.cameraDepthTexture;
            if (!sceneColor.IsValid() || !sceneDepth.IsValid())
            {
                FluidRendererLog.WarnOnce(ref m_LoggedMissingTextures,
                    "the camera has no opaque or depth texture. Turn on Opaque Texture and Depth Texture in the URP asset (or on the camera); fluids are not drawn until then.");
                return;
            }
            Camera camera = cameraData.camera;
            if (camera == null)
                return;
            int width = cameraData.cameraTargetDescriptor.width, height = cameraData.cameraTargetDescriptor.height;
            if (width <= 0 || height <= 0)
                return;
            // The composite reads the scene one texel per screen pixel, so a downsampled opaque texture cannot be used.
            TextureDesc opaqueDesc = renderGraph.GetTextureDesc(sceneColor);
            if (opaqueDesc.width > 0 && opaqueDesc.height > 0 && (opaqueDesc.width != width || opaqueDesc.height != height))
            {
                FluidRendererLog.WarnOnce(ref m_LoggedDownsampled,
                    $"the opaque texture is {opaqueDesc.width} × {opaqueDesc.height} for a {width} × {height} camera target. Set Opaque Downsampling to None in the URP asset; fluids are not drawn until then.");
                return;
            }

            GeometryUtility.CalculateFrustumPlanes(camera, m_Frustum);
            FluidSurfaceLighting lighting = FluidUnityCamera.Lighting(RenderSettings.sun, m_Settings.skyZenith, m_Settings.skyHorizon);
            FluidSurfaceCamera fluidCamera = FluidUnityCamera.From(camera.worldToCameraMatrix, width, height, camera.fieldOfView, camera.nearClipPlane);
            // The camera depth texture holds device depth; this turns it back into eye depth (m) in the composite.
            float4 sceneDepthParams = FluidSurfaceConstants.ZBufferParams(camera.nearClipPlane, camera.farClipPlane, SystemInfo.usesReversedZBuffer);
            var frame = new Frame
            {
                Camera = fluidCamera,
                Lighting = lighting,
                SceneDepthParams = sceneDepthParams,
                SceneColor = sceneColor,
                SceneDepth = sceneDepth,
                Target = resources.activeColorTexture,
            };
            FluidRenderSources.CollectAll(m_Sources);
            foreach (FluidRenderSource source in m_Sources)
                if (FluidRenderVisibility.IsDrawn(source, m_Frustum))
                    RecordSource(renderGraph, source, frame);
            ReleaseUnregistered();
        }

        /// <summary>Releases the buffers of fluids that are no longer registered.</summary>
        void ReleaseUnregistered()
        {
            if (m_Resources.Count <= m_Sources.Count)
                return;
            m_Stale.Clear();
            foreach (FluidRenderSource source in m_Resources.Keys)
                if (!m_Sources.Contains(source))
                    m_Stale.Add(source);
            foreach (FluidRenderSource source in m_Stale)
            {
                m_Resources[source].Dispose();
                m_Resources.Remove(source);
                m_ReportedProblems.Remove(source);
            }
        }

        /// <summary>What every fluid of one camera's frame shares.</summary>
        struct Frame
        {
            public FluidSurfaceCamera Camera;
            public FluidSurfaceLighting Lighting;
            public float4 SceneDepthParams;
            public TextureHandle SceneColor, SceneDepth, Target;
        }

        void RecordSource(RenderGraph renderGraph, FluidRenderSource source, in Frame frame)
        {
            FluidSurfaceSettings settings = m_Settings.ToSettings(source.ParticleRadius, out string settingsProblems);
            FluidLook look = source.Look.Sanitized(out string lookProblems);
            ReportProblems(source, settingsProblems, lookProblems);

            FluidSurfaceTargets targets = FluidSurfaceTargets.Of(frame.Camera, settings);
            // The one list of passes this fluid runs: what the settings and the look call for, nothing else.
            FluidSurfacePassList passes = FluidSurfacePassList.Of(settings, look);
            FluidSurfaceResources buffers = ResourcesFor(source);
            buffers.Ensure(targets);
            FluidSurfaceConstants constants = FluidSurfaceConstants.Of(frame.Camera, settings, look, frame.Lighting, source.Count,
                buffers.TileCapacity, frame.SceneDepthParams, flipY: SystemInfo.graphicsUVStartsAtTop);

            // rgb fluid colour (linear, HDR), a coverage 0 or 1: premultiplied, written to every pixel by the composite; at
            // the composite's resolution (the screen's, or half of it each way, upsampled by the overlay).
            var colorDesc = new TextureDesc(targets.Composite.x, targets.Composite.y)
            {
                colorFormat = GraphicsFormat.R16G16B16A16_SFloat,
                enableRandomWrite = true,
                msaaSamples = MSAASamples.None,
                clearBuffer = false,
                name = "_FluidColor",
            };
            TextureHandle fluidColor = renderGraph.CreateTexture(colorDesc);

            using (IComputeRenderGraphBuilder builder = renderGraph.AddComputePass("Fluid Surface", out ComputeData data))
            {
                data.Shader = m_Kernels.Shader;
                data.Kernels = m_Kernels.Indices;
                data.Constants = constants;
                data.ConstantBuffer = buffers.Constants;
                data.Targets = targets;
                data.Passes = passes;
                data.Particles = source.Count;
                for (int b = 0; b < k_BufferCount; b++)
                {
                    var id = (FluidSurfaceBuffer)b;
                    bool particles = id == FluidSurfaceBuffer.Particles;
                    BufferHandle handle = renderGraph.ImportBuffer(particles ? source.Particles : buffers[id]);
                    data.Buffers[b] = builder.UseBuffer(handle, particles ? AccessFlags.Read : AccessFlags.ReadWrite);
                }
                data.SceneColor = frame.SceneColor;
                data.SceneDepth = frame.SceneDepth;
                data.FluidColor = fluidColor;
                builder.UseTexture(frame.SceneColor, AccessFlags.Read);
                builder.UseTexture(frame.SceneDepth, AccessFlags.Read);
                builder.UseTexture(fluidColor, AccessFlags.Write);
                // The counters it writes are read back outside the graph.
                builder.AllowPassCulling(false);
                builder.SetRenderFunc(static (ComputeData d, ComputeGraphContext context) => ExecuteCompute(d, context.cmd));
            }

            using (IRasterRenderGraphBuilder builder = renderGraph.AddRasterRenderPass("Fluid Overlay", out OverlayData data))
            {
                data.FluidColor = fluidColor;
                data.Material = m_Overlay;
                builder.UseTexture(fluidColor, AccessFlags.Read);
                builder.SetRenderAttachment(frame.Target, 0, AccessFlags.Write);
                builder.SetRenderFunc(static (OverlayData d, RasterGraphContext context) =>
                    Blitter.BlitTexture(context.cmd, d.FluidColor, k_ScaleBias, d.Material, 0));
            }

            if (buffers.PollStats(out int previousCapacity))
                FluidRendererLog.Warn($"a fluid of {source.Count} particles needed {buffers.LastEntries} tile entries, more than the {previousCapacity} allocated " +
                    $"({buffers.LastDropped} were not drawn); the tile list grows to {buffers.TileCapacity} entries from the next frame. " +
                    "Raise Initial Tile Capacity in the fluid renderer settings to avoid this.");
        }

        static void ExecuteCompute(ComputeData d, ComputeCommandBuffer cmd)
        {
            // Every named buffer on every kernel (a kernel ignores what it does not use), and the depth slots on a
            // default so no kernel ever runs with one unset; the recorder points them where each pass needs them.
            for (int b = 0; b < k_BufferCount; b++)
                d.Resolved[b] = d.Buffers[b];
            GraphicsBuffer depthA = d.Resolved[(int)FluidSurfaceBuffer.DepthA], depthB = d.Resolved[(int)FluidSurfaceBuffer.DepthB];
            foreach (int kernel in d.Kernels)
            {
                for (int b = 0; b < k_BufferCount; b++)
                    if (FluidShaderIds.Buffers[b] >= 0)
                        cmd.SetComputeBufferParam(d.Shader, kernel, FluidShaderIds.Buffers[b], d.Resolved[b]);
                cmd.SetComputeBufferParam(d.Shader, kernel, FluidShaderIds.DepthSlots[(int)FluidSurfaceDepthSlot.Depth], depthA);
                cmd.SetComputeBufferParam(d.Shader, kernel, FluidShaderIds.DepthSlots[(int)FluidSurfaceDepthSlot.DepthIn], depthA);
                cmd.SetComputeBufferParam(d.Shader, kernel, FluidShaderIds.DepthSlots[(int)FluidSurfaceDepthSlot.DepthOut], depthB);
            }

            // Only the composite reads the scene and writes the fluid colour.
            int composite = d.Kernels[(int)FluidSurfaceKernel.Composite];
            cmd.SetComputeTextureParam(d.Shader, composite, FluidShaderIds.SceneColor, d.SceneColor);
            cmd.SetComputeTextureParam(d.Shader, composite, FluidShaderIds.SceneDepth, d.SceneDepth);
            cmd.SetComputeTextureParam(d.Shader, composite, FluidShaderIds.FluidColor, d.FluidColor);

            var commands = new FluidSurfaceComputeCommands(cmd, d.Shader, d.Kernels, d.Resolved, d.ConstantBuffer);
            commands.SetConstants(d.Constants);
            FluidSurfaceFrame.Record(ref commands, d.Targets, d.Passes, d.Particles);
        }

        /// <summary>Finds the kernels and creates the overlay material for the current settings; false (logged once) when either fails.</summary>
        bool EnsureShaders()
        {
            ComputeShader compute = m_Settings.computeShader;
            Shader overlay = m_Settings.overlayShader;
            if (compute == null || overlay == null)
                return false;
            if (m_Kernels == null || m_Kernels.Shader != compute)
            {
                m_Kernels = FluidSurfaceKernels.Find(compute, out string missing);
                if (m_Kernels == null)
                {
                    FluidRendererLog.WarnOnce(ref m_LoggedKernels, $"the compute shader '{compute.name}' has no kernel '{missing}'; assign Shaders/FluidSurface.compute.");
                    return false;
                }
            }
            if (m_Overlay == null || m_OverlayShader != overlay)
            {
                CoreUtils.Destroy(m_Overlay);
                m_Overlay = CoreUtils.CreateEngineMaterial(overlay);
                m_OverlayShader = overlay;
                if (m_Overlay == null)
                {
                    FluidRendererLog.WarnOnce(ref m_LoggedMaterial, $"could not create the overlay material from '{overlay.name}'.");
                    return false;
                }
            }
            return true;
        }

        FluidSurfaceResources ResourcesFor(FluidRenderSource source)
        {
            if (!m_Resources.TryGetValue(source, out FluidSurfaceResources resources))
            {
                resources = new FluidSurfaceResources(m_Settings.initialTileCapacity);
                m_Resources.Add(source, resources);
            }
            return resources;
        }

        /// <summary>Logs a fluid's settings or look problems when they first appear or change, not every frame.</summary>
        void ReportProblems(FluidRenderSource source, string settingsProblems, string lookProblems)
        {
            string problems = lookProblems.Length == 0 ? settingsProblems
                : settingsProblems.Length == 0 ? lookProblems : settingsProblems + " " + lookProblems;
            m_ReportedProblems.TryGetValue(source, out string reported);
            if (problems == (reported ?? string.Empty))
                return;
            m_ReportedProblems[source] = problems;
            if (problems.Length > 0)
                FluidRendererLog.Warn($"a fluid of {source.Count} particles: {problems}");
        }

        /// <summary>Releases every GPU buffer and the overlay material.</summary>
        public void Dispose()
        {
            foreach (FluidSurfaceResources resources in m_Resources.Values)
                resources.Dispose();
            m_Resources.Clear();
            m_ReportedProblems.Clear();
            CoreUtils.Destroy(m_Overlay);
            m_Overlay = null;
            m_OverlayShader = null;
            m_Kernels = null;
        }
    }
}
