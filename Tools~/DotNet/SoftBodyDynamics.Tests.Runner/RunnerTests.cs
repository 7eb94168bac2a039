using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Runner;

namespace SoftBodyDynamics.Tests.Runner
{
    public class RunOptionsTests
    {
        [Test]
        public void NoOption_IsTheStandardScope()
        {
            RunOptions o = RunOptions.Parse(new string[0], out string error);
            Assert.IsNull(error);
            Assert.AreEqual(RunScope.Standard, o.Scope);
        }

        [TestCase("--quick", RunScope.Quick)]
        [TestCase("--full", RunScope.Full)]
        public void ScopeFlags_SelectTheirScope(string flag, RunScope scope) =>
            Assert.AreEqual(scope, RunOptions.Parse(new[] { flag }, out _).Scope);

        [Test]
        public void QuickAndFull_Together_AreRefused()
        {
            Assert.IsNull(RunOptions.Parse(new[] { "--quick", "--full" }, out string error));
            StringAssert.Contains("exclude", error);
        }

        [Test]
        public void UnknownOption_IsRefusedByName()
        {
            Assert.IsNull(RunOptions.Parse(new[] { "--fast" }, out string error));
            StringAssert.Contains("--fast", error);
        }

        [Test]
        public void Help_IsRecognised_AndTheUsageListsEveryOption()
        {
            Assert.IsTrue(RunOptions.Parse(new[] { "--help" }, out _).Help);
            foreach (string option in new[] { "--quick", "--full", "--filter", "--method", "--out", "--repeats", "--help" })
                StringAssert.Contains(option, RunOptions.Usage);
        }
    }

    public class ProgressEstimateTests
    {
        [Test]
        public void NothingKnown_GivesNoEstimate()
        {
            var e = new ProgressEstimate(RunTimings.Empty(), new[] { "a", "b" });
            Assert.IsNull(e.SecondsLeft(0));
        }

        [Test]
        public void StepsNeverTimed_CostTheMeanOfThisRunsFinishedSteps()
        {
            var e = new ProgressEstimate(RunTimings.Empty(), new[] { "a", "b", "c", "d" });
            e.Finished(0, 2.0);
            e.Finished(1, 4.0);
            Assert.AreEqual(6.0, e.SecondsLeft(2).Value, 1e-12);
        }

        [Test]
        public void PreviousTimings_AreScaledByHowThisRunCompares()
        {
            string dir = TempDir();
            var previous = RunTimings.Empty();
            previous.Record("a", 10.0);
            previous.Record("b", 20.0);
            previous.Record("c", 30.0);
            previous.Save(dir);
            var e = new ProgressEstimate(RunTimings.Load(dir), new[] { "a", "b", "c" });
            Assert.AreEqual(60.0, e.SecondsLeft(0).Value, 1e-9);
            e.Finished(0, 5.0); // twice as fast as last time
            Assert.AreEqual(25.0, e.SecondsLeft(1).Value, 1e-9);
        }

        [Test]
        public void PreparationStep_IsLeftOutOfTheMeanOfUntimedSteps()
        {
            var e = new ProgressEstimate(RunTimings.Empty(), new[] { "prepare", "a", "b", "c" }, excludedFromMean: 0);
            e.Finished(0, 100.0);
            Assert.IsNull(e.SecondsLeft(1), "no ordinary step finished yet");
            e.Finished(1, 2.0);
            Assert.AreEqual(4.0, e.SecondsLeft(2).Value, 1e-12);
        }

        [Test]
        public void StepsNeverTimed_BeforeAnyMean_AreCountedApart()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sbd-estimate-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            var previous = RunTimings.Empty();
            previous.Record("b", 10.0);
            previous.Save(dir);
            var e = new ProgressEstimate(RunTimings.Load(dir), new[] { "new", "b", "also new" });
            Assert.AreEqual(10.0, e.SecondsLeft(0, out int unknown).Value, 1e-12);
            Assert.AreEqual(2, unknown);
            Assert.IsNull(e.SecondsLeft(0), "the total is not known");
        }

