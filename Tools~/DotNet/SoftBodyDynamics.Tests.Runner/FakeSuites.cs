using System;
using System.Collections.Generic;
using System.Linq;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Tests.Runner
{
    /// <summary>A scenario with a known error and cost; its Setup throws when asked to, as a run cut off there would stop.</summary>
    sealed class FakeScenario : IScenario, IScenarioRepeatCap
    {
        readonly double m_Error;
        readonly bool m_Throw;
        int m_Steps;

        public FakeScenario(string method, int size, double error, bool throwOnSetup = false)
        {
            Method = method;
            Size = size;
            m_Error = error;
            m_Throw = throwOnSetup;
        }

        public string Name => "Fake";
        public string Method { get; }
        public int Size { get; }
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;
        public int MaxRepeats => 3;

        /// <summary>How many times Setup ran.</summary>
        public int Setups;

        public void Setup()
        {
            Setups++;
            if (m_Throw)
                throw new InvalidOperationException("the run stops here");
        }

        public void Step() => m_Steps++;

        public IReadOnlyList<Metric> Evaluate() => new[]
        {
            new Metric("err", m_Error, MetricUnit.Fraction),
            new Metric("tip", 0.25, MetricUnit.Metre),
            new Metric("resets", 0, MetricUnit.Count),
        };
    }

    /// <summary>The fake suite as one whose scenarios share nothing: set up in the preparation step, evaluated on threads.</summary>
    sealed class IndependentFakeSuite : IScenarioSuite, IScenarioSuiteIndependent
    {
        readonly FakeSuite m_Inner;
        public IndependentFakeSuite(string name, params IScenario[] scenarios) { m_Inner = new FakeSuite(name, scenarios); }
        public string Name => m_Inner.Name;
        public SuiteDefinition Definition => m_Inner.Definition;
        public string ErrorMetricForPlot => m_Inner.ErrorMetricForPlot;
        public IEnumerable<IScenario> Scenarios(RunScope scope) => m_Inner.Scenarios(scope);
    }

    /// <summary>A suite of fake scenarios that reports one accuracy finding (cost: µs per step of the body, as the method study counts it).</summary>
    sealed class FakeSuite : IScenarioSuite, IScenarioSuiteFindings
    {
        readonly IScenario[] m_Scenarios;

        public FakeSuite(string name, params IScenario[] scenarios)
        {
            Name = name;
            m_Scenarios = scenarios;
        }

        public string Name { get; }

        public SuiteDefinition Definition => new SuiteDefinition
        {
            Purpose = "What a fake body costs.",
            Body = "a fake body",
            Material = "none",
            Load = "none",
            Reference = "a made-up error",
            Metric = "err: the made-up error",
        };

        public string ErrorMetricForPlot => "err";

        public IEnumerable<IScenario> Scenarios(RunScope scope) => scope == RunScope.Quick ? m_Scenarios.Take(1) : m_Scenarios;

        public IEnumerable<Finding> Findings(IReadOnlyList<ScenarioOutcome> rows, RunScope scope)
        {
            yield return AccuracyFinding.FromRows("Fake scene", "err", "err", rows, AccuracyFinding.RelativeThresholds,
                r => r.NsPerItem * r.Size * 1e-6, r => r.Method, "ms/frame");
        }
    }
}
