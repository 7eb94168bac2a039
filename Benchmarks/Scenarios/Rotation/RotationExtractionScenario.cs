using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>How a rotation-extraction scenario starts its iteration.</summary>
    public enum RotationStart
    {
        /// <summary>From the previous step's rotation (the optimum turned by up to 0.2 rad): the simulation's case.</summary>
        Warm,
        /// <summary>From identity: a new body, or a teleport.</summary>
        Cold,
    }

    /// <summary>
    /// Extracts the rotation of N seeded matrices from every hard-case family (see
    /// <see cref="RotationCases"/>) per step. Time per item is ns per decomposition. Errors are
    /// measured in float64 against the SVD reference.
    /// </summary>
    public sealed class RotationExtractionScenario : IScenario
    {
        readonly RotationStart m_Start;
        readonly int m_MaxIterations;
        readonly uint m_Seed;
        float3x3[] m_A;
        quaternion[] m_Start0;
        quaternion[] m_Q;
        int[] m_Iterations;

        public RotationExtractionScenario(int count, RotationStart start, int maxIterations, uint seed = 1234u)
        {
            Size = count;
            m_Start = start;
            m_MaxIterations = maxIterations;
            m_Seed = seed;
        }

        public string Name => "RotationExtraction";
        public string Method => $"{(m_Start == RotationStart.Warm ? "warm" : "cold")}, <={m_MaxIterations} it";
        public int Size { get; }
        public string SizeUnit => "matrices";
        public long ItemsPerStep => Size;

        public void Setup()
        {
            m_A = new float3x3[Size];
            m_Start0 = new quaternion[Size];
            m_Q = new quaternion[Size];
            m_Iterations = new int[Size];
            for (int i = 0; i < Size; i++)
            {
                RotationCase c = RotationCases.Make(RotationCases.SeedOf(m_Seed, i));
                m_A[i] = c.A;
                m_Start0[i] = m_Start == RotationStart.Warm ? c.WarmStart : quaternion.identity;
            }
        }

        public void Step()
        {
            // Every step starts from the same warm starts, so steps are identical work.
            for (int i = 0; i < m_A.Length; i++)
            {
                quaternion q = m_Start0[i];
                m_Iterations[i] = RotationExtraction.Extract(m_A[i], ref q, m_MaxIterations);
                m_Q[i] = q;
            }
        }

        public IReadOnlyList<Metric> Evaluate()
        {
            var gaps = new double[Size];
            double maxDet = 0, maxOrth = 0;
            int nonFinite = 0;
            for (int i = 0; i < Size; i++)
            {
                RotationError e = RotationMetrics.Evaluate(m_A[i], m_Q[i]);
                if (!e.Finite) { nonFinite++; gaps[i] = double.PositiveInfinity; continue; }
                maxDet = Math.Max(maxDet, e.Determinant);
                maxOrth = Math.Max(maxOrth, e.Orthonormality);
                gaps[i] = Math.Max(0.0, e.ObjectiveGap);
            }
            // Iterations of every case, a failed one included: it spent them too.
            var its = (int[])m_Iterations.Clone();
            Array.Sort(gaps);
            Array.Sort(its);
            double meanIt = 0;
            foreach (int it in its) meanIt += it;
            meanIt /= Math.Max(1, Size);
            return new[]
            {
                new Metric("non-finite", nonFinite, MetricUnit.Count),
                new Metric("max |det R - 1|", maxDet, MetricUnit.Dimensionless),
                new Metric("max orth err", maxOrth, MetricUnit.Dimensionless),
                new Metric("p99 gap", gaps[(int)(0.99 * (Size - 1))], MetricUnit.Fraction),
                new Metric("max gap", gaps[Size - 1], MetricUnit.Fraction),
                new Metric("mean it", meanIt, MetricUnit.Dimensionless),
                new Metric("p99 it", its[(int)(0.99 * (Size - 1))], MetricUnit.Count),
            };
        }
    }

    /// <summary>Rotation extraction: ns per decomposition against accuracy, for start and iteration cap.</summary>
    public sealed class RotationExtractionSuite : IScenarioSuite
    {
        public string Name => "RotationExtraction";

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What extracting the rotation of one cluster costs, and how close it comes to the optimal rotation, for warm and cold starts and each iteration cap.",
            Body = $"Seeded A = Σ m p qᵀ of {RotationCases.PointsPerCluster}-particle clusters from every hard-case family: rotated/stretched, random, mirrored, coplanar, " +
                   "collinear, coincident, flattened to ±1e-4; scales 1e-4…1e4.",
            Material = $"None: RotationExtraction.Extract on float32 input, up to the row's iteration cap ('<= N it'; default {RotationExtraction.DefaultMaxIterations}).",
            Load = $"'warm' starts from the previous step's rotation (the optimum turned by up to {RotationCases.WarmStartMaxAngle} rad), 'cold' from identity; " +
                   "every timed step starts again from the same starts.",
            Reference = "A float64 SVD with sign fix: the optimal proper rotation of each A.",
            Metric = "One item is one decomposition. 'gap' = (max tr(R'ᵀA) − tr(RᵀA)) / Σσ over proper rotations R', 0 at the optimum (p99 and max over the matrices); " +
                     "'orth err' = largest entry of |RᵀR − I|; 'it' = iterations taken (mean, p99).",
            Details = "shape-matching.md#benchmark-rotationextraction",
        };

        public string ErrorMetricForPlot => "p99 gap";

        public IEnumerable<IScenario> Scenarios(RunScope scope)
        {
            bool quick = scope == RunScope.Quick;
            int[] sizes = quick ? new[] { 1000, 10000 } : new[] { 1000, 10000, 100000 };
            foreach (int n in sizes)
                yield return new RotationExtractionScenario(n, RotationStart.Warm, RotationExtraction.DefaultMaxIterations);
            int accuracyN = 10000;
            foreach (int cap in new[] { 1, 2, 3, 5 })
                yield return new RotationExtractionScenario(accuracyN, RotationStart.Warm, cap);
            foreach (int cap in new[] { 5, 10, 20, 50 })
                yield return new RotationExtractionScenario(accuracyN, RotationStart.Cold, cap);
        }
    }
}