        [TestCase(0.0, "0:00")]
        [TestCase(59.4, "0:59")]
        [TestCase(61.0, "1:01")]
        [TestCase(3725.0, "1:02:05")]
        public void Clock_IsMinutesAndSeconds(double seconds, string text) => Assert.AreEqual(text, ProgressEstimate.Clock(seconds));

        static string TempDir()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sbd-runner-tests-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            return dir;
        }
    }

    public class RunTimingsTests
    {
        [Test]
        public void SaveThenLoad_KeepsKeysWithCommasAndQuotes()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sbd-timings-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            var t = RunTimings.Empty();
            string key = RunTimings.Key("Suite", "m, \"x\" (3 particles)");
            t.Record(key, 1.25);
            t.Save(dir);
            Assert.AreEqual(1.25, RunTimings.Load(dir).Previous(key).Value, 1e-12);
        }

        [Test]
        public void ReferenceTimings_FillWhatThePreviousRunDidNotTime_AndThePreviousRunWins()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sbd-timings-" + Guid.NewGuid().ToString("N"));
            string referenceDir = dir + "-reference";
            Directory.CreateDirectory(dir);
            Directory.CreateDirectory(referenceDir);
            var reference = RunTimings.Empty();
            reference.Record("both", 1.0);
            reference.Record("reference only", 2.0);
            reference.Save(referenceDir);
            var previous = RunTimings.Empty();
            previous.Record("both", 3.0);
            previous.Save(dir);
            RunTimings t = RunTimings.Load(dir, Path.Combine(referenceDir, RunTimings.FileName));
            Assert.AreEqual(3.0, t.Previous("both").Value);
            Assert.AreEqual(2.0, t.Previous("reference only").Value);
            Assert.IsNull(t.Previous("neither"));
            // The reference run's timings are read, never written into the report folder's file.
            t.Save(dir);
            Assert.IsNull(RunTimings.Load(dir).Previous("reference only"));
        }

        [Test]
        public void Save_KeepsThePreviousRunsStepsThatThisRunDidNotTake()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sbd-timings-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            var first = RunTimings.Empty();
            first.Record("kept", 3.0);
            first.Record("redone", 4.0);
            first.Save(dir);
            RunTimings second = RunTimings.Load(dir);
            second.Record("redone", 5.0);
            second.Save(dir);
            RunTimings third = RunTimings.Load(dir);
            Assert.AreEqual(3.0, third.Previous("kept").Value);
            Assert.AreEqual(5.0, third.Previous("redone").Value);
        }
    }

    public class ReportTests
    {
        static string OutDir() => Path.Combine(Path.GetTempPath(), "sbd-report-" + Guid.NewGuid().ToString("N"));

        static (int Code, string Output, string Progress, string Dir) RunFake(RunScope scope, params IScenarioSuite[] suites)
        {
            string dir = OutDir();
            var options = new RunOptions { OutDir = dir, Scope = scope, Repeats = 3 };
            var output = new StringWriter();
            var progress = new StringWriter();
            int code = Program.Run(options, suites, new ReportPart[0], output, progress);
            return (code, output.ToString(), progress.ToString(), dir);
        }

        static FakeSuite TwoRows() => new FakeSuite("FakeStudy",
            new FakeScenario("cheap; 1 substeps", 10, 0.30),
            new FakeScenario("dear; 8 substeps", 10, 0.03));

        [Test]
        public void Report_OpensWithTheSummary_ThenTheMachine_ThenTheContents()
        {
            var (code, _, _, dir) = RunFake(RunScope.Standard, TwoRows());
            Assert.AreEqual(0, code);
            string md = File.ReadAllText(Path.Combine(dir, "report.md"));
            int summary = md.IndexOf("## Summary", StringComparison.Ordinal);
            int machine = md.IndexOf("## Machine", StringComparison.Ordinal);
            int contents = md.IndexOf("## Contents", StringComparison.Ordinal);
            int suite = md.IndexOf("## FakeStudy", StringComparison.Ordinal);
            Assert.That(summary, Is.GreaterThan(0));
            Assert.That(machine, Is.GreaterThan(summary));
            Assert.That(contents, Is.GreaterThan(machine));
            Assert.That(suite, Is.GreaterThan(contents));
            StringAssert.DoesNotContain("Partial report", md);
        }

        [Test]
        public void Summary_NamesTheCheapestSettingWithinEachThreshold()
        {
            var (_, _, _, dir) = RunFake(RunScope.Standard, TwoRows());
            string md = File.ReadAllText(Path.Combine(dir, "report.md"));
            string row = md.Split('\n').First(l => l.StartsWith("| [Fake scene]", StringComparison.Ordinal));
            string[] cells = row.Split('|').Select(c => c.Trim()).ToArray();
            // cells: "", scene, error, 20 %, 5 %, 1 %, best, figure, ""
            StringAssert.StartsWith("dear; 8 substeps", cells[3]);   // 30 % misses 20 %: only the dear row is within it
            StringAssert.StartsWith("dear; 8 substeps", cells[4]);
            Assert.AreEqual("not reached", cells[5]);
            StringAssert.StartsWith("3.00 %", cells[6]);
        }

        [Test]
        public void Tables_PrintFractionsAsPercent_AndTheCsvKeepsTheFractionWithItsUnit()
        {
            var (_, output, _, dir) = RunFake(RunScope.Standard, TwoRows());
            StringAssert.Contains("err=30 %", output);
            string md = File.ReadAllText(Path.Combine(dir, "report.md"));
            StringAssert.Contains("| err (%) |", md);
            string[] csv = File.ReadAllLines(Path.Combine(dir, "results.csv"));
            Assert.AreEqual(Report.CsvHeader, csv[0]);
            string err = csv.First(l => l.Contains("\"err\"") && l.Contains("cheap"));
            StringAssert.EndsWith(",0.3,fraction", err);
            string tip = csv.First(l => l.Contains("\"tip\"") && l.Contains("cheap"));
            StringAssert.EndsWith(",0.25,m", tip);
        }

        [Test]
        public void Definition_IsAListUnderTheTable()
        {
            var (_, _, _, dir) = RunFake(RunScope.Standard, TwoRows());
            string md = File.ReadAllText(Path.Combine(dir, "report.md"));
            int table = md.IndexOf("| method | size |", StringComparison.Ordinal);
            int body = md.IndexOf("- *Body:* a fake body", StringComparison.Ordinal);
            Assert.That(table, Is.GreaterThan(0));
            Assert.That(body, Is.GreaterThan(table));
            Assert.That(md.IndexOf("*What a fake body costs.*", StringComparison.Ordinal), Is.InRange(0, table));
        }

        [Test]
        public void Progress_PrintsOneLinePerStepAsItStarts_WithCountElapsedAndEstimate()
        {
            var (_, _, progress, _) = RunFake(RunScope.Standard, TwoRows());
            string[] lines = progress.Split('\n').Where(l => l.StartsWith("[", StringComparison.Ordinal)).ToArray();
            Assert.AreEqual(2, lines.Length);
            StringAssert.StartsWith("[1/2] FakeStudy: cheap; 1 substeps (10 particles)", lines[0]);
            StringAssert.Contains("elapsed", lines[0]);
            StringAssert.Contains("time left known after the first step", lines[0]);
            StringAssert.StartsWith("[2/2]", lines[1]);
            StringAssert.Contains("left", lines[1]);
        }

        [Test]
        public void SecondRun_EstimatesFromTheFirstRunsTimings()
        {
            string dir = OutDir();
            var options = new RunOptions { OutDir = dir, Scope = RunScope.Standard, Repeats = 3 };
            Program.Run(options, new[] { TwoRows() }, new ReportPart[0], new StringWriter(), new StringWriter());
            var progress = new StringWriter();
            Program.Run(options, new[] { TwoRows() }, new ReportPart[0], new StringWriter(), progress);
            string first = progress.ToString().Split('\n').First(l => l.StartsWith("[1/2]", StringComparison.Ordinal));
            StringAssert.Contains("about", first);
            StringAssert.DoesNotContain("known after", first);
        }

        [Test]
        public void RunCutOffMidway_LeavesAValidReportOfWhatFinished()
        {
            var suite = new FakeSuite("FakeStudy",
                new FakeScenario("first; 1 substeps", 10, 0.5),
                new FakeScenario("second; 2 substeps", 10, 0.2),
                new FakeScenario("third; 4 substeps", 10, 0.1, throwOnSetup: true));
            string dir = OutDir();
            var options = new RunOptions { OutDir = dir, Scope = RunScope.Standard, Repeats = 3 };
            Assert.Throws<InvalidOperationException>(() =>
                Program.Run(options, new IScenarioSuite[] { suite }, new ReportPart[0], new StringWriter(), new StringWriter()));
            string md = File.ReadAllText(Path.Combine(dir, "report.md"));
            StringAssert.Contains("Partial report:** 2 of 3 steps finished", md);
            StringAssert.Contains("| first; 1 substeps |", md);
            StringAssert.Contains("| second; 2 substeps |", md);
            StringAssert.DoesNotContain("third", md.Substring(md.IndexOf("## FakeStudy", StringComparison.Ordinal)));
            string[] csv = File.ReadAllLines(Path.Combine(dir, "results.csv"));
            Assert.AreEqual(1 + 2 * 3, csv.Length, "header and three metrics of each finished row");
            Assert.IsNull(RunTimings.Load(dir).Previous(RunTimings.Key("FakeStudy", "Fake: third; 4 substeps (10 particles), default")));
            Assert.IsNotNull(RunTimings.Load(dir).Previous(RunTimings.Key("FakeStudy", "Fake: second; 2 substeps (10 particles), default")));
        }

        [Test]
        public void IndependentSuite_IsSetUpOnceInThePreparationStep_AndReportsEveryRow()
        {
            var a = new FakeScenario("a; 1 substeps", 10, 0.5);
            var b = new FakeScenario("b; 2 substeps", 10, 0.2);
            var suite = new IndependentFakeSuite("FakeIndependent", a, b);
            string dir = OutDir();
            var progress = new StringWriter();
            var options = new RunOptions { OutDir = dir, Scope = RunScope.Standard, Repeats = 3, Threads = 2 };
            Assert.AreEqual(0, Program.Run(options, new IScenarioSuite[] { suite }, new ReportPart[0], new StringWriter(), progress));
            Assert.AreEqual(1, a.Setups);
            Assert.AreEqual(1, b.Setups);
            string[] lines = progress.ToString().Split('\n').Where(l => l.StartsWith("[", StringComparison.Ordinal)).ToArray();
            StringAssert.StartsWith("[1/3] preparing: the references of 0 scenes and the setup of 2 scenarios", lines[0]);
            StringAssert.StartsWith("[2/3] FakeIndependent: a; 1 substeps", lines[1]);
            string md = File.ReadAllText(Path.Combine(dir, "report.md"));
            StringAssert.Contains("| a; 1 substeps | 10 particles |", md);
            StringAssert.Contains("| b; 2 substeps | 10 particles |", md);
        }

        [Test]
        public void MethodFilter_KeepsOnlyMatchingScenarios_AndSkipsTheReportParts()
        {
            var options = new RunOptions { Method = "dear" };
            var part = new ReportPart { Name = "LavapipeX", Title = "X" };
            RunPlan plan = RunPlan.Build(options, new[] { TwoRows() }, new[] { part });
            Assert.AreEqual(1, plan.Count);
            Assert.AreEqual("dear; 8 substeps", plan.Suites[0].Scenarios[0].Scenario.Method);
            Assert.IsEmpty(plan.Parts);
        }

        [Test]
        public void SuiteFilter_RunsAPartOnlyWhenItNamesIt()
        {
            var part = new ReportPart { Name = "LavapipeX", Title = "X" };
            Assert.AreEqual(0, RunPlan.Build(new RunOptions { Filter = "Fake" }, new[] { TwoRows() }, new[] { part }).Parts.Count);
            Assert.AreEqual(1, RunPlan.Build(new RunOptions { Filter = "lavapipe" }, new[] { TwoRows() }, new[] { part }).Parts.Count);
            Assert.AreEqual(1, RunPlan.Build(new RunOptions(), new[] { TwoRows() }, new[] { part }).Parts.Count);
        }
    }

    public class SummaryTests
    {
        static ScenarioOutcome Row(string method, double err, double nsPerItem, int size = 100) =>
            new ScenarioOutcome(method, nsPerItem, new[] { new Metric("err", err, MetricUnit.Fraction) }, size, size);

        [Test]
        public void AccuracyFinding_TakesTheCheapestRowWithinEachThreshold_AndIgnoresDivergedRows()
        {
            var rows = new[]
            {
                Row("a", 0.15, 1000),          // within 20 %, cost 0.1 ms
                Row("b", 0.04, 5000),          // within 5 %, cost 0.5 ms
                Row("c", 0.03, 9000),          // within 5 % but dearer
                Row("d", double.NaN, 1),       // diverged: never counts, however cheap
            };
            AccuracyFinding f = AccuracyFinding.FromRows("s", "err", "err", rows, AccuracyFinding.RelativeThresholds,
                r => r.NsPerItem * r.Size * 1e-6, r => r.Method, "ms");
            Assert.AreEqual("a", f.Reaches[0].Setting);
            Assert.AreEqual(0.1, f.Reaches[0].Cost, 1e-12);
            Assert.AreEqual("b", f.Reaches[1].Setting);
            Assert.IsFalse(f.Reaches[2].Reached);
            Assert.IsTrue(double.IsPositiveInfinity(f.Reaches[2].Cost));
            Assert.AreEqual(0.03, f.BestError, 1e-15);
            Assert.AreEqual("c", f.BestSetting);
        }

        [Test]
        public void AccuracyFinding_EveryRowDiverged_HasNoBest()
        {
            AccuracyFinding f = AccuracyFinding.FromRows("s", "err", "err", new[] { Row("a", double.NaN, 1) }, AccuracyFinding.RelativeThresholds,
                r => r.NsPerItem, r => r.Method, "ms");
            Assert.IsTrue(double.IsNaN(f.BestError));
            Assert.IsNull(f.BestSetting);
        }

        [Test]
        public void EffectsNoSuiteMeasured_ReadNoneYet_AndMeasuredOnesTheirCost()
        {
            var suite = new SuiteResult(new FakeSuite("FakeEffects"));
            suite.Findings.Add(new EffectFinding { Effect = EffectNames.FlockingCohesion, Cost = "0.5 ms per frame" });
            suite.Finished = true;
            var md = new System.Text.StringBuilder();
            SummaryWriter.Write(md, new[] { suite }, new PartResult[0]);
            string text = md.ToString();
            StringAssert.Contains($"- {EffectNames.FlockingCohesion}: 0.5 ms per frame ([FakeEffects](#fakeeffects))", text);
            StringAssert.Contains($"- {EffectNames.Plasticity}: none yet", text);
        }

        [Test]
        public void HardCases_ArePassedOverTotalPerMethod_WithWhatFailed()
        {
            var suite = new SuiteResult(new FakeSuite("FakeHard"));
            suite.Findings.Add(new HardCaseFinding { Group = "Soft bodies", Method = "A", Passed = 4, Total = 4, Failed = new string[0] });
            suite.Findings.Add(new HardCaseFinding { Group = "Soft bodies", Method = "B", Passed = 3, Total = 4, Failed = new[] { "huge step: diverged" } });
            suite.Finished = true;
            var md = new System.Text.StringBuilder();
            SummaryWriter.Write(md, new[] { suite }, new PartResult[0]);
            StringAssert.Contains("- [Soft bodies](#fakehard): 1 of 2 pass every case. A 4/4; B 3/4 (huge step: diverged).", md.ToString());
            Assert.AreEqual(1, System.Text.RegularExpressions.Regex.Matches(md.ToString(), "Soft bodies").Count);
        }

        [Test]
        public void AccuracyRow_LinksTheSuitesFigure_OnlyWhenTheFigurePlotsItsMetric()
        {
            var suite = new SuiteResult(new FakeSuite("FakeFigure"));
            suite.Figures.Add(("FakeFigure-accuracy-vs-cost.png", "alt", "caption"));
            var rows = new[] { Row("a", 0.1, 1000) };
            suite.Findings.Add(AccuracyFinding.FromRows("plotted", "err", "err", rows, AccuracyFinding.RelativeThresholds, r => 1.0, r => r.Method, "ms"));
            suite.Findings.Add(AccuracyFinding.FromRows("other", "tip", "tip", rows, AccuracyFinding.RelativeThresholds, r => 1.0, r => r.Method, "ms"));
            suite.Finished = true;
            var md = new System.Text.StringBuilder();
            SummaryWriter.Write(md, new[] { suite }, new PartResult[0]);
            string[] lines = md.ToString().Split('\n');
            StringAssert.EndsWith("[figure](FakeFigure-accuracy-vs-cost.png) |", lines.First(l => l.StartsWith("| [plotted]", StringComparison.Ordinal)));
            StringAssert.EndsWith("| – |", lines.First(l => l.StartsWith("| [other]", StringComparison.Ordinal)));
        }

        [TestCase("FluidAccuracy", "fluidaccuracy")]
        [TestCase("GPU fluid kernels on lavapipe (CPU driver; not a GPU number)", "gpu-fluid-kernels-on-lavapipe-cpu-driver-not-a-gpu-number")]
        public void Slug_FollowsGitHubsHeadingAnchors(string heading, string slug) => Assert.AreEqual(slug, Report.Slug(heading));

        [TestCase(0.05, MetricUnit.Fraction, "5.00 %")]
        [TestCase(0.4, MetricUnit.Fraction, "40.0 %")]
        [TestCase(0.0004, MetricUnit.Fraction, "0.040 %")]
        [TestCase(0.08, MetricUnit.ColumnWidth, "0.08 a")]
        public void Error_PrintsFractionsAsPercentAndOtherUnitsWithTheirSymbol(double v, MetricUnit unit, string text) =>
            Assert.AreEqual(text, SummaryWriter.Error(v, unit));
    }
}

