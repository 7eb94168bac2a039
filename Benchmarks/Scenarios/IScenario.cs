using System;
using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>A measured value a scenario reports beside its time (name, value, unit); for errors, lower is better.</summary>
    public readonly struct Metric
    {
        public readonly string Name;
        public readonly double Value;
        /// <summary>What <see cref="Value"/> is measured in; relative errors are <see cref="MetricUnit.Fraction"/>.</summary>
        public readonly MetricUnit Unit;

        public Metric(string name, double value, MetricUnit unit)
        {
            Name = name;
            Value = value;
            Unit = unit;
        }
    }

    /// <summary>
    /// A benchmark scenario shared by the headless runner (.NET) and the Unity Performance tests:
    /// a named workload, one method and one size. The harness calls <see cref="Setup"/>, then
    /// <see cref="Step"/> repeatedly (warm-up, then timed), then <see cref="Evaluate"/> for the
    /// error metrics. Scenarios own their data; Step must not allocate.
    /// </summary>
    public interface IScenario
    {
        /// <summary>Workload, e.g. "RotationExtraction".</summary>
        string Name { get; }
        /// <summary>Method and setting, e.g. "warm, ≤20 it".</summary>
        string Method { get; }
        /// <summary>Problem size in <see cref="SizeUnit"/>.</summary>
        int Size { get; }
        /// <summary>Unit of <see cref="Size"/> and of throughput, e.g. "matrices", "particles".</summary>
        string SizeUnit { get; }
        /// <summary>Work items per Step, for the time-per-item column (e.g. decompositions).</summary>
        long ItemsPerStep { get; }

        void Setup();
        void Step();
        IReadOnlyList<Metric> Evaluate();
    }

    /// <summary>A scenario whose steps take long enough that the harness times fewer of them than it would by default.</summary>
    public interface IScenarioRepeatCap
    {
        /// <summary>Most timed steps the harness runs for this scenario (≥ 1).</summary>
        int MaxRepeats { get; }
    }

    /// <summary>
    /// A scenario whose step is a whole run of many frames: the default and quick runs warm it up with a few frames of the same
    /// run (the first frame compiles the step and the rest fill the caches) instead of whole steps, as a long run amortises
    /// what is left of that cost over its frames.
    /// </summary>
    public interface IScenarioShortWarmup
    {
        /// <summary>Runs the first few frames of the step's run; the next <see cref="IScenario.Step"/> starts the run again from its initial state.</summary>
        void WarmupFrames();
    }

    /// <summary>
    /// A suite whose scenarios share no mutable state: the Setup and Evaluate of different scenarios may run at the same time
    /// on worker threads (each is single-threaded and gives the same bits either way). The runner still times their steps
    /// one at a time, with nothing else running.
    /// </summary>
    public interface IScenarioSuiteIndependent
    {
    }

    /// <summary>
    /// A suite with work every scenario needs and none of them times (a float64 reference): the runner calls
    /// <see cref="Prepare"/> for every such suite of the run before the first timed step, on worker threads.
    /// </summary>
    public interface IScenarioSuitePreparation
    {
        /// <summary>Does the shared work once; thread-safe, and cheap when done already.</summary>
        void Prepare();
    }

    /// <summary>
    /// A suite whose prepared work is a set of reference values that depend on its sources only: the runner may hand it the
    /// values an earlier run computed from the same sources (<see cref="UseReference"/>) in place of computing them again.
    /// </summary>
    public interface IScenarioSuiteStoredReference : IScenarioSuitePreparation
    {
        /// <summary>Type of the reference values: public fields of numbers, and arrays and structs of them.</summary>
        Type ReferenceType { get; }

        /// <summary>The reference values, computed on the first call.</summary>
        object Reference();

        /// <summary>Takes stored values of <see cref="ReferenceType"/> as the reference; <see cref="IScenarioSuitePreparation.Prepare"/> then has nothing left to do.</summary>
        void UseReference(object values);
    }

    /// <summary>Groups of scenarios the runner knows, with the figure each group plots.</summary>
    public interface IScenarioSuite
    {
        /// <summary>Suite name, used for the report section and figure file names.</summary>
        string Name { get; }
        /// <summary>What the suite measures and against which reference, printed under its table.</summary>
        SuiteDefinition Definition { get; }
        /// <summary>The scenarios a run of <paramref name="scope"/> covers, in table order.</summary>
        IEnumerable<IScenario> Scenarios(RunScope scope);
        /// <summary>The metric plotted against time per item in the accuracy-versus-cost figure; null for a suite without an error reference (no such figure).</summary>
        string ErrorMetricForPlot { get; }
    }

    /// <summary>One row of a finished suite, as a summary sees it.</summary>
    public readonly struct ScenarioOutcome
    {
        public readonly string Method;
        public readonly double NsPerItem;
        public readonly IReadOnlyList<Metric> Metrics;
        /// <summary>Problem size of the row (<see cref="IScenario.Size"/>); 0 when not given.</summary>
        public readonly int Size;
        /// <summary>Items per step of the row (<see cref="IScenario.ItemsPerStep"/>); 0 when not given.</summary>
        public readonly long ItemsPerStep;

        public ScenarioOutcome(string method, double nsPerItem, IReadOnlyList<Metric> metrics, int size = 0, long itemsPerStep = 0)
        {
            Method = method;
            NsPerItem = nsPerItem;
            Metrics = metrics;
            Size = size;
            ItemsPerStep = itemsPerStep;
        }

        /// <summary>The named metric, or NaN when the row does not report it.</summary>
        public double Value(string name)
        {
            foreach (Metric m in Metrics)
                if (m.Name == name)
                    return m.Value;
            return double.NaN;
        }
    }

    /// <summary>A suite that also writes a summary (Markdown) of all its rows, printed and added to the report after its table.</summary>
    public interface IScenarioSuiteSummary
    {
        /// <summary>Markdown: tables and sentences; the rows are in the order the suite yielded them.</summary>
        string Summary(IReadOnlyList<ScenarioOutcome> rows, RunScope scope);
    }

    /// <summary>
    /// A suite that says how its accuracy-versus-cost figure is drawn: which rows form a series (joined by a line in
    /// cost order), what labels the first and last point of a series, and what the cost axis is.
    /// </summary>
    public interface IScenarioSuiteFigure
    {
        /// <summary>The series a row belongs to (its legend entry).</summary>
        string Series(ScenarioOutcome row);
        /// <summary>The label of a row's point (drawn at the two ends of each series); rows of a series with the same label are one point.</summary>
        string PointLabel(ScenarioOutcome row);
        /// <summary>Title of the cost axis.</summary>
        string CostLabel { get; }
        /// <summary>A row's cost (the x value).</summary>
        double Cost(ScenarioOutcome row);
    }
}
