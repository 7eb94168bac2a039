using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>One bad field at a time on top of <see cref="FemParameters.Default"/>; the fields FEM shares with shape matching get the same codes.</summary>
    public class FemParameterValidationTests
    {
        public delegate void Spoil(ref FemParameters p);

        static TestCaseData Case(string name, Spoil spoil, IssueCode code) =>
            new TestCaseData(spoil, code).SetName($"FemValidate_Flags_{name}");

        static IEnumerable<TestCaseData> BadFields()
        {
            yield return Case("ModelOutOfEnum", (ref FemParameters p) => p.Model = (FemMaterialModel)5, FemIssueCode.ModelInvalid);
            yield return Case("IntegratorOutOfEnum", (ref FemParameters p) => p.Integrator = (FemIntegrator)9, FemIssueCode.ModelInvalid);
            yield return Case("SubstepsZero", (ref FemParameters p) => p.Body.Substeps = 0, FemIssueCode.IterationsOutOfRange);
            yield return Case("SubstepsAboveMax", (ref FemParameters p) => p.Body.Substeps = FemParameters.MaxSubsteps + 1, FemIssueCode.IterationsOutOfRange);
            yield return Case("IterationsZero", (ref FemParameters p) => p.Iterations = 0, FemIssueCode.IterationsOutOfRange);
            yield return Case("CgIterationsAboveMax", (ref FemParameters p) => p.CgIterations = FemParameters.MaxCgIterations + 1, FemIssueCode.IterationsOutOfRange);
            yield return Case("NewtonIterationsNegative", (ref FemParameters p) => p.NewtonIterations = -1, FemIssueCode.IterationsOutOfRange);
            yield return Case("CgToleranceZero", (ref FemParameters p) => p.CgTolerance = 0f, FemIssueCode.CgToleranceInvalid);
            yield return Case("CgToleranceOne", (ref FemParameters p) => p.CgTolerance = 1f, FemIssueCode.CgToleranceInvalid);
            yield return Case("CgToleranceNaN", (ref FemParameters p) => p.CgTolerance = float.NaN, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("DampingFrequencyNegative", (ref FemParameters p) => p.DampingFrequency = -1f, FemIssueCode.DampingFrequencyInvalid);
            yield return Case("AccelerationInfinite", (ref FemParameters p) => p.Body.Acceleration.y = float.NegativeInfinity, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("DepenetrationZero", (ref FemParameters p) => p.Body.MaxDepenetrationSpeed = 0f, ParticleBodyIssueCode.MaxDepenetrationSpeedNotPositive);
            yield return Case("ParticleRadiusZero", (ref FemParameters p) => p.Body.ParticleRadius = 0f, ParticleBodyIssueCode.ParticleRadiusInvalid);
            yield return Case("FrictionNegative", (ref FemParameters p) => p.Body.Friction = -0.1f, ParticleBodyIssueCode.FrictionNegative);
            yield return Case("RestitutionAboveOne", (ref FemParameters p) => p.Body.Restitution = 1.5f, ParticleBodyIssueCode.RestitutionOutOfRange);
            yield return Case("SleepSpeedNegative", (ref FemParameters p) => p.Body.SleepSpeed = -1f, ParticleBodyIssueCode.SleepSpeedNegative);
            yield return Case("SleepDelayNegative", (ref FemParameters p) => p.Body.SleepDelay = -1f, ParticleBodyIssueCode.SleepDelayNegative);
            yield return Case("MaxSpeedZero", (ref FemParameters p) => p.Body.MaxSpeed = 0f, ParticleBodyIssueCode.MaxSpeedNotPositive);
            yield return Case("RotationIterationsZero", (ref FemParameters p) => p.RotationIterations = 0, ParticleBodyIssueCode.RotationIterationsInvalid);
        }

        [Test]
        public void Validate_DefaultParameters_HaveNoIssues()
        {
            var issues = new List<ValidationIssue>();
            Assert.That(FemParameterValidation.Validate(FemParameters.Default, issues), Is.True);
            Assert.That(issues, Is.Empty);
        }

        [TestCaseSource(nameof(BadFields))]
        public void Validate_FlagsTheBadField(Spoil spoil, IssueCode code)
        {
            FemParameters p = FemParameters.Default;
            spoil(ref p);
            var issues = new List<ValidationIssue>();
            bool valid = FemParameterValidation.Validate(p, issues);
            Assert.That(issues.Count, Is.EqualTo(1), string.Join("; ", issues));
            Assert.That(issues[0].Code, Is.EqualTo(code));
            Assert.That(issues[0].Severity, Is.EqualTo(IssueSeverity.Error));
            Assert.That(valid, Is.False);
        }

        [Test]
        public void SharedField_GetsTheSameMessageAsInShapeMatching()
        {
            FemParameters f = FemParameters.Default;
            f.Body.Friction = -0.3f;
            ShapeMatchingParameters s = ShapeMatchingParameters.Default;
            s.Body.Friction = -0.3f;
            var fem = new List<ValidationIssue>();
            var sm = new List<ValidationIssue>();
            FemParameterValidation.Validate(f, fem);
            ShapeMatchingParameterValidation.Validate(s, sm);
            Assert.AreEqual(sm[0].Message, fem[0].Message);
            Assert.AreEqual(sm[0].Code, fem[0].Code);
        }
    }
}