namespace SoftBodyDynamics.Tests.Runner
{
    public class ScenarioTimerTests
    {
        /// <summary>A scenario whose step sleeps <paramref name="ms"/> milliseconds.</summary>
        sealed class SleepingScenario : IScenario
        {
            readonly int m_Ms;
            public SleepingScenario(int ms) { m_Ms = ms; }
            public string Name => "Sleep";
            public string Method => "sleep";
            public int Size => 1;
            public string SizeUnit => "steps";
            public long ItemsPerStep => 1;
            public void Setup() { }
            public void Step() => System.Threading.Thread.Sleep(m_Ms);
            public IReadOnlyList<Metric> Evaluate() => new Metric[0];
        }

        static TimingRule Budget(double seconds, int minRepeats) => new TimingRule(0.0, 1, 0.0, 0.0, seconds, minRepeats, true);

        [Test]
        public void TimedBudget_CutsTheRepeatsOfLongSteps_ButNeverBelowTheRulesFloor()
        {
            // Steps of at least 40 ms in a 0.2 s budget: at most 5 fit.
            Assert.That(SoftBodyDynamics.Runner.ScenarioTimer.Time(new SleepingScenario(40), 15, Budget(0.2, 3)).Repeats, Is.InRange(3, 5));
            Assert.AreEqual(3, SoftBodyDynamics.Runner.ScenarioTimer.Time(new SleepingScenario(40), 15, Budget(0.01, 3)).Repeats);
            Assert.AreEqual(1, SoftBodyDynamics.Runner.ScenarioTimer.Time(new SleepingScenario(40), 15, Budget(0.01, 1)).Repeats);
        }

