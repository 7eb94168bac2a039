using System;
using System.Collections.Generic;
using System.Diagnostics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One row of <see cref="RendererEffectCostSuite"/>: one renderer pass or tier, timed in pairs as
    /// <see cref="EffectScenario"/> times a simulation effect. Each step renders the frame whose pass list has it, then the
    /// frame whose list does not (<see cref="FluidSurfaceCpuFrame"/>: the C# reference passes on the CPU), each under its
    /// own stopwatch; a frame with no fluid to draw records nothing. The metrics are the fastest of each (the first
    /// <see cref="EffectScenario.WarmupPairs"/> left out), their difference, the fastest time of the kernels the frame
    /// with the pass dispatches more often than the other (the pass alone, timed inside the frame), the dispatches and
    /// the counted bytes per pixel of each list.
    /// </summary>
    public sealed class RendererEffectScenario : IScenario, IScenarioRepeatCap
    {
        public const string DispatchesWith = "dispatches, with", DispatchesWithout = "dispatches, without";
        public const string BytesWith = "counted B/px, with", BytesWithout = "counted B/px, without";
        /// <summary>NaN when both lists dispatch the same kernels (a change of resolution, not of passes).</summary>
        public const string PassMs = "the pass alone (ms per frame, fastest)";

        readonly RendererEffectCostSuite.Case m_Case;
        readonly int m_MaxRepeats;
        readonly List<double> m_With = new List<double>(EffectScenario.MaxPairs), m_Without = new List<double>(EffectScenario.MaxPairs);
        readonly List<double> m_Pass = new List<double>(EffectScenario.MaxPairs);
        readonly bool[] m_Extra = new bool[Enum.GetValues(typeof(FluidSurfaceKernel)).Length];
        bool m_AnyExtra;
        FluidSurfaceCpuFrame m_FrameWith, m_FrameWithout;

        public RendererEffectScenario(RendererEffectCostSuite.Case effect, int maxRepeats)
        {
            m_Case = effect;
            m_MaxRepeats = maxRepeats;
        }

        public string Name => RendererEffectCostSuite.SuiteName;
        public string Method => m_Case.Effect;
        /// <summary>Particles drawn by the frame with the pass.</summary>
        public int Size { get; private set; }
        public string SizeUnit => "particles";
        /// <summary>One item is one pair of frames.</summary>
        public long ItemsPerStep => 1;
        public int MaxRepeats => m_MaxRepeats;

        public void Setup()
        {
            m_FrameWith = m_Case.Build(true);
            m_FrameWithout = m_Case.Build(false);
            Size = m_FrameWith?.Scene.Particles.Length ?? 0;
            // One frame of each finds the kernels only the frame with the pass dispatches (or dispatches more often).
            m_FrameWith?.Render();
            m_FrameWithout?.Render();
            m_AnyExtra = false;
            for (int k = 0; k < m_Extra.Length; k++)
            {
                var kernel = (FluidSurfaceKernel)k;
                m_Extra[k] = m_FrameWith != null && m_FrameWith.DispatchesOf(kernel) > (m_FrameWithout?.DispatchesOf(kernel) ?? 0);
                m_AnyExtra |= m_Extra[k];
            }
            m_With.Clear();
            m_Without.Clear();
            m_Pass.Clear();
        }

        public void Step()
        {
            long t0 = Stopwatch.GetTimestamp();
            m_FrameWith?.Render();
            long t1 = Stopwatch.GetTimestamp();
            m_FrameWithout?.Render();
            long t2 = Stopwatch.GetTimestamp();
            if (m_With.Count == EffectScenario.MaxPairs)
                return;
            m_With.Add((t1 - t0) * 1e3 / Stopwatch.Frequency);
            m_Without.Add((t2 - t1) * 1e3 / Stopwatch.Frequency);
            if (!m_AnyExtra)
                return;
            double pass = 0;
            for (int k = 0; k < m_Extra.Length; k++)
                if (m_Extra[k])
                    pass += m_FrameWith.MillisecondsOf((FluidSurfaceKernel)k);
            m_Pass.Add(pass);
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            double with = EffectScenario.Fastest(m_With), without = EffectScenario.Fastest(m_Without);
            return new[]
            {
                new Metric(EffectScenario.WithMs, with, MetricUnit.Millisecond),
                new Metric(EffectScenario.WithoutMs, without, MetricUnit.Millisecond),
                new Metric(EffectScenario.AddedMs, with - without, MetricUnit.Millisecond),
                new Metric(PassMs, m_AnyExtra ? EffectScenario.Fastest(m_Pass) : double.NaN, MetricUnit.Millisecond),
                new Metric(DispatchesWith, m_FrameWith?.Dispatches ?? 0, MetricUnit.Count),
                new Metric(DispatchesWithout, m_FrameWithout?.Dispatches ?? 0, MetricUnit.Count),
                new Metric(BytesWith, Bytes(m_FrameWith), MetricUnit.Dimensionless),
                new Metric(BytesWithout, Bytes(m_FrameWithout), MetricUnit.Dimensionless),
            };
        }

        /// <summary>Counted bytes per screen pixel of the frame's pass list; 0 for no frame.</summary>
        static double Bytes(FluidSurfaceCpuFrame frame) => frame == null ? 0 : FluidSurfaceCost.BytesPerPixel(frame.Passes);
    }
}
