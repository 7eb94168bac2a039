using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Shape-matching accuracy against cost: volume, shape recovery and momentum for every mode, layout and substep count.</summary>
    public sealed class ShapeMatchingAccuracySuite : IScenarioSuite
    {
        /// <summary>Metric: max over 0–2 s of |det(A_pq A_qq⁻¹) − 1| of the whole squashed body (dimensionless).</summary>
        public const string MaxVolumeError = "max |det-1|";
        /// <summary>Metric: RMS distance from the best-fit rigid placement of the rest shape over the rest size, 1 s after release (dimensionless).</summary>
        public const string ShapeErrorAt1s = "shape err 1s";
        /// <summary>Metric: the same 2 s after release (dimensionless).</summary>
        public const string ShapeErrorAt2s = "shape err 2s";
        /// <summary>Metric: the largest shape error from 1 s to 2 s after release, the envelope of the remaining wobble (dimensionless).</summary>
        public const string MaxShapeErrorFrom1sTo2s = "max shape err 1-2s";
        /// <summary>Metric: max over 1000 steps of |P − P₀| / Σ m|v|₀ of the spinning blob (dimensionless).</summary>
        public const string MomentumDrift = "|dP|/sum m|v|";
        /// <summary>Metric: max over 1000 steps of |L − L₀| / |L₀| of the spinning blob (dimensionless).</summary>
        public const string AngularMomentumDrift = "|dL|/|L0|";
        /// <summary>Metric: NaN-guard resets in both tests (count; 0 expected).</summary>
        public const string Resets = "resets";

        /// <summary>Substep counts of the full run (the cost axis).</summary>
        public static readonly int[] SubstepCounts = { 1, 2, 4, 8 };
        /// <summary>Substep counts of the quick run.</summary>
        public static readonly int[] QuickSubstepCounts = { 1, 4 };

        public string Name => "ShapeMatchingAccuracy";

        public string Description =>
            "A 0.7 m cube of 8³ = 512 particles, default jelly parameters (α = 0.2, β = 0.5, damping 1/s), no gravity, " +
            "for each mode (rigid, linear, quadratic), cluster layout (1 cluster, or overlapping 4^3 clusters) and substep count " +
            "(1, 2, 4, 8; quick run: 1, 4). One item is one particle-step (one particle through a 1/60 s step, all substeps " +
            "included), so ns/item grows with the substep count. " +
            "Squash recovery: the body is squashed to half its height with x and z stretched by √2 (volume kept), released at " +
            "rest and followed for 2 s. '" + MaxVolumeError + "' is the largest |det(A_pq A_qq⁻¹) − 1| of the whole body after " +
            "any step. The shape error is the RMS distance of the particles from the rest shape placed at its best fit (centre " +
            "of mass, float64 SVD rotation) over the body size; the reference is the rest shape, the exact target of shape " +
            "matching, and the squash itself is ≈ 0.25. '" + ShapeErrorAt1s + "' and '" + ShapeErrorAt2s + "' sample it 1 s and " +
            "2 s after release; '" + MaxShapeErrorFrom1sTo2s + "' is its largest value from 1 s to 2 s, the envelope of the " +
            "remaining wobble (a single sample can fall near a zero crossing), and is the plotted error. " +
            "Spinning blob: the body, every particle jittered by ±20 % of the spacing, spins at 3 rad/s and drifts at 0.5 m/s with " +
            "±0.1 m/s of noise, for 1000 steps; '" + MomentumDrift + "' and '" + AngularMomentumDrift + "' are the largest drifts of " +
            "linear momentum (over the initial Σ m|v|) and of angular momentum about the centre of mass (over |L0|), which nothing " +
            "outside changes. 'resets' counts NaN-guard resets in both tests. All metrics are dimensionless; lower is better.";

        public string ErrorMetricForPlot => MaxShapeErrorFrom1sTo2s;

        public IEnumerable<IScenario> Scenarios(bool quick)
        {
            foreach (ShapeMatchingClusterLayout layout in new[] { ShapeMatchingClusterLayout.Single, ShapeMatchingClusterLayout.Overlapping })
            foreach (ShapeMatchingMode mode in new[] { ShapeMatchingMode.Rigid, ShapeMatchingMode.Linear, ShapeMatchingMode.Quadratic })
            foreach (int substeps in quick ? QuickSubstepCounts : SubstepCounts)
                yield return new ShapeMatchingAccuracyScenario(mode, layout, substeps);
        }
    }
}
