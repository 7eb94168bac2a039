using System;
using System.Diagnostics;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One fluid's surface frame run by the C# reference passes on the CPU (<see cref="FluidSurfacePasses"/>,
    /// <see cref="FluidSurfaceComposite"/>): a recorder of <see cref="FluidSurfaceFrame"/> that runs the reference of each
    /// kernel it is asked to dispatch, so it follows the same <see cref="FluidSurfacePassList"/> as the URP and lavapipe
    /// frames. The reference builds no tile lists (each pixel tests every particle whose tile rectangle covers its tile),
    /// so the four tile-list dispatches are counted and do nothing; the overlay (a raster blend) is not run. The targets
    /// are allocated once; <see cref="Render"/> allocates nothing.
    /// </summary>
    public sealed class FluidSurfaceCpuFrame : IFluidSurfaceCommands
    {
        public readonly FluidSurfaceScene Scene;
        public readonly FluidSurfacePassList Passes;
        public readonly FluidSurfaceTargets Targets;
        public readonly FluidSurfaceConstants Constants;
        /// <summary>The two depth buffers of the smoothing ping-pong (depth pixels).</summary>
        public readonly float[] DepthA, DepthB;
        /// <summary>Thickness and mean attribute per thickness pixel; zeros when the list has no thickness splat.</summary>
        public readonly float2[] Thickness;
        /// <summary>Packed normal per depth pixel; zeros when the list has no normals pass.</summary>
        public readonly uint[] Normals;
        /// <summary>rgb fluid colour and coverage per composite pixel.</summary>
        public readonly float4[] Colour;

        readonly int4[] m_Rects;
        readonly float4[] m_Spheres;
        readonly int[] m_Covering;
        readonly FluidSurfaceBuffer[] m_Bound;
        readonly int[] m_Dispatches;
        readonly long[] m_Ticks;
        static readonly int s_Kernels = Enum.GetValues(typeof(FluidSurfaceKernel)).Length;
        static readonly int s_Slots = Enum.GetValues(typeof(FluidSurfaceDepthSlot)).Length;

        public FluidSurfaceCpuFrame(FluidSurfaceScene scene, in FluidSurfaceSettings settings, in FluidLook look)
        {
            Scene = scene;
            Passes = FluidSurfacePassList.Of(settings, look);
            Targets = FluidSurfaceTargets.Of(scene.Camera, settings);
            int n = scene.Particles.Length;
            FluidSurfaceConstants probe = FluidSurfaceConstants.Of(scene.Camera, settings, look, scene.Lighting, n, 1);
            Constants = FluidSurfaceConstants.Of(scene.Camera, settings, look, scene.Lighting, n, math.max(1, FluidSurfacePasses.TileEntries(probe, scene.Particles)));
            DepthA = new float[Targets.Depth.x * Targets.Depth.y];
            DepthB = new float[DepthA.Length];
            Thickness = new float2[Targets.Thickness.x * Targets.Thickness.y];
            Normals = new uint[DepthA.Length];
            Colour = new float4[Targets.Composite.x * Targets.Composite.y];
            m_Rects = new int4[n];
            m_Spheres = new float4[n];
            m_Covering = new int[n];
            m_Bound = new FluidSurfaceBuffer[s_Kernels * s_Slots];
            m_Dispatches = new int[s_Kernels];
            m_Ticks = new long[s_Kernels];
        }

        /// <summary>Compute dispatches of the last <see cref="Render"/>.</summary>
        public int Dispatches { get; private set; }

        /// <summary>Dispatches of <paramref name="kernel"/> in the last <see cref="Render"/>.</summary>
        public int DispatchesOf(FluidSurfaceKernel kernel) => m_Dispatches[(int)kernel];

        /// <summary>Milliseconds the reference of <paramref name="kernel"/> took in the last <see cref="Render"/> (all its dispatches).</summary>
        public double MillisecondsOf(FluidSurfaceKernel kernel) => m_Ticks[(int)kernel] * 1e3 / Stopwatch.Frequency;

        /// <summary>The buffer holding the smoothed depth the composite read.</summary>
        public float[] SmoothedDepth => FluidSurfaceFrame.SmoothedDepth(Passes) == FluidSurfaceBuffer.DepthB ? DepthB : DepthA;

        /// <summary>One frame: <see cref="FluidSurfaceFrame.Record"/> of the list against this recorder.</summary>
        public void Render()
        {
            Array.Clear(m_Dispatches, 0, m_Dispatches.Length);
            Array.Clear(m_Ticks, 0, m_Ticks.Length);
            Dispatches = 0;
            FluidSurfaceCpuFrame self = this;
            FluidSurfaceFrame.Record(ref self, Targets, Passes, Scene.Particles.Length);
        }

        /// <summary>Nothing to upload: the reference passes read <see cref="Constants"/>.</summary>
        public void SetConstants(in FluidSurfaceConstants constants) { }

        public void BindDepth(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot, FluidSurfaceBuffer buffer) =>
            m_Bound[(int)kernel * s_Slots + (int)slot] = buffer;

        public void Dispatch(FluidSurfaceKernel kernel, int groupsX, int groupsY)
        {
            m_Dispatches[(int)kernel]++;
            Dispatches++;
            long t0 = Stopwatch.GetTimestamp();
            Run(kernel);
            m_Ticks[(int)kernel] += Stopwatch.GetTimestamp() - t0;
        }

        void Run(FluidSurfaceKernel kernel)
        {
            ReadOnlySpan<float4> particles = Scene.Particles;
            switch (kernel)
            {
                case FluidSurfaceKernel.SplatDepth:
                    FluidSurfacePasses.SplatDepth(Constants, particles, Bound(kernel, FluidSurfaceDepthSlot.Depth), m_Rects, m_Spheres, m_Covering);
                    break;
                case FluidSurfaceKernel.SplatThickness:
                    FluidSurfacePasses.SplatThickness(Constants, particles, Thickness, m_Rects, m_Spheres, m_Covering);
                    break;
                case FluidSurfaceKernel.NarrowRangeX:
                case FluidSurfaceKernel.NarrowRangeY:
                case FluidSurfaceKernel.BilateralX:
                case FluidSurfaceKernel.BilateralY:
                    bool x = kernel == FluidSurfaceKernel.NarrowRangeX || kernel == FluidSurfaceKernel.BilateralX;
                    bool narrow = kernel == FluidSurfaceKernel.NarrowRangeX || kernel == FluidSurfaceKernel.NarrowRangeY;
                    FluidSurfacePasses.Separable(Constants, Bound(kernel, FluidSurfaceDepthSlot.DepthIn), Bound(kernel, FluidSurfaceDepthSlot.DepthOut),
                        x ? 1 : 0, x ? 0 : 1, narrow);
                    break;
                case FluidSurfaceKernel.CurvatureFlow:
                    FluidSurfacePasses.CurvatureFlow(Constants, Bound(kernel, FluidSurfaceDepthSlot.DepthIn), Bound(kernel, FluidSurfaceDepthSlot.DepthOut));
                    break;
                case FluidSurfaceKernel.Normals:
                    FluidSurfacePasses.Normals(Constants, Bound(kernel, FluidSurfaceDepthSlot.Depth), Normals);
                    break;
                case FluidSurfaceKernel.Composite:
                    FluidSurfaceComposite.Composite(Constants, new FluidSurfaceComposite.Inputs(Bound(kernel, FluidSurfaceDepthSlot.Depth), Normals, Thickness,
                        Scene.SceneColour, Scene.SceneEyeDepth), Colour);
                    break;
            }
        }

        float[] Bound(FluidSurfaceKernel kernel, FluidSurfaceDepthSlot slot) =>
            m_Bound[(int)kernel * s_Slots + (int)slot] == FluidSurfaceBuffer.DepthB ? DepthB : DepthA;
    }
}
