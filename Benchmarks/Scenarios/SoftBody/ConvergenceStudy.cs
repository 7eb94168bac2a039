using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One mode and cluster layout of the convergence suite, shared by its rows (one per substep count): the
    /// released body (<see cref="ConvergenceRelease"/>), its float64 reference computed once at two RK4 steps
    /// (the finer one is the reference; the change between them bounds its error), and the solver's error at each
    /// substep count, computed on first use.
    /// </summary>
    public sealed class ConvergenceStudy
    {
        /// <summary>Particles per edge of the test body.</summary>
        public const int Edge = 6;
        /// <summary>Side of the test body (m).</summary>
        public const float BodySize = 0.5f;
        /// <summary>Seed of the jitter.</summary>
        public const uint Seed = 2024u;
        /// <summary>RK4 steps per frame of the coarser reference run (the finer has twice as many).</summary>
        public const int ReferenceStepsPerFrame = 16;

        public readonly ShapeMatchingMode Mode;
        public readonly ShapeMatchingClusterLayout Layout;
        public readonly ConvergenceRelease Release;
        readonly int m_ReferenceSteps;
        Vector3d[][] m_Reference, m_CoarseReference;
        double m_ReferenceChange = double.NaN;
        readonly Dictionary<int, double> m_Errors = new Dictionary<int, double>();
        readonly Dictionary<int, int> m_Resets = new Dictionary<int, int>();
        readonly Dictionary<int, FreeOscillationResult> m_Oscillations = new Dictionary<int, FreeOscillationResult>();
        double[] m_Mode;
        bool m_ModeSearched;
        /// <summary>Guards the lazily computed members: scenarios of one study may be evaluated on different threads.</summary>
        readonly object m_Lock = new object();

        static readonly Dictionary<(ShapeMatchingMode, ShapeMatchingClusterLayout, int), ConvergenceStudy> s_Studies =
            new Dictionary<(ShapeMatchingMode, ShapeMatchingClusterLayout, int), ConvergenceStudy>();

        /// <summary>The shared study of a mode and layout (references are computed once per process).</summary>
        public static ConvergenceStudy For(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout, int referenceStepsPerFrame = ReferenceStepsPerFrame)
        {
            var key = (mode, layout, referenceStepsPerFrame);
            lock (s_Studies)
            {
                if (!s_Studies.TryGetValue(key, out ConvergenceStudy study))
                    s_Studies[key] = study = new ConvergenceStudy(mode, layout, referenceStepsPerFrame);
                return study;
            }
        }

        public ConvergenceStudy(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout, int referenceStepsPerFrame = ReferenceStepsPerFrame)
        {
            Mode = mode;
            Layout = layout;
            m_ReferenceSteps = referenceStepsPerFrame;
            ShapeMatchingModelData model = ShapeMatchingBenchmarkBody.Lattice(Edge, BodySize, layout, mode);
            ShapeMatchingParameters p = ShapeMatchingBenchmarkBody.Parameters(mode, 1, float3.zero,
                ShapeMatchingBenchmarkBody.ParticleRadius(Edge, BodySize));
            Release = new ConvergenceRelease(model, p, ShapeMatchingBenchmarkBody.Spacing(Edge, BodySize), Seed);
        }

        /// <summary>The reference trajectory (RK4 at 2 × <see cref="ReferenceStepsPerFrame"/> steps per frame).</summary>
        public Vector3d[][] Reference
        {
            get
            {
                lock (m_Lock)
                {
                    if (m_Reference == null)
                    {
                        m_CoarseReference = Release.ReferenceTrajectory(m_ReferenceSteps);
                        m_Reference = Release.ReferenceTrajectory(2 * m_ReferenceSteps);
                        m_ReferenceChange = Release.Error(m_CoarseReference, m_Reference);
                    }
                    return m_Reference;
                }
            }
        }

        /// <summary>The reference at half the RK4 steps (<see cref="ReferenceStepsPerFrame"/> per frame), for Richardson checks.</summary>
        public Vector3d[][] CoarseReference
        {
            get
            {
                _ = Reference;
                return m_CoarseReference;
            }
        }

        /// <summary>
        /// RMS change (over the size) of the reference trajectory when its RK4 step is halved: an upper bound of its own
        /// error (for a 4th-order method the finer run's error is about 1/15 of it).
        /// </summary>
        public double ReferenceChange
        {
            get
            {
                _ = Reference;
                return m_ReferenceChange;
            }
        }

        /// <summary>The solver's trajectory error with <paramref name="substeps"/> substeps per 1/60 s frame.</summary>
        public double Error(int substeps)
        {
            lock (m_Lock)
            {
                if (!m_Errors.TryGetValue(substeps, out double e))
                {
                    m_Errors[substeps] = e = Release.Error(Release.SolverTrajectory(substeps, out int resets), Reference);
                    m_Resets[substeps] = resets;
                }
                return e;
            }
        }

        /// <summary>NaN-guard resets of the solver's trajectory with <paramref name="substeps"/> substeps (0 expected).</summary>
        public int Resets(int substeps)
        {
            lock (m_Lock)
            {
                Error(substeps);
                return m_Resets[substeps];
            }
        }

        /// <summary>Observed order of convergence between two substep counts: ln(e₁/e₂) / ln(n₂/n₁).</summary>
        public double ObservedOrder(int fewer, int more) =>
            Math.Log(Error(fewer) / Error(more)) / Math.Log((double)more / fewer);

        /// <summary>The body's <see cref="FullyResistedMode"/>, or null (quadratic goals on overlapping 4-plane clusters follow every x pattern).</summary>
        public double[] ResistedMode
        {
            get
            {
                lock (m_Lock)
                {
                    if (!m_ModeSearched)
                    {
                        m_Mode = FullyResistedMode.Find(Release.Model, Mode);
                        m_ModeSearched = true;
                    }
                    return m_Mode;
                }
            }
        }

        /// <summary>Free oscillation of the fully resisted mode at 1/60 s steps and <paramref name="substeps"/> substeps (null mode: Valid false).</summary>
        public FreeOscillationResult Oscillation(int substeps)
        {
            lock (m_Lock)
            {
                if (m_Oscillations.TryGetValue(substeps, out FreeOscillationResult r))
                    return r;
                if (ResistedMode != null)
                {
                    ShapeMatchingParameters p = Release.Parameters;
                    p.Body.Substeps = substeps;
                    r = FreeOscillation.Run(Release.Model, ResistedMode, p, ConvergenceRelease.FrameTime, float3.zero);
                }
                m_Oscillations[substeps] = r;
                return r;
            }
        }
    }
}
