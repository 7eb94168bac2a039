using System;
using System.Collections.Generic;
using System.Diagnostics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One row of <see cref="EffectCostSuite"/>: one effect, timed in pairs. Each step runs the 1/60 s frame of the scene
    /// with the effect, then the same frame of the scene without it (<see cref="EffectScene"/>), each under its own
    /// stopwatch, so both are measured at the same moment of the run. Every timed frame does the same work (it starts from the
    /// same state), and the machine's interference only ever adds time, so the metrics are the fastest of each frame's times
    /// and their difference; ns per item is the pair's cost.
    /// </summary>
    public sealed class EffectScenario : IScenario, IScenarioRepeatCap
    {
        /// <summary>Metric names.</summary>
        public const string WithMs = "with (ms per frame, fastest)", WithoutMs = "without (ms per frame, fastest)", AddedMs = "added (ms per frame)";
        /// <summary>Timed pairs at most (a frame with fluid is tens of ms in managed code).</summary>
        public const int Repeats = 15;
        /// <summary>Pairs recorded at most; later pairs are timed by the harness but not recorded.</summary>
        public const int MaxPairs = 4096;
        /// <summary>Pairs left out: the first ones run while the harness warms up.</summary>
        public const int WarmupPairs = 2;

        readonly EffectCostSuite.Case m_Case;
        // Sized for every pair the harness can ask for (warm-up up to 0.5 s and the timed repeats), so Step never grows them.
        readonly List<double> m_With = new List<double>(MaxPairs), m_Without = new List<double>(MaxPairs);
        EffectScene m_SceneWith, m_SceneWithout;

        public EffectScenario(EffectCostSuite.Case effect) => m_Case = effect;

        public string Name => "EffectCost";
        public string Method => m_Case.Effect;
        /// <summary>Particles of the scene with the effect.</summary>
        public int Size { get; private set; }
        public string SizeUnit => "particles";
        /// <summary>One item is one pair of frames.</summary>
        public long ItemsPerStep => 1;
        public int MaxRepeats => Repeats;

        public void Setup()
        {
            m_SceneWith = m_Case.Build(true);
            m_SceneWithout = m_Case.Build(false);
            m_SceneWith.Start(m_Case.StartFrames);
            m_SceneWithout.Start(m_Case.StartFrames);
            Size = m_SceneWith.ParticleCount;
            m_With.Clear();
            m_Without.Clear();
        }

        public void Step()
        {
            long t0 = Stopwatch.GetTimestamp();
            m_SceneWith.Step();
            long t1 = Stopwatch.GetTimestamp();
            m_SceneWithout.Step();
            long t2 = Stopwatch.GetTimestamp();
            if (m_With.Count == MaxPairs)
                return;
            m_With.Add((t1 - t0) * 1e3 / Stopwatch.Frequency);
            m_Without.Add((t2 - t1) * 1e3 / Stopwatch.Frequency);
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            double with = Fastest(m_With), without = Fastest(m_Without);
            return new[]
            {
                new Metric(WithMs, with, MetricUnit.Millisecond),
                new Metric(WithoutMs, without, MetricUnit.Millisecond),
                new Metric(AddedMs, with - without, MetricUnit.Millisecond),
                new Metric("steps in the frame, with", m_SceneWith.LastBodySteps + m_SceneWith.LastFluidSubsteps, MetricUnit.Count),
                new Metric("steps in the frame, without", m_SceneWithout.LastBodySteps + m_SceneWithout.LastFluidSubsteps, MetricUnit.Count),
                new Metric("resets", m_SceneWith.Resets + m_SceneWithout.Resets, MetricUnit.Count),
            };
        }

        /// <summary>The smallest value after the first <see cref="WarmupPairs"/> (of all of them when there are no more); NaN when empty.</summary>
        public static double Fastest(List<double> values)
        {
            int skip = values.Count > WarmupPairs ? WarmupPairs : 0;
            double fastest = double.NaN;
            for (int i = skip; i < values.Count; i++)
                if (!(values[i] >= fastest))
                    fastest = values[i];
            return fastest;
        }
    }
}
