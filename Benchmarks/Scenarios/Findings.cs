using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>The three promises the report's summary answers first.</summary>
    public enum Promise
    {
        /// <summary>What accuracy costs in time: the cheapest setting that reaches an error.</summary>
        AccuracyCost,
        /// <summary>Hard cases: how many a method or solver passes.</summary>
        HardCases,
        /// <summary>What an effect costs per frame.</summary>
        Effects,
    }

    /// <summary>One line of the report's summary, contributed by a suite (<see cref="IScenarioSuiteFindings"/>).</summary>
    public abstract class Finding
    {
        /// <summary>The promise this line answers.</summary>
        public abstract Promise Promise { get; }
    }

    /// <summary>The cheapest setting that reaches a threshold of one scene's error, or that none did.</summary>
    public readonly struct ThresholdReach
    {
        /// <summary>The threshold, in the error's unit (a fraction for relative errors).</summary>
        public readonly double Threshold;
        /// <summary>Method and setting of the cheapest row within the threshold; null when no row reached it.</summary>
        public readonly string Setting;
        /// <summary>Its cost in <see cref="AccuracyFinding.CostUnit"/>; +∞ when not reached.</summary>
        public readonly double Cost;

        public ThresholdReach(double threshold, string setting, double cost)
        {
            Threshold = threshold;
            Setting = setting;
            Cost = cost;
        }

        public bool Reached => Setting != null;
    }

    /// <summary>What accuracy costs on one scene: per threshold the cheapest setting that reaches it, and the best error seen.</summary>
    public sealed class AccuracyFinding : Finding
    {
        public override Promise Promise => Promise.AccuracyCost;
        /// <summary>Scene, e.g. "Cantilever".</summary>
        public string Scene;
        /// <summary>The error judged, in words (e.g. "worst of tip sag and frequency").</summary>
        public string Error;
        /// <summary>The metric the error is (the suite's figure is linked when it plots this metric).</summary>
        public string Metric;
        /// <summary>Unit of the error and the thresholds.</summary>
        public MetricUnit ErrorUnit = MetricUnit.Fraction;
        /// <summary>Unit of <see cref="ThresholdReach.Cost"/>, e.g. "ms per 1/60 s frame".</summary>
        public string CostUnit;
        /// <summary>One entry per threshold, loosest first.</summary>
        public IReadOnlyList<ThresholdReach> Reaches;
        /// <summary>The smallest error any row reached (NaN when every row diverged) and the row's setting.</summary>
        public double BestError = double.NaN;
        public string BestSetting;

        /// <summary>The error thresholds of the summary for relative errors: 20 %, 5 %, 1 %.</summary>
        public static readonly double[] RelativeThresholds = { 0.20, 0.05, 0.01 };

        /// <summary>
        /// A finding from rows: per threshold the cheapest row whose <paramref name="error"/> is within it; rows with a NaN error
        /// (diverged) never count.
        /// </summary>
        public static AccuracyFinding FromRows(string scene, string errorText, string metric, IReadOnlyList<ScenarioOutcome> rows, double[] thresholds,
            System.Func<ScenarioOutcome, double> cost, System.Func<ScenarioOutcome, string> setting, string costUnit,
            MetricUnit errorUnit = MetricUnit.Fraction)
        {
            double error(ScenarioOutcome r) => r.Value(metric);
            var reaches = new List<ThresholdReach>();
            foreach (double t in thresholds)
            {
                string best = null;
                double bestCost = double.PositiveInfinity;
                foreach (ScenarioOutcome r in rows)
                {
                    double e = error(r), c = cost(r);
                    if (e <= t && c < bestCost)
                    {
                        bestCost = c;
                        best = setting(r);
                    }
                }
                reaches.Add(new ThresholdReach(t, best, bestCost));
            }
            double bestError = double.NaN;
            string bestSetting = null;
            foreach (ScenarioOutcome r in rows)
            {
                double e = error(r);
                if (double.IsFinite(e) && !(e >= bestError))
                {
                    bestError = e;
                    bestSetting = setting(r);
                }
            }
            return new AccuracyFinding
            {
                Scene = scene, Error = errorText, Metric = metric, ErrorUnit = errorUnit, CostUnit = costUnit, Reaches = reaches,
                BestError = bestError, BestSetting = bestSetting,
            };
        }
    }

    /// <summary>How many hard cases one method or solver passed.</summary>
    public sealed class HardCaseFinding : Finding
    {
        public override Promise Promise => Promise.HardCases;
        /// <summary>"Soft bodies" or "Fluids".</summary>
        public string Group;
        /// <summary>Method or solver.</summary>
        public string Method;
        public int Passed, Total;
        /// <summary>The cases not passed, with what happened (e.g. "huge step: diverged").</summary>
        public IReadOnlyList<string> Failed;
        /// <summary>When a case counts as passed, in words (the same for a whole group).</summary>
        public string Criterion;
    }

    /// <summary>What one effect costs per frame, measured with and without it.</summary>
    public sealed class EffectFinding : Finding
    {
        public override Promise Promise => Promise.Effects;
        /// <summary>The effect, e.g. "flocking cohesion".</summary>
        public string Effect;
        /// <summary>The cost as the summary prints it, with the scene it was measured on.</summary>
        public string Cost;
    }

    /// <summary>The effects a scene can call for, by the names the summary lists them under.</summary>
    public static class EffectNames
    {
        public const string ShapeMatchingBody = "Shape-matching body";
        public const string MassSpringBody = "Mass-spring body";
        public const string FemBody = "FEM body";
        public const string Fluid = "Fluid (SPH)";
        public const string FlockingCohesion = "Flocking cohesion (fluid)";
        public const string AkinciCohesion = "Akinci cohesion and curvature (fluid)";
        public const string FluidViscosity = "Implicit viscosity (fluid)";
        public const string FluidColliders = "Colliders (fluid)";
        public const string FluidCollidersOutOfReach = "Colliders out of the fluid's reach";
        public const string SoftBodyCollisions = "Colliders (soft body)";
        public const string Plasticity = "Plasticity (shape matching)";
        public const string FluidSoftBodyCoupling = "Fluid ↔ soft body coupling";
        public const string SoftSoftContacts = "Soft ↔ soft contacts";
        public const string FluidRenderer = "Screen-space fluid renderer (GPU)";
        public const string RendererSmoothing = "Depth smoothing (fluid renderer)";
        public const string RendererThickness = "Thickness pass (fluid renderer)";
        public const string RendererNormals = "Normals pass (fluid renderer)";
        public const string RendererFullResolution = "Full-resolution depth and composite (fluid renderer)";
    }

    /// <summary>A suite that contributes lines to the report's summary.</summary>
    public interface IScenarioSuiteFindings
    {
        /// <summary>The summary lines of the finished suite; the rows are in the order the suite yielded them.</summary>
        IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope);
    }
}
