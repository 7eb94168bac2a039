using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>One bad field at a time on top of <see cref="MassSpringParameters.Default"/>; the shared fields get shape matching's codes and messages.</summary>
    public class MassSpringParameterValidationTests
    {
        public delegate void Spoil(ref MassSpringParameters p);

        static TestCaseData Case(string name, Spoil spoil, IssueCode code) =>
            new TestCaseData(spoil, code).SetName($"MassSpringValidate_Flags_{name}");

        static IEnumerable<TestCaseData> BadFields()
        {
            yield return Case("IntegratorOutOfEnum", (ref MassSpringParameters p) => p.Integrator = (MassSpringIntegrator)4, MassSpringIssueCode.IntegratorInvalid);
            yield return Case("SubstepsZero", (ref MassSpringParameters p) => p.Body.Substeps = 0, MassSpringIssueCode.IterationsOutOfRange);
            yield return Case("IterationsAboveMax", (ref MassSpringParameters p) => p.Iterations = MassSpringParameters.MaxIterations + 1, MassSpringIssueCode.IterationsOutOfRange);
            yield return Case("CgIterationsZero", (ref MassSpringParameters p) => p.CgIterations = 0, MassSpringIssueCode.IterationsOutOfRange);
            yield return Case("CgToleranceNegative", (ref MassSpringParameters p) => p.CgTolerance = -1e-4f, MassSpringIssueCode.CgToleranceInvalid);
            yield return Case("CgToleranceOne", (ref MassSpringParameters p) => p.CgTolerance = 1f, MassSpringIssueCode.CgToleranceInvalid);
            yield return Case("ParticleRadiusHuge", (ref MassSpringParameters p) => p.Body.ParticleRadius = 1000f, ParticleBodyIssueCode.ParticleRadiusInvalid);
            yield return Case("RestitutionNegative", (ref MassSpringParameters p) => p.Body.Restitution = -0.1f, ParticleBodyIssueCode.RestitutionOutOfRange);
            yield return Case("SleepDelayNaN", (ref MassSpringParameters p) => p.Body.SleepDelay = float.NaN, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("MaxSpeedNegative", (ref MassSpringParameters p) => p.Body.MaxSpeed = -5f, ParticleBodyIssueCode.MaxSpeedNotPositive);
        }

        [Test]
        public void Validate_DefaultParameters_HaveNoIssues()
        {
            var issues = new List<ValidationIssue>();
            Assert.That(MassSpringParameterValidation.Validate(MassSpringParameters.Default, issues), Is.True);
            Assert.That(issues, Is.Empty);
        }

        [Test]
        public void Validate_AcceptsAZeroCgTolerance_WhichRunsEveryIteration()
        {
            MassSpringParameters p = MassSpringParameters.Default;
            p.CgTolerance = 0f;
            Assert.That(MassSpringParameterValidation.Validate(p, new List<ValidationIssue>()), Is.True);
        }

        [TestCaseSource(nameof(BadFields))]
        public void Validate_FlagsTheBadField(Spoil spoil, IssueCode code)
        {
            MassSpringParameters p = MassSpringParameters.Default;
            spoil(ref p);
            var issues = new List<ValidationIssue>();
            bool valid = MassSpringParameterValidation.Validate(p, issues);
            Assert.That(issues.Count, Is.EqualTo(1), string.Join("; ", issues));
            Assert.That(issues[0].Code, Is.EqualTo(code));
            Assert.That(valid, Is.False);
        }
    }
}
