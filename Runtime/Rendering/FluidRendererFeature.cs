using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using UnityEngine;
using UnityEngine.Rendering.Universal;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// URP renderer feature that draws the fluids of every world's <see cref="FluidRenderSources"/> as smooth screen-space
    /// surfaces (<see cref="FluidSurfacePass"/>). Add it to the URP renderer, assign a <see cref="FluidRendererSettings"/>
    /// asset with both shaders, and turn on Opaque Texture and Depth Texture (Opaque Downsampling None) in the URP asset.
    /// Needs compute shaders with 256-thread groups and 6 buffers per kernel (<see cref="FluidSurfaceDevice"/>) and URP's
    /// render graph (Compatibility Mode is not supported). Cameras that see no fluid get no pass; preview and reflection
    /// cameras record nothing (the pass reads the camera type from <c>UniversalCameraData</c> in the render graph).
    /// </summary>
    public sealed class FluidRendererFeature : ScriptableRendererFeature
    {
        [Tooltip("The renderer's settings asset (Create > Soft Body Dynamics > Fluid Renderer Settings) with the FluidSurface compute shader and the FluidOverlay shader. Nothing is drawn without it.")]
        public FluidRendererSettings settings;

        FluidSurfacePass m_Pass;
        readonly Plane[] m_Frustum = new Plane[FluidRenderVisibility.PlaneCount];
        readonly List<FluidRenderSource> m_Sources = new List<FluidRenderSource>();
        bool m_LoggedCannotDraw;

        public override void Create()
        {
            // URP calls Create again on every inspector edit; the pass, and the GPU buffers it holds, are kept.
            m_Pass ??= new FluidSurfacePass();
        }

        public override void AddRenderPasses(ScriptableRenderer renderer, ref RenderingData renderingData)
        {
            if (settings == null || settings.computeShader == null || settings.overlayShader == null)
                return;
            if (!FluidSurfaceDevice.CanDraw(SystemInfo.supportsComputeShaders, SystemInfo.maxComputeWorkGroupSize,
                    SystemInfo.maxComputeBufferInputsCompute, out string reason))
            {
                FluidRendererLog.WarnOnce(ref m_LoggedCannotDraw, reason + "; fluids are not drawn.");
                return;
            }
            FluidRenderSources.CollectAll(m_Sources);
            if (!FluidRenderVisibility.AnyDrawn(renderingData.cameraData.camera, m_Frustum, m_Sources))
                return;
            m_Pass ??= new FluidSurfacePass();
            m_Pass.Setup(settings);
            // Color asks URP for the opaque copy the composite refracts, Depth for the scene depth it tests against.
            m_Pass.ConfigureInput(ScriptableRenderPassInput.Depth | ScriptableRenderPassInput.Color);
            renderer.EnqueuePass(m_Pass);
        }

        protected override void Dispose(bool disposing)
        {
            m_Pass?.Dispose();
            m_Pass = null;
        }
    }
}
