using System;
using System.Collections.Generic;
using System.Linq;
using System.Threading.Tasks;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;

namespace SoftBodyDynamics.Tests.Runner
{
    /// <summary>
    /// The runner sets up and evaluates the scenarios of an <see cref="IScenarioSuiteIndependent"/> suite on worker threads; that
    /// must not change a single bit of any metric.
    /// </summary>
    public class ConcurrentEvaluationTests
    {
        static List<IReadOnlyList<Metric>> Serial(IReadOnlyList<IScenario> scenarios)
        {
            var metrics = new List<IReadOnlyList<Metric>>();
            foreach (IScenario s in scenarios)
            {
                s.Setup();
                s.Step();
                metrics.Add(s.Evaluate());
            }
            return metrics;
        }

        static List<IReadOnlyList<Metric>> Concurrent(IReadOnlyList<IScenario> scenarios)
        {
            var metrics = new IReadOnlyList<Metric>[scenarios.Count];
            var options = new ParallelOptions { MaxDegreeOfParallelism = Math.Max(2, scenarios.Count) };
            Parallel.For(0, scenarios.Count, options, k => scenarios[k].Setup());
            // As the runner does: the timed steps one at a time, then the evaluations on threads.
            foreach (IScenario s in scenarios)
                s.Step();
            Parallel.For(0, scenarios.Count, options, k => metrics[k] = scenarios[k].Evaluate());
            return metrics.ToList();
        }

        static void AssertSameBits(IReadOnlyList<IReadOnlyList<Metric>> a, IReadOnlyList<IReadOnlyList<Metric>> b, IReadOnlyList<IScenario> scenarios)
        {
            Assert.AreEqual(a.Count, b.Count);
            for (int k = 0; k < a.Count; k++)
            {
                Assert.AreEqual(a[k].Count, b[k].Count, scenarios[k].Method);
                for (int m = 0; m < a[k].Count; m++)
                {
                    Assert.AreEqual(a[k][m].Name, b[k][m].Name);
                    Assert.AreEqual(BitConverter.DoubleToInt64Bits(a[k][m].Value), BitConverter.DoubleToInt64Bits(b[k][m].Value),
                        $"{scenarios[k].Method}: {a[k][m].Name} = {a[k][m].Value} serially, {b[k][m].Value} on threads");
                }
            }
        }

        [Test]
        public void MethodStudy_EvaluatedOnThreads_GivesTheSerialBits()
        {
            var suite = new MethodStudySuite(new SquashScene());
            Assert.IsInstanceOf<IScenarioSuiteIndependent>(suite);
            List<IScenario> first = suite.Scenarios(RunScope.Quick).ToList();
            List<IScenario> second = suite.Scenarios(RunScope.Quick).ToList();
            Assert.That(first.Count, Is.GreaterThanOrEqualTo(2));
            AssertSameBits(Serial(first), Concurrent(second), first);
        }

        [Test]
        public void FluidAccuracy_SetUpAndEvaluatedOnThreads_GivesTheSerialBits()
        {
            var suite = new FluidAccuracySuite();
            Assert.IsInstanceOf<IScenarioSuiteIndependent>(suite);
            List<IScenario> first = suite.Scenarios(RunScope.Quick).ToList();
            List<IScenario> second = suite.Scenarios(RunScope.Quick).ToList();
            AssertSameBits(Serial(first), Concurrent(second), first);
        }

        /// <summary>
        /// The shape-matching studies share one lazily computed reference per family among their scenarios (locked): set up and
        /// evaluated on threads first, then again one at a time, every metric has the same bits.
        /// </summary>
        [Test]
        public void ShapeMatchingStudies_SetUpAndEvaluatedOnThreads_GiveTheSerialBits()
        {
            foreach (IScenarioSuite suite in new IScenarioSuite[] { new ShapeMatchingConvergenceSuite(), new ShapeMatchingFrameRateSuite() })
            {
                Assert.IsInstanceOf<IScenarioSuiteIndependent>(suite);
                List<IScenario> first = suite.Scenarios(RunScope.Quick).ToList();
                List<IScenario> second = suite.Scenarios(RunScope.Quick).ToList();
                Assert.That(first.Count, Is.GreaterThanOrEqualTo(2));
                List<IReadOnlyList<Metric>> concurrent = Concurrent(first);
                AssertSameBits(Serial(second), concurrent, first);
            }
        }

        [Test]
        public void StabilityStudy_SetUpOnThreads_GivesTheSerialBits()
        {
            var suite = new MethodStudyStabilitySuite();
            Assert.IsInstanceOf<IScenarioSuiteIndependent>(suite);
            // The two cheapest methods of the study: shape matching and XPBD springs.
            static List<IScenario> Pick(IEnumerable<IScenario> all) =>
                all.Where(s => s.Method.StartsWith("SM linear", StringComparison.Ordinal) || s.Method.StartsWith("MS XPBD", StringComparison.Ordinal)).ToList();
            List<IScenario> first = Pick(suite.Scenarios(RunScope.Quick));
            List<IScenario> second = Pick(suite.Scenarios(RunScope.Quick));
            Assert.AreEqual(2, first.Count);
            AssertSameBits(Serial(first), Concurrent(second), first);
        }
    }
}
