using System;
using System.Collections.Generic;
using System.IO;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Runner;

namespace SoftBodyDynamics.Tests.Runner
{
    /// <summary>Stored float64 references: used only for the sources they were computed from, and returned bit for bit.</summary>
    public class ReferenceStoreTests
    {
        public struct FakeEstimate
        {
            public double Order, Extrapolated;
        }

        public sealed class FakeValues
        {
            public double Tip;
            public double Missing = double.NaN;
            public double[] PerMesh;
            public double[][] PerLoad;
            public int[] Resolutions;
            public FakeEstimate Estimate;
            public double Seconds;
        }

        /// <summary>A suite with a reference that counts how often it was computed.</summary>
        sealed class StoredFakeSuite : IScenarioSuite, IScenarioSuiteStoredReference
        {
            FakeValues m_Values;
            public int Computed;
            public StoredFakeSuite(string name) { Name = name; }
            public string Name { get; }
            public SuiteDefinition Definition => new SuiteDefinition { Purpose = "A fake reference.", Body = "-", Material = "-", Load = "-", Reference = "-", Metric = "err" };
            public string ErrorMetricForPlot => "err";
            public IEnumerable<IScenario> Scenarios(RunScope scope) => new IScenario[] { new FakeScenario("a; 1 substeps", 10, 0.1) };
            public void Prepare() => Reference();
            public Type ReferenceType => typeof(FakeValues);

            public object Reference()
            {
                if (m_Values == null)
                {
                    Computed++;
                    m_Values = Make(0.1 + 0.2);
                }
                return m_Values;
            }

            public void UseReference(object values) => m_Values = (FakeValues)values;
            public FakeValues Values() => m_Values;
        }

        static FakeValues Make(double tip) => new FakeValues
        {
            Tip = tip,
            PerMesh = new[] { 1.0 / 3.0, Math.PI, -0.0 },
            PerLoad = new[] { new[] { 1e-300, 2.5 }, new[] { double.Epsilon } },
            Resolutions = new[] { 1, 2, 3 },
            Estimate = new FakeEstimate { Order = 1.4, Extrapolated = 0.072 },
            Seconds = 12.5,
        };