        [Test]
        public void NoBudget_TimesEveryRepeatAskedFor() =>
            Assert.AreEqual(7, SoftBodyDynamics.Runner.ScenarioTimer.Time(new SleepingScenario(1), 7, TimingRule.Full).Repeats);

        [Test]
        public void FewerRepeatsAskedThanTheFloor_AreKept() =>
            Assert.AreEqual(2, SoftBodyDynamics.Runner.ScenarioTimer.Time(new SleepingScenario(40), 2, Budget(0.01, 3)).Repeats);

        [Test]
        public void ShortRule_WarmsUpAtLeastTwoSteps_AndFullAtLeastThree()
        {
            var s = new CountingScenario();
            SoftBodyDynamics.Runner.ScenarioTimer.Time(s, 1, TimingRule.Short);
            Assert.That(s.Steps, Is.GreaterThanOrEqualTo(2 + 1));
            var f = new CountingScenario();
            SoftBodyDynamics.Runner.ScenarioTimer.Time(f, 1, TimingRule.Full);
            Assert.That(f.Steps, Is.GreaterThanOrEqualTo(3 + 1));
        }

        [Test]
        public void ShortRule_WarmsUpAWholeRunStepByItsFirstFrames_AndFullByWholeSteps()
        {
            var s = new WholeRunScenario();
            SoftBodyDynamics.Runner.ScenarioTimer.Time(s, 1, TimingRule.Short);
            Assert.AreEqual((1, 1), (s.WarmupCalls, s.Steps));
            var f = new WholeRunScenario();
            SoftBodyDynamics.Runner.ScenarioTimer.Time(f, 1, TimingRule.Full);
            Assert.AreEqual(0, f.WarmupCalls);
            Assert.That(f.Steps, Is.GreaterThanOrEqualTo(3 + 1));
        }

