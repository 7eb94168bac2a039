using System;
using System.IO;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Lavapipe
{
    /// <summary>
    /// The screen-space fluid passes (Shaders/FluidSurface.compute) on lavapipe, recorded by the same
    /// <see cref="FluidSurfaceFrame"/> and <see cref="FluidSurfacePassList"/> as Unity's renderer feature. The scene comes in and the fluid colour goes out
    /// as structured buffers (SBD_SCREEN_BUFFERS), everything between is the kernels Unity runs.
    /// </summary>
    public sealed class LavapipeFluidSurface : IDisposable, IFluidSurfaceCommands
    {
        /// <summary>What one frame produced, read back from the device.</summary>
        public sealed class Frame
        {
            public FluidSurfaceConstants Constants;
            public FluidSurfaceTargets Targets;
            /// <summary>The passes the frame ran; a target whose pass is off holds nothing meaningful.</summary>
            public FluidSurfacePassList Passes;
            /// <summary>Compute dispatches recorded for the frame (the last attempt's, when the tile list grew).</summary>
            public int Dispatches;
            /// <summary>Depth straight from the splat (m, 0 = no fluid), per depth pixel.</summary>
            public float[] RawDepth;
            /// <summary>Depth after smoothing.</summary>
            public float[] Depth;
            public float2[] Thickness;
            public uint[] Normals;
            /// <summary>rgb fluid colour and coverage per composite pixel (Targets.Composite: the screen, or half of it each way).</summary>
            public float4[] Colour;
            public uint[] Stats;
            /// <summary>Device milliseconds of the splats (tile lists included), the smoothing, and normals + composite.</summary>
            public double SplatMs, SmoothMs, ShadeMs;
            public double TotalMs => SplatMs + SmoothMs + ShadeMs;

            /// <summary>The fluid over the scene as the overlay draws it (upsampled when the composite is at half resolution).</summary>
            public float4[] Over(ReadOnlySpan<float4> scene) =>
                Imaging.RenderImage.Over(Colour, Targets.Composite.x, Targets.Composite.y, scene, Targets.Screen.x, Targets.Screen.y);
        }

        readonly LavapipeDevice m_Device;
        readonly LavapipeComputeShader m_Shader;
        readonly LavapipeBuffer[] m_Buffers = new LavapipeBuffer[Enum.GetValues(typeof(FluidSurfaceBuffer)).Length];
        LavapipeBuffer m_SceneColour, m_SceneDepth, m_FluidColour;
        readonly int[] m_Kernels;
        int m_Dispatches;

        /// <summary>Tile entries the buffers hold; grown when a frame needs more.</summary>
        public int TileCapacity { get; private set; }
        /// <summary>Whether a frame whose tile entries do not fit grows the list and redoes its splats (default), or keeps what fit.</summary>
        public bool GrowTileLists { get; set; } = true;
        /// <summary>Times the tile list was grown and the frame's splats redone.</summary>
        public int Regrowths { get; private set; }
        /// <summary>Whether each frame starts with +∞ in the thickness target (tests: a pass that is off leaves nothing a kernel may read).</summary>
        public bool PoisonThickness { get; set; }

        public LavapipeFluidSurface(LavapipeDevice device, int initialTileCapacity = 4096)
        {
            m_Device = device;
            m_Shader = new LavapipeComputeShader(device, ComputePath(), "SBD_SCREEN_BUFFERS=1");
            var names = Enum.GetNames(typeof(FluidSurfaceKernel));
            m_Kernels = new int[names.Length];
            for (int i = 0; i < names.Length; i++)
                m_Kernels[i] = m_Shader.FindKernel(names[i]);
            TileCapacity = initialTileCapacity;
        }

        public LavapipeComputeShader Shader => m_Shader;

        /// <summary>Shaders/FluidSurface.compute of the package this harness runs from.</summary>
        public static string ComputePath() =>
            Path.Combine(Path.GetDirectoryName(LavapipeFluidSolver.ComputePath()), "FluidSurface.compute");

        public void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer) =>
            m_Shader.SetBuffer(m_Kernels[(int)kernel], FluidSurfaceLayout.DepthSlotNames[(int)slot], m_Buffers[(int)buffer]);

        public void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY)
        {
            m_Dispatches++;
            m_Shader.Dispatch(m_Kernels[(int)kernel], groupsX, groupsY);
        }

        public void SetConstants(in FluidSurfaceConstants constants) => m_Shader.SetConstantBuffer(FluidSurfaceConstants.BufferName, constants);

        void Allocate(in FluidSurfaceTargets t, int particles, int screenPixels)
        {
            DisposeBuffers();
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                var buffer = (FluidSurfaceBuffer)b;
                m_Buffers[b] = m_Device.CreateBuffer((long)FluidSurfaceLayout.Stride(buffer) * FluidSurfaceLayout.Length(buffer, t, particles, TileCapacity));
            }
            m_SceneColour = m_Device.CreateBuffer(16L * screenPixels);
            m_SceneDepth = m_Device.CreateBuffer(4L * screenPixels);
            m_FluidColour = m_Device.CreateBuffer(16L * screenPixels);
            foreach (int k in m_Kernels)
            {
                for (int b = 0; b < FluidSurfaceLayout.BufferNames.Length; b++)
                    if (FluidSurfaceLayout.BufferNames[b] != null)
                        m_Shader.SetBuffer(k, FluidSurfaceLayout.BufferNames[b], m_Buffers[b]);
                m_Shader.SetBuffer(k, "_SceneColor", m_SceneColour);
                m_Shader.SetBuffer(k, "_SceneEyeDepth", m_SceneDepth);
                m_Shader.SetBuffer(k, "_FluidColor", m_FluidColour);
            }
        }

        /// <summary>
        /// Renders <paramref name="particles"/> (xyz world position, w attribute) over the scene (linear colour and eye
        /// depth per screen pixel, row 0 at the bottom) and reads every target back.
        /// </summary>
        public Frame Render(in FluidSurfaceCamera camera, in FluidSurfaceSettings settings, in FluidLook look, in FluidSurfaceLighting lighting,
            ReadOnlySpan<float4> particles, ReadOnlySpan<float4> sceneColour, ReadOnlySpan<float> sceneEyeDepth)
        {
            FluidSurfaceTargets t = FluidSurfaceTargets.Of(camera, settings);
            int screenPixels = t.Screen.x * t.Screen.y;
            if (sceneColour.Length != screenPixels || sceneEyeDepth.Length != screenPixels)
                throw new ArgumentException($"the scene must have {screenPixels} pixels");
            var frame = new Frame { Targets = t, Passes = FluidSurfacePassList.Of(settings, look) };
            LavapipeFluidSurface self = this;
            for (int attempt = 0; ; attempt++)
            {
                Allocate(t, particles.Length, screenPixels);
                particles.CopyTo(m_Buffers[(int)FluidSurfaceBuffer.Particles].As<float4>());
                sceneColour.CopyTo(m_SceneColour.As<float4>());
                sceneEyeDepth.CopyTo(m_SceneDepth.As<float>());
                if (PoisonThickness)
                    m_Buffers[(int)FluidSurfaceBuffer.Thickness].As<float2>().Fill(new float2(float.PositiveInfinity));
                frame.Constants = FluidSurfaceConstants.Of(camera, settings, look, lighting, particles.Length, TileCapacity);
                SetConstants(frame.Constants);
                m_Dispatches = 0;
                FluidSurfaceFrame.RecordSplats(ref self, t, frame.Passes, particles.Length);
                frame.SplatMs = m_Shader.Submit();
                frame.Stats = m_Buffers[(int)FluidSurfaceBuffer.Stats].As<uint>().ToArray();
                int needed = (int)frame.Stats[FluidSurfaceLayout.StatEntries];
                if (needed <= TileCapacity || attempt > 0 || !GrowTileLists)
                    break;
                // What Unity's feature does a frame later from the read-back: grow to the next power of two.
                TileCapacity = (int)System.Numerics.BitOperations.RoundUpToPowerOf2((uint)needed);
                Regrowths++;
            }
            frame.RawDepth = m_Buffers[(int)FluidSurfaceBuffer.DepthA].As<float>().Slice(0, t.Depth.x * t.Depth.y).ToArray();
            FluidSurfaceBuffer smoothed = FluidSurfaceFrame.RecordSmoothing(ref self, t, frame.Passes);
            frame.SmoothMs = m_Shader.Recorded > 0 ? m_Shader.Submit() : 0.0;
            FluidSurfaceFrame.RecordShading(ref self, t, frame.Passes, smoothed);
            frame.ShadeMs = m_Shader.Submit();
            frame.Dispatches = m_Dispatches;
            frame.Depth = m_Buffers[(int)smoothed].As<float>().Slice(0, t.Depth.x * t.Depth.y).ToArray();
            frame.Thickness = m_Buffers[(int)FluidSurfaceBuffer.Thickness].As<float2>().Slice(0, t.Thickness.x * t.Thickness.y).ToArray();
            frame.Normals = m_Buffers[(int)FluidSurfaceBuffer.Normals].As<uint>().Slice(0, t.Depth.x * t.Depth.y).ToArray();
            frame.Colour = m_FluidColour.As<float4>().Slice(0, t.Composite.x * t.Composite.y).ToArray();
            return frame;
        }

        void DisposeBuffers()
        {
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                m_Buffers[b]?.Dispose();
                m_Buffers[b] = null;
            }
            m_SceneColour?.Dispose();
            m_SceneDepth?.Dispose();
            m_FluidColour?.Dispose();
            m_SceneColour = m_SceneDepth = m_FluidColour = null;
        }

        public void Dispose()
        {
            DisposeBuffers();
            m_Shader.Dispose();
        }
    }
}