        static string TempDir()
        {
            string dir = Path.Combine(Path.GetTempPath(), "sbd-ref-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            return dir;
        }

        /// <summary>A package root with one reference source, one scene, one target file and one method body.</summary>
        static string FakeRoot()
        {
            string root = TempDir();
            Directory.CreateDirectory(Path.Combine(root, "Benchmarks/Scenarios/Reference/Fem"));
            Directory.CreateDirectory(Path.Combine(root, "Benchmarks/Scenarios/SoftBody/Methods"));
            File.WriteAllText(Path.Combine(root, "Benchmarks/Scenarios/Reference/Fem/Solver.cs"), "class Solver {}");
            File.WriteAllText(Path.Combine(root, "Benchmarks/Scenarios/SoftBody/Methods/BeamScene.cs"), "class BeamScene {}");
            File.WriteAllText(Path.Combine(root, "Benchmarks/Scenarios/SoftBody/Methods/BeamTargets.cs"), "class BeamTargets {}");
            File.WriteAllText(Path.Combine(root, "Benchmarks/Scenarios/SoftBody/Methods/FemMethodBody.cs"), "class FemMethodBody {}");
            return root;
        }

        [Test]
        public void StoredValues_ComeBackBitForBit_NaNAndArraysIncluded()
        {
            string path = Path.Combine(TempDir(), ReferenceStore.FileName);
            var computed = new StoredFakeSuite("Beam");
            ReferenceStore.Write(path, "abc", new[] { computed }, "test");

            var fresh = new StoredFakeSuite("Beam");
            List<string> used = ReferenceStore.Use(path, "abc", new[] { fresh }, out string why, out string computedBy);
            CollectionAssert.AreEqual(new[] { "Beam" }, used);
            Assert.AreEqual("stored", why);
            Assert.AreEqual("test", computedBy);
            fresh.Prepare();
            Assert.AreEqual(0, fresh.Computed);
            FakeValues a = computed.Values(), b = fresh.Values();
            Assert.AreEqual(BitConverter.DoubleToInt64Bits(a.Tip), BitConverter.DoubleToInt64Bits(b.Tip));
            Assert.IsNaN(b.Missing);
            CollectionAssert.AreEqual(Array.ConvertAll(a.PerMesh, BitConverter.DoubleToInt64Bits), Array.ConvertAll(b.PerMesh, BitConverter.DoubleToInt64Bits));
            Assert.AreEqual(a.PerLoad[0][0], b.PerLoad[0][0]);
            Assert.AreEqual(double.Epsilon, b.PerLoad[1][0]);
            CollectionAssert.AreEqual(a.Resolutions, b.Resolutions);
            Assert.AreEqual((a.Estimate.Order, a.Estimate.Extrapolated), (b.Estimate.Order, b.Estimate.Extrapolated));
        }

        [Test]
        public void ValuesOfOtherSources_AreNotUsed()
        {
            string path = Path.Combine(TempDir(), ReferenceStore.FileName);
            ReferenceStore.Write(path, "old", new[] { new StoredFakeSuite("Beam") }, "test");
            var fresh = new StoredFakeSuite("Beam");
            Assert.IsEmpty(ReferenceStore.Use(path, "new", new[] { fresh }, out string why, out string computedBy));
            Assert.IsNull(computedBy);
            StringAssert.Contains("changed", why);
            fresh.Prepare();
            Assert.AreEqual(1, fresh.Computed);
        }

        [Test]
        public void SourceHash_ChangesWithTheReferenceSourcesAndScenes_NotWithTheMethodBodies()
        {
            string root = FakeRoot();
            string h0 = ReferenceStore.SourceHash(root);
            File.WriteAllText(Path.Combine(root, "Benchmarks/Scenarios/SoftBody/Methods/FemMethodBody.cs"), "class FemMethodBody { int x; }");
            Assert.AreEqual(h0, ReferenceStore.SourceHash(root));
            File.WriteAllText(Path.Combine(root, "Benchmarks/Scenarios/SoftBody/Methods/BeamScene.cs"), "class BeamScene { const float L = 0.5f; }");
            string h1 = ReferenceStore.SourceHash(root);
            Assert.AreNotEqual(h0, h1);
            File.WriteAllText(Path.Combine(root, "Benchmarks/Scenarios/Reference/Fem/Solver.cs"), "class Solver { }");
            Assert.AreNotEqual(h1, ReferenceStore.SourceHash(root));
        }

        [Test]
        public void Differences_IgnoreTheReferencesTiming_AndNameTheSuitesThatDiffer()
        {
            string dir = TempDir();
            string stored = Path.Combine(dir, "stored.json"), computed = Path.Combine(dir, "computed.json");
            var beam = new StoredFakeSuite("Beam");
            var bar = new StoredFakeSuite("Bar");
            ReferenceStore.Write(stored, "abc", new[] { beam, bar }, "test");
            beam.Values().Seconds = 99;
            ReferenceStore.Write(computed, "abc", new[] { beam, bar }, "test");
            Assert.IsEmpty(ReferenceStore.Differences(stored, computed));
            bar.Values().PerMesh[1] = 3.0;
            ReferenceStore.Write(computed, "abc", new[] { beam, bar }, "test");
            CollectionAssert.AreEqual(new[] { "Bar" }, ReferenceStore.Differences(stored, computed));
            ReferenceStore.Write(computed, "xyz", new[] { beam, bar }, "test");
            Assert.IsNull(ReferenceStore.Differences(stored, computed));
        }

        [Test]
        public void DefaultRun_UsesStoredValues_AndAFullRunComputesAndWritesThem()
        {
            string root = FakeRoot();
            Directory.CreateDirectory(Path.Combine(root, "Tools~", "Runner"));
            string full = TempDir();
            var computing = new StoredFakeSuite("Beam");
            Program.Run(new RunOptions { Root = root, OutDir = full, Scope = RunScope.Full, Repeats = 1 }, new IScenarioSuite[] { computing },
                new ReportPart[0], new StringWriter(), new StringWriter());
            Assert.AreEqual(1, computing.Computed);
            string written = Path.Combine(full, ReferenceStore.FileName);
            FileAssert.Exists(written);
            StringAssert.Contains("none are stored for these sources", File.ReadAllText(Path.Combine(full, "report.md")));

            File.Copy(written, Path.Combine(root, "Tools~", "Runner", ReferenceStore.FileName));
            var stored = new StoredFakeSuite("Beam");
            string standard = TempDir();
            Program.Run(new RunOptions { Root = root, OutDir = standard, Scope = RunScope.Standard, Repeats = 1 }, new IScenarioSuite[] { stored },
                new ReportPart[0], new StringWriter(), new StringWriter());
            Assert.AreEqual(0, stored.Computed);
            StringAssert.Contains("are the stored ones", File.ReadAllText(Path.Combine(standard, "report.md")));
        }
    }
}