        [Test]
        public void TimedSteps_StopOnceTheyHaveTakenTheBudget()
        {
            // 30 ms steps, 0.1 s budget: the fourth step ends past it (3 × 30 ms < 100 ms ≤ 4 × 30 ms, give or take the sleep's overrun).
            int repeats = SoftBodyDynamics.Runner.ScenarioTimer.Time(new CountingScenario(), 15, Budget(0.1, 1)).Repeats;
            Assert.That(repeats, Is.InRange(3, 4));
        }

        /// <summary>A whole-run scenario that counts its short warm-ups and its steps.</summary>
        sealed class WholeRunScenario : IScenario, IScenarioShortWarmup
        {
            public int Steps, WarmupCalls;
            public string Name => "Run";
            public string Method => "run";
            public int Size => 1;
            public string SizeUnit => "runs";
            public long ItemsPerStep => 1;
            public void Setup() { }
            public void Step() { Steps++; System.Threading.Thread.Sleep(30); }
            public void WarmupFrames() => WarmupCalls++;
            public IReadOnlyList<Metric> Evaluate() => new Metric[0];
        }

        /// <summary>A scenario whose step takes 30 ms and counts its calls.</summary>
        sealed class CountingScenario : IScenario
        {
            public int Steps;
            public string Name => "Count";
            public string Method => "count";
            public int Size => 1;
            public string SizeUnit => "steps";
            public long ItemsPerStep => 1;
            public void Setup() { }
            public void Step() { Steps++; System.Threading.Thread.Sleep(30); }
            public IReadOnlyList<Metric> Evaluate() => new Metric[0];
        }
    }
}
